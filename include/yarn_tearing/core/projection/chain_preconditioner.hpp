#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/linalg/tridiagonal_ldlt.hpp"
#include "yarn_tearing/core/model/edge_chains.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

/// A preconditioner of the edge Gram system (GramOperator) for conjugate gradients: the
/// system's couplings along each yarn, kept, and those between yarns, dropped. In chain order
/// (EdgeChains) that is a tridiagonal matrix, each yarn's block the Gram matrix of that yarn alone
/// (positive definite), factorized in O(q). Two yarns couple only where they share a vertex v, by
/// w_v n_e . n_f: where warp and weft cross at right angles that is 0, so for a woven fabric the
/// preconditioner is nearly the system itself.
class ChainPreconditioner {
 public:
  /// Factorizes the chains' blocks of the system of `direction`, `vertex_weight`, the rows
  /// `included` and the assembled `diagonal` (GramOperator's).
  void factorize(const EdgeSet& edges, const EdgeChains& chains,
                 const std::vector<Eigen::Vector3d>& direction,
                 const std::vector<double>& vertex_weight,
                 const std::vector<std::uint8_t>& included, const std::vector<double>& diagonal);
  /// x = P^-1 b with the last factorization.
  template <typename Rhs, typename Dest>
  void apply(const Rhs& b, Dest& x) const {
    const std::size_t size = order_.size();
    for (std::size_t i = 0; i < size; ++i) chain_rhs_[i] = b[order_[i]];
    tridiagonal_.solveInPlace(chain_rhs_.data());
    x.resize(static_cast<Eigen::Index>(size));
    for (std::size_t i = 0; i < size; ++i) x[order_[i]] = chain_rhs_[i];
  }
  /// Rows [-].
  Eigen::Index size() const { return static_cast<Eigen::Index>(order_.size()); }

 private:
  std::vector<std::uint32_t> order_;    ///< EdgeChains::order() of the last factorization
  std::vector<double> chain_diagonal_;  ///< the diagonal in chain order
  std::vector<double> chain_upper_;     ///< couplings along the chains
  TridiagonalLdlt tridiagonal_;
  mutable std::vector<double> chain_rhs_;  ///< a right-hand side in chain order (scratch)
};

}  // namespace yarn_tearing
