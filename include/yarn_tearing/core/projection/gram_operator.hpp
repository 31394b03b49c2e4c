#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

/// The edge Gram system's matrix as an operator, never assembled: (A x)_e =
/// sum_v w_v g_ev . (sum_f g_fv x_f) + (d_e - G_ee) x_e for the included edges (G_ee = w_a + w_b,
/// d_e the assembled diagonal with its regularization and compliance shift; g_ea = -n_e,
/// g_eb = +n_e), and x_e for the others. One product is two passes over the edges, O(q), for
/// conjugate gradients.
class GramOperator {
 public:
  /// The operator of one system; the pointed-to vectors must outlive it. `diagonal` d_e and
  /// `gram_diagonal` G_ee per edge; `included` marks the rows that are not identity rows;
  /// `vertex_sum` is the products' per-vertex scratch, kept by the caller so that a product
  /// allocates nothing.
  GramOperator(const EdgeSet& edges, const std::vector<Eigen::Vector3d>& direction,
               const std::vector<double>& vertex_weight, const std::vector<std::uint8_t>& included,
               const std::vector<double>& diagonal, const std::vector<double>& gram_diagonal,
               std::vector<Eigen::Vector3d>& vertex_sum)
      : edges_(&edges),
        direction_(&direction),
        weight_(&vertex_weight),
        included_(&included),
        diagonal_(&diagonal),
        gram_diagonal_(&gram_diagonal),
        vertex_sum_(&vertex_sum) {}

  Eigen::Index rows() const { return static_cast<Eigen::Index>(included_->size()); }
  Eigen::Index cols() const { return rows(); }

  /// y = A x (`y` of the operator's size).
  void multiply(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const;

 private:
  const EdgeSet* edges_;
  const std::vector<Eigen::Vector3d>* direction_;
  const std::vector<double>* weight_;
  const std::vector<std::uint8_t>* included_;
  const std::vector<double>* diagonal_;
  const std::vector<double>* gram_diagonal_;
  /// Per vertex: sum_f g_fv x_f of the last product.
  std::vector<Eigen::Vector3d>* vertex_sum_;
};

}  // namespace yarn_tearing
