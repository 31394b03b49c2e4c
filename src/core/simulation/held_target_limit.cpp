#include "yarn_tearing/core/simulation/held_target_limit.hpp"

namespace yarn_tearing {

std::vector<RequestedTarget> limitHeldTargets(Scene& scene, double time_step) {
  VertexSet& vertices = scene.vertices;
  std::vector<RequestedTarget> requested;
  for (std::uint32_t v = 0; v < vertices.size(); ++v) {
    if (vertices.motion[v] != VertexMotion::kKinematic) continue;
    const Eigen::Vector3d way = vertices.kinematic_target[v] - vertices.position[v];
    const double reach = scene.yarns[vertices.yarn[v]].material.snapBackSpeed() * time_step;
    const double distance = way.norm();
    if (!(distance > reach)) continue;
    requested.push_back({v, vertices.kinematic_target[v]});
    vertices.kinematic_target[v] = vertices.position[v] + (reach / distance) * way;
  }
  return requested;
}

void restoreHeldTargets(const std::vector<RequestedTarget>& requested, Scene& scene) {
  for (const RequestedTarget& r : requested) {
    if (scene.vertices.motion[r.vertex] == VertexMotion::kKinematic) {
      scene.vertices.kinematic_target[r.vertex] = r.target;
    }
  }
}

}  // namespace yarn_tearing
