#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {
class GramOperator;
}  // namespace yarn_tearing

namespace Eigen {
namespace internal {
/// Eigen's iterative solvers take GramOperator as a sparse matrix (matrix-free operator).
template <>
struct traits<yarn_tearing::GramOperator> : public traits<Eigen::SparseMatrix<double>> {};
}  // namespace internal
}  // namespace Eigen

namespace yarn_tearing {

/// The edge Gram system's matrix as an operator, never assembled: (A x)_e =
/// sum_v w_v g_ev . (sum_f g_fv x_f) + (d_e - G_ee) x_e for the included edges (G_ee = w_a + w_b,
/// d_e the assembled diagonal with its regularization and compliance shift; g_ea = -n_e,
/// g_eb = +n_e), and x_e for the others. One product is two passes over the edges, O(q), for
/// Eigen's ConjugateGradient.
class GramOperator : public Eigen::EigenBase<GramOperator> {
 public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum {
    ColsAtCompileTime = Eigen::Dynamic,
    MaxColsAtCompileTime = Eigen::Dynamic,
    IsRowMajor = 0
  };

  /// The operator of one system; the pointed-to vectors must outlive it. `diagonal` d_e and
  /// `gram_diagonal` G_ee per edge; `included` marks the rows that are not identity rows.
  GramOperator(const EdgeSet& edges, const std::vector<Eigen::Vector3d>& direction,
               const std::vector<double>& vertex_weight, const std::vector<std::uint8_t>& included,
               const std::vector<double>& diagonal, const std::vector<double>& gram_diagonal)
      : edges_(&edges),
        direction_(&direction),
        weight_(&vertex_weight),
        included_(&included),
        diagonal_(&diagonal),
        gram_diagonal_(&gram_diagonal) {}

  Eigen::Index rows() const { return static_cast<Eigen::Index>(included_->size()); }
  Eigen::Index cols() const { return rows(); }

  template <typename Rhs>
  Eigen::Product<GramOperator, Rhs, Eigen::AliasFreeProduct> operator*(
      const Eigen::MatrixBase<Rhs>& x) const {
    return Eigen::Product<GramOperator, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }

  /// y = A x (`y` of the operator's size).
  void multiply(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const;
  /// A x into a vector the operator keeps (valid until its next product): Eigen's solvers take a
  /// product every iteration, which then allocates nothing.
  const Eigen::VectorXd& product(const Eigen::Ref<const Eigen::VectorXd>& x) const {
    product_.resize(rows());
    multiply(x, product_);
    return product_;
  }

 private:
  const EdgeSet* edges_;
  const std::vector<Eigen::Vector3d>* direction_;
  const std::vector<double>* weight_;
  const std::vector<std::uint8_t>* included_;
  const std::vector<double>* diagonal_;
  const std::vector<double>* gram_diagonal_;
  /// Per vertex: sum_f g_fv x_f of the last product (scratch; copies share nothing of use).
  mutable std::vector<Eigen::Vector3d> vertex_sum_;
  mutable Eigen::VectorXd product_;  ///< the last product() [-]
};

}  // namespace yarn_tearing

namespace Eigen {
namespace internal {
/// dst += alpha A x for Eigen's solvers.
template <typename Rhs>
struct generic_product_impl<yarn_tearing::GramOperator, Rhs, SparseShape, DenseShape, GemvProduct>
    : generic_product_impl_base<yarn_tearing::GramOperator, Rhs,
                                generic_product_impl<yarn_tearing::GramOperator, Rhs>> {
  template <typename Dest>
  static void scaleAndAddTo(Dest& dst, const yarn_tearing::GramOperator& lhs, const Rhs& rhs,
                            const double& alpha) {
    dst += alpha * lhs.product(rhs);
  }
};
}  // namespace internal
}  // namespace Eigen
