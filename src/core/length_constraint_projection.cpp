#include "yarn_tearing/core/length_constraint_projection.hpp"

#include <algorithm>
#include <cmath>

namespace yarn_tearing {

ProjectionResult LengthConstraintProjection::project(std::vector<Eigen::Vector3d>& position,
                                                     const VertexSet& vertices,
                                                     const EdgeSet& edges,
                                                     const std::vector<double>& compliance,
                                                     const SimulationParameters& parameters,
                                                     EdgeGramSolver& gram) {
  time_step2_ = parameters.time_step * parameters.time_step;
  inverse_mass_.resize(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) inverse_mass_[v] = vertices.inverseMass(v);
  const std::size_t q = edges.size();
  shift_.resize(q);
  for (std::size_t e = 0; e < q; ++e) shift_[e] = compliance[e] / time_step2_;
  direction_.resize(q);
  residual_.resize(q);
  limit_.resize(q);
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
    direction_[e] = length > 0.0 ? Eigen::Vector3d(d / length) : Eigen::Vector3d::Zero();
    limit_[e] = edges.rest_length[e] + shift_[e] * multiplier_[e];
    residual_[e] = length - limit_[e];
    const bool holding = multiplier_[e] > 0.0;
    active_[e] = (residual_[e] > 0.0 || holding) ? 1 : 0;
    const double violation = holding ? std::abs(residual_[e]) : std::max(residual_[e], 0.0);
    max_violation = std::max(max_violation, violation / limit_[e]);
  }
  return max_violation;
}

ProjectionResult LengthConstraintProjection::projectFast(std::vector<Eigen::Vector3d>& position,
                                                         const EdgeSet& edges,
                                                         const SimulationParameters& parameters,
                                                         EdgeGramSolver& gram) {
  GramSystem system;
  system.direction = &direction_;
  system.vertex_weight = &inverse_mass_;
  system.active = &active_;
  system.diagonal_shift = &shift_;
  ProjectionResult result;
  for (;;) {
    result.max_violation = evaluate(position, edges);
    result.converged = result.max_violation <= parameters.constraint_tolerance;
    if (result.converged || result.iterations >= parameters.max_projection_iterations) break;
    for (std::size_t e = 0; e < edges.size(); ++e) step_[e] = active_[e] ? residual_[e] : 0.0;
    gram.solve(edges, system, step_);
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (!active_[e]) continue;
      const double dl = step_[e];
      const std::uint32_t a = edges.vertex_a[e];
      const std::uint32_t b = edges.vertex_b[e];
      position[a] += (inverse_mass_[a] * dl) * direction_[e];
      position[b] -= (inverse_mass_[b] * dl) * direction_[e];
      // The full Newton step moves the vertices (clamping it would break the balance between
      // redundant constraints); an edge whose force would turn compressive is released instead:
      // it holds no force and leaves the active set unless stretched again.
      multiplier_[e] = std::max(multiplier_[e] + dl, 0.0);
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
      const double residual = length - edges.rest_length[e] - shift_[e] * multiplier_[e];
      const double denominator = inverse_mass_[a] + inverse_mass_[b] + shift_[e];
      const double dl = std::max(residual / denominator, -multiplier_[e]);
      if (dl == 0.0 || !(length > 0.0)) continue;
      multiplier_[e] += dl;
      const Eigen::Vector3d n = d / length;
      position[a] += (inverse_mass_[a] * dl) * n;
      position[b] -= (inverse_mass_[b] * dl) * n;
    }
    ++result.iterations;
  }
  return result;
}

}  // namespace yarn_tearing
