#include "yarn_tearing/ros/message_conversion.hpp"

#include "yarn_tearing/ros/geometry_conversion.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

YarnState toYarnState(const Simulator& simulator, const Yarn& yarn) {
  const Scene& scene = simulator.scene();
  const VertexSet& vertices = scene.vertices;
  const EdgeSet& edges = scene.edges;
  YarnState state;
  state.name = yarn.name;
  for (std::uint32_t i = 0; i < yarn.num_vertices; ++i) {
    const std::uint32_t v = yarn.first_vertex + i;
    state.positions.push_back(toPoint(vertices.position[v]));
    state.velocities.push_back(toVector3(vertices.velocity[v]));
    if (vertices.isSupport(v)) {
      state.support_vertices.push_back(static_cast<std::int32_t>(i));
      state.support_forces.push_back(toVector3(simulator.supportForce(v)));
    }
  }
  for (std::uint32_t j = 0; j < yarn.num_edges; ++j) {
    const std::uint32_t e = yarn.first_edge + j;
    state.edge_vertices.push_back(static_cast<std::int32_t>(edges.vertex_a[e] - yarn.first_vertex));
    state.edge_vertices.push_back(static_cast<std::int32_t>(edges.vertex_b[e] - yarn.first_vertex));
    state.rest_lengths.push_back(edges.rest_length[e]);
    state.tensions.push_back(edges.tension[e]);
    state.stresses.push_back(edges.stress[e]);
    state.strains.push_back(edges.strain[e]);
    state.plastic_strains.push_back(edges.plastic_strain[e]);
    state.strain_limits.push_back(edges.strain_limit[e]);
    state.broken.push_back(!edges.intact(e));
  }
  return state;
}

}  // namespace

ros::Time simulatedStamp(double simulated_time) { return ros::Time(simulated_time); }

YarnStateArray toYarnStateArray(const Simulator& simulator, const std::string& frame_id,
                                const ros::Time& stamp) {
  YarnStateArray array;
  array.header.stamp = stamp;
  array.header.frame_id = frame_id;
  array.sim_time = simulator.time();
  for (const Yarn& yarn : simulator.scene().yarns) {
    array.yarns.push_back(toYarnState(simulator, yarn));
  }
  return array;
}

BreakEvent toBreakEventMsg(const TearEvent& event, const Scene& scene, const std::string& frame_id,
                           const ros::Time& stamp) {
  BreakEvent msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame_id;
  msg.sim_time = event.time;
  msg.yarn = scene.yarns.at(event.yarn).name;
  msg.edge = static_cast<std::int32_t>(event.edge);
  msg.vertex_a = static_cast<std::int32_t>(event.vertex_a);
  msg.vertex_b = static_cast<std::int32_t>(event.vertex_b);
  msg.position = toPoint(event.position);
  msg.tension = event.tension;
  msg.stress = event.stress;
  msg.strain = event.strain;
  msg.plastic_strain = event.plastic_strain;
  msg.strain_rate = event.strain_rate;
  return msg;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
