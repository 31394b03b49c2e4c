#include "yarn_tearing/core/forces/explicit_forces.hpp"

namespace yarn_tearing {

void accumulateExternalForces(const SimulationParameters& parameters, const VertexSet& vertices,
                              std::vector<Eigen::Vector3d>& force) {
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    force[v] = vertices.mass[v] * parameters.gravity + vertices.applied_force[v] -
               parameters.air_damping * vertices.damping_length[v] * vertices.velocity[v];
  }
}

void accumulateExplicitForces(const SimulationParameters& parameters, const VertexSet& vertices,
                              const std::vector<double>& spring_constant, EdgeSet& edges,
                              std::vector<Eigen::Vector3d>& force) {
  accumulateExternalForces(parameters, vertices, force);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    edges.spring_tension[e] = 0.0;
    if (!edges.intact(e)) continue;
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    const Eigen::Vector3d d = vertices.position[b] - vertices.position[a];
    const double length = d.norm();
    const double stretch = length - edges.rest_length[e];
    if (!(stretch > 0.0)) continue;  // yarns do not resist compression
    const double tension = spring_constant[e] * stretch;
    edges.spring_tension[e] = tension;
    const Eigen::Vector3d f = (tension / length) * d;
    force[a] += f;
    force[b] -= f;
  }
}

void predictPositions(const std::vector<Eigen::Vector3d>& force, double time_step,
                      VertexSet& vertices) {
  const double dt = time_step;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    switch (vertices.motion[v]) {
      case VertexMotion::kFree:
        vertices.velocity[v] += (dt / vertices.mass[v]) * force[v];
        vertices.position[v] += dt * vertices.velocity[v];
        break;
      case VertexMotion::kPinned:
        vertices.velocity[v].setZero();
        break;
      case VertexMotion::kKinematic:
        vertices.velocity[v] = (vertices.kinematic_target[v] - vertices.position[v]) / dt;
        vertices.position[v] = vertices.kinematic_target[v];
        break;
    }
  }
}

}  // namespace yarn_tearing
