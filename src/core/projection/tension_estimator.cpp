#include "yarn_tearing/core/projection/tension_estimator.hpp"

#include <cmath>

namespace yarn_tearing {

void TensionEstimator::solve(const EdgeSet& edges, double regularization, EdgeGramSolver& gram,
                             std::vector<double>& tension) {
  anchor_.assign(tension.begin(), tension.end());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    // Right-hand side A^T b: a tension T pulls a along +n and b along -n.
    tension[e] = direction_[e].dot(weight_[a] * target_[a] - weight_[b] * target_[b]);
  }
  GramSystem system;
  system.direction = &direction_;
  system.vertex_weight = &weight_;
  system.active = &active_;
  system.regularization = regularization;
  system.anchor = &anchor_;
  gram.solve(edges, system, tension);
}

double TensionEstimator::estimate(const TensionEstimateInput& input, const EdgeSet& edges,
                                  EdgeGramSolver& gram, std::vector<double>& tension) {
  const VertexSet& vertices = *input.vertices;
  const double dt = input.time_step;
  const std::size_t n = vertices.size();
  const std::size_t q = edges.size();
  weight_.resize(n);
  target_.resize(n);
  double target_norm2 = 0.0;
  for (std::size_t v = 0; v < n; ++v) {
    if (vertices.isSupport(v)) {
      weight_[v] = 0.0;
      target_[v].setZero();
      continue;
    }
    // Force-balance row of vertex v [N]: m (v'' - v) / dt - F = sum_e T_e u_ev.
    target_[v] = (vertices.mass[v] / dt) * (vertices.velocity[v] - (*input.start_velocity)[v]) -
                 (*input.force)[v];
    const double scale = input.rows == TensionRowWeighting::kVelocity ? dt / vertices.mass[v] : 1.0;
    weight_[v] = scale * scale;
    target_norm2 += weight_[v] * target_[v].squaredNorm();
  }
  direction_.resize(q);
  active_.resize(q);
  for (std::size_t e = 0; e < q; ++e) {
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    const Eigen::Vector3d d = vertices.position[b] - vertices.position[a];
    const double length = d.norm();
    active_[e] = edges.intact(e) && length > 0.0;
    direction_[e] = active_[e] ? Eigen::Vector3d(d / length) : Eigen::Vector3d::Zero();
  }
  if (input.source == TensionSource::kLeastSquares)
    solve(edges, input.regularization, gram, tension);

  // Residual A T - b, accumulated per vertex in target_ (which is no longer needed).
  for (std::size_t e = 0; e < q; ++e) {
    if (!active_[e]) continue;
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    target_[a] -= tension[e] * direction_[e];
    target_[b] += tension[e] * direction_[e];
  }
  double residual2 = 0.0;
  for (std::size_t v = 0; v < n; ++v) residual2 += weight_[v] * target_[v].squaredNorm();
  return target_norm2 > 0.0 ? std::sqrt(residual2 / target_norm2) : 0.0;
}

}  // namespace yarn_tearing
