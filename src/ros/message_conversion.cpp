#include "yarn_tearing/ros/message_conversion.hpp"

#include "yarn_tearing/ros/geometry_conversion.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

/// Positions, velocities and supports of `count` vertices from global id `first` (indices in the
/// message relative to `first`), into a YarnState or FabricState.
template <typename State>
void addVertices(const Simulator& simulator, std::uint32_t first, std::uint32_t count,
                 State& state) {
  const VertexSet& vertices = simulator.scene().vertices;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint32_t v = first + i;
    state.positions.push_back(toPoint(vertices.position[v]));
    state.velocities.push_back(toVector3(vertices.velocity[v]));
    if (vertices.isSupport(v)) {
      state.support_vertices.push_back(static_cast<std::int32_t>(i));
      state.support_forces.push_back(toVector3(simulator.supportForce(v)));
    }
  }
}

/// Edge e's vertices (relative to `first_vertex`) and loading, into a YarnState or FabricState.
template <typename State>
void addEdge(const EdgeSet& edges, std::uint32_t e, std::uint32_t first_vertex, State& state) {
  state.edge_vertices.push_back(static_cast<std::int32_t>(edges.vertex_a[e] - first_vertex));
  state.edge_vertices.push_back(static_cast<std::int32_t>(edges.vertex_b[e] - first_vertex));
  state.rest_lengths.push_back(edges.rest_length[e]);
  state.tensions.push_back(edges.tension[e]);
  state.stresses.push_back(edges.stress[e]);
  state.strains.push_back(edges.strain[e]);
  state.plastic_strains.push_back(edges.plastic_strain[e]);
  state.broken.push_back(!edges.intact(e));
}

YarnState toYarnState(const Simulator& simulator, const Yarn& yarn) {
  const EdgeSet& edges = simulator.scene().edges;
  YarnState state;
  state.name = yarn.name;
  addVertices(simulator, yarn.first_vertex, yarn.num_vertices, state);
  for (std::uint32_t e = yarn.first_edge; e < yarn.first_edge + yarn.num_edges; ++e) {
    addEdge(edges, e, yarn.first_vertex, state);
    state.strain_limits.push_back(edges.strain_limit[e]);
  }
  return state;
}

FabricState toFabricState(const Simulator& simulator, const Fabric& fabric) {
  const Scene& scene = simulator.scene();
  FabricState state;
  state.name = fabric.name;
  state.ends = static_cast<std::int32_t>(fabric.ends);
  state.picks = static_cast<std::int32_t>(fabric.picks);
  addVertices(simulator, fabric.first_vertex, fabric.numVertices(), state);
  for (const std::uint32_t group : {fabric.warp_group, fabric.weft_group}) {
    const Yarn& yarn = scene.yarns[group];
    for (std::uint32_t e = yarn.first_edge; e < yarn.first_edge + yarn.num_edges; ++e) {
      const FabricSegment segment = fabric.segmentOf(yarn.family, e - yarn.first_edge);
      state.families.push_back(static_cast<std::uint8_t>(segment.family));
      state.yarns.push_back(static_cast<std::int32_t>(segment.yarn));
      state.segments.push_back(static_cast<std::int32_t>(segment.segment));
      addEdge(scene.edges, e, fabric.first_vertex, state);
    }
  }
  return state;
}

/// An empty YarnStateArray or FabricStateArray with its header and sim_time [s] set.
template <typename Array>
Array stampedArray(const Simulator& simulator, const std::string& frame_id,
                   const ros::Time& stamp) {
  Array array;
  array.header.stamp = stamp;
  array.header.frame_id = frame_id;
  array.sim_time = simulator.time();
  return array;
}

}  // namespace

ros::Time simulatedStamp(double simulated_time) { return ros::Time(simulated_time); }

YarnStateArray toYarnStateArray(const Simulator& simulator, const std::string& frame_id,
                                const ros::Time& stamp) {
  auto array = stampedArray<YarnStateArray>(simulator, frame_id, stamp);
  for (const Yarn& yarn : simulator.scene().yarns) {
    if (yarn.fabric >= 0) continue;  // a fabric's warp or weft: in fabric_states
    array.yarns.push_back(toYarnState(simulator, yarn));
  }
  return array;
}

FabricStateArray toFabricStateArray(const Simulator& simulator, const std::string& frame_id,
                                    const ros::Time& stamp) {
  auto array = stampedArray<FabricStateArray>(simulator, frame_id, stamp);
  for (const Fabric& fabric : simulator.scene().fabrics) {
    array.fabrics.push_back(toFabricState(simulator, fabric));
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
  if (event.fabric >= 0) {
    msg.fabric = scene.fabrics.at(static_cast<std::size_t>(event.fabric)).name;
    msg.family = static_cast<std::uint8_t>(event.segment.family);
    msg.fabric_yarn = static_cast<std::int32_t>(event.segment.yarn);
    msg.segment = static_cast<std::int32_t>(event.segment.segment);
  }
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
