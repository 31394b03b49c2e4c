#include "yarn_tearing/core/length_constraint_projection.hpp"

#include <algorithm>

namespace yarn_tearing {

ProjectionResult LengthConstraintProjection::project(std::vector<Eigen::Vector3d>& position,
                                                     const VertexSet& vertices,
                                                     const EdgeSet& edges,
                                                     const SimulationParameters& parameters,
                                                     EdgeGramSolver& gram) {
  inverse_mass_.resize(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) inverse_mass_[v] = vertices.inverseMass(v);
  const std::size_t q = edges.size();
  direction_.resize(q);
  violation_.resize(q);
  step_.resize(q);
  active_.resize(q);
  multiplier_.assign(q, 0.0);
  if (parameters.projection_method == ProjectionMethod::kGaussSeidel) {
    return projectGaussSeidel(position, edges, parameters);
  }
  return projectFast(position, edges, parameters, gram);
}

double LengthConstraintProjection::evaluate(const std::vector<Eigen::Vector3d>& position,
                                            const EdgeSet& edges) {
  double max_violation = 0.0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    const bool movable = inverse_mass_[a] + inverse_mass_[b] > 0.0;
    if (!edges.intact(e) || !movable) {
      active_[e] = 0;
      continue;
    }
    const Eigen::Vector3d d = position[b] - position[a];
    const double length = d.norm();
    const double limit = edges.rest_length[e] * (1.0 + edges.strain_limit[e]);
    direction_[e] = length > 0.0 ? Eigen::Vector3d(d / length) : Eigen::Vector3d::Zero();
    violation_[e] = length - limit;
    active_[e] = (violation_[e] > 0.0 || multiplier_[e] > 0.0) ? 1 : 0;
    max_violation = std::max(max_violation, violation_[e] / limit);
  }
  return max_violation;
}

ProjectionResult LengthConstraintProjection::projectFast(std::vector<Eigen::Vector3d>& position,
                                                         const EdgeSet& edges,
                                                         const SimulationParameters& parameters,
                                                         EdgeGramSolver& gram) {
  ProjectionResult result;
  for (;;) {
    result.max_violation = evaluate(position, edges);
    result.converged = result.max_violation <= parameters.constraint_tolerance;
    if (result.converged || result.iterations >= parameters.max_projection_iterations) break;
    for (std::size_t e = 0; e < edges.size(); ++e) step_[e] = active_[e] ? violation_[e] : 0.0;
    gram.solve(edges, direction_, inverse_mass_, active_, 0.0, nullptr, step_);
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (!active_[e]) continue;
      // Projected Newton: the accumulated multiplier may not turn compressive.
      const double dl = std::max(step_[e], -multiplier_[e]);
      multiplier_[e] += dl;
      const std::uint32_t a = edges.vertex_a[e];
      const std::uint32_t b = edges.vertex_b[e];
      position[a] += (inverse_mass_[a] * dl) * direction_[e];
      position[b] -= (inverse_mass_[b] * dl) * direction_[e];
    }
    ++result.iterations;
  }
  return result;
}

ProjectionResult LengthConstraintProjection::projectGaussSeidel(
    std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
    const SimulationParameters& parameters) {
  ProjectionResult result;
  for (;;) {
    result.max_violation = evaluate(position, edges);
    result.converged = result.max_violation <= parameters.constraint_tolerance;
    if (result.converged || result.iterations >= parameters.max_projection_iterations) break;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (!active_[e]) continue;
      const std::uint32_t a = edges.vertex_a[e];
      const std::uint32_t b = edges.vertex_b[e];
      const Eigen::Vector3d d = position[b] - position[a];
      const double length = d.norm();
      const double excess = length - edges.rest_length[e] * (1.0 + edges.strain_limit[e]);
      if (!(excess > 0.0)) continue;
      const Eigen::Vector3d n = d / length;
      const double dl = excess / (inverse_mass_[a] + inverse_mass_[b]);
      position[a] += (inverse_mass_[a] * dl) * n;
      position[b] -= (inverse_mass_[b] * dl) * n;
    }
    ++result.iterations;
  }
  return result;
}

}  // namespace yarn_tearing
