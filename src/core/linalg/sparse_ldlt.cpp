#include "yarn_tearing/core/linalg/sparse_ldlt.hpp"

namespace yarn_tearing {

bool SparseLdlt::analyzeWith(const Eigen::SparseMatrix<double>& upper) {
  if (supernodal_) return supernodal_ldlt_.analyzePattern(upper);
  simplicial_ldlt_.analyzePreordered(upper);
  return simplicial_ldlt_.info() == Eigen::Success;
}

bool SparseLdlt::analyzePattern(const Eigen::SparseMatrix<double>& upper) {
  if (!analyzeWith(upper)) return false;
  const bool hand_over = supernodal_ ? supernodal_ldlt_.factorizationCost() < kSimplicialCost
                                     : simplicial_ldlt_.factorizationCost() >= kSupernodalCost;
  if (!hand_over) return true;
  supernodal_ = !supernodal_;
  return analyzeWith(upper);
}

bool SparseLdlt::factorize(const Eigen::SparseMatrix<double>& upper) {
  if (supernodal_) return supernodal_ldlt_.factorize(upper);
  simplicial_ldlt_.factorize(upper);
  return simplicial_ldlt_.info() == Eigen::Success;
}

void SparseLdlt::solveInPlace(Eigen::VectorXd& x) const {
  if (supernodal_) {
    supernodal_ldlt_.solveInPlace(x);
    return;
  }
  solution_ = simplicial_ldlt_.solve(x);
  x.swap(solution_);
}

Eigen::Index SparseLdlt::factorNonZeros() const {
  return supernodal_ ? supernodal_ldlt_.factorNonZeros()
                     : simplicial_ldlt_.matrixL().nestedExpression().nonZeros();
}

}  // namespace yarn_tearing
