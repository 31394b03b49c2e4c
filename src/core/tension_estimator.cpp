#include "yarn_tearing/core/tension_estimator.hpp"

#include <cmath>

namespace yarn_tearing {

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
    const double h = dt / vertices.mass[v];
    weight_[v] = h * h;
    target_[v] = vertices.velocity[v] - (*input.start_velocity)[v] - h * (*input.force)[v];
    target_norm2 += target_[v].squaredNorm();
  }
  direction_.resize(q);
  active_.resize(q);
  anchor_.assign(tension.begin(), tension.end());
  for (std::size_t e = 0; e < q; ++e) {
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    const Eigen::Vector3d d = vertices.position[b] - vertices.position[a];
    const double length = d.norm();
    active_[e] = edges.intact(e) && length > 0.0;
    direction_[e] = active_[e] ? Eigen::Vector3d(d / length) : Eigen::Vector3d::Zero();
    // Right-hand side A^T b: a tension T pulls a along +n and b along -n.
    const double ha = weight_[a] > 0.0 ? dt / vertices.mass[a] : 0.0;
    const double hb = weight_[b] > 0.0 ? dt / vertices.mass[b] : 0.0;
    tension[e] = direction_[e].dot(ha * target_[a] - hb * target_[b]);
  }
  gram.solve(edges, direction_, weight_, active_, input.regularization, &anchor_, tension);

  // Residual A T - b, accumulated per vertex in target_ (which is no longer needed).
  for (std::size_t e = 0; e < q; ++e) {
    if (!active_[e]) continue;
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    if (weight_[a] > 0.0) target_[a] -= (dt / vertices.mass[a] * tension[e]) * direction_[e];
    if (weight_[b] > 0.0) target_[b] += (dt / vertices.mass[b] * tension[e]) * direction_[e];
  }
  double residual2 = 0.0;
  for (std::size_t v = 0; v < n; ++v) residual2 += target_[v].squaredNorm();
  return target_norm2 > 0.0 ? std::sqrt(residual2 / target_norm2) : 0.0;
}

}  // namespace yarn_tearing
