#include "yarn_tearing/core/projection/gram_operator.hpp"

namespace yarn_tearing {

void GramOperator::multiply(const Eigen::Ref<const Eigen::VectorXd>& x,
                            Eigen::Ref<Eigen::VectorXd> y) const {
  const EdgeSet& edges = *edges_;
  const std::vector<Eigen::Vector3d>& n = *direction_;
  const std::vector<double>& w = *weight_;
  const std::vector<std::uint8_t>& included = *included_;
  std::vector<Eigen::Vector3d>& vertex_sum = *vertex_sum_;
  vertex_sum.assign(w.size(), Eigen::Vector3d::Zero());
  for (std::size_t e = 0; e < included.size(); ++e) {
    if (!included[e]) continue;
    const Eigen::Vector3d pull = x[static_cast<Eigen::Index>(e)] * n[e];
    vertex_sum[edges.vertex_a[e]] -= pull;
    vertex_sum[edges.vertex_b[e]] += pull;
  }
  for (std::size_t e = 0; e < included.size(); ++e) {
    const auto i = static_cast<Eigen::Index>(e);
    const double own = ((*diagonal_)[e] - (*gram_diagonal_)[e]) * x[i];
    if (!included[e]) {
      y[i] = own;
      continue;
    }
    const std::uint32_t a = edges.vertex_a[e];
    const std::uint32_t b = edges.vertex_b[e];
    y[i] = n[e].dot(w[b] * vertex_sum[b] - w[a] * vertex_sum[a]) + own;
  }
}

}  // namespace yarn_tearing
