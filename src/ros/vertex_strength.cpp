#include "yarn_tearing/ros/vertex_strength.hpp"

namespace yarn_tearing {
namespace ros_layer {

std::vector<double> vertexBreakingForces(const Scene& scene) {
  std::vector<double> strength(scene.vertices.position.size(), 0.0);
  const EdgeSet& edges = scene.edges;
  for (std::size_t e = 0; e < edges.vertex_a.size(); ++e) {
    const double breaking_force = edges.area[e] * edges.strength_factor[e] *
                                  scene.yarns[edges.yarn[e]].material.curve.breakingStress();
    strength[edges.vertex_a[e]] += breaking_force;
    strength[edges.vertex_b[e]] += breaking_force;
  }
  return strength;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
