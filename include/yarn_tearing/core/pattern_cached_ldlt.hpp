#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

namespace yarn_tearing {

/// A sparse LDL^T (Eigen SimplicialLDLT, AMD ordering) that redoes the symbolic analysis
/// (fill-reducing ordering, elimination tree, column counts) only when the matrix's sparsity
/// pattern differs from the one it last analysed; otherwise only the numeric factorization runs.
/// The projection's successive solves within a step, and from step to step while the set of taut
/// edges holds, share one pattern, and the analysis cost more than the factorization on woven
/// grids. Copies start without an analysis (Eigen's solvers cannot be copied).
class PatternCachedLdlt {
 public:
  PatternCachedLdlt() = default;
  PatternCachedLdlt(const PatternCachedLdlt&) {}
  PatternCachedLdlt& operator=(const PatternCachedLdlt&) {
    outer_.clear();
    inner_.clear();
    return *this;
  }

  /// Factorizes `matrix` (compressed, lower triangle read); false when the factorization fails.
  bool factorize(const Eigen::SparseMatrix<double>& matrix);
  /// Solves with the last factorization.
  template <typename Rhs>
  Eigen::VectorXd solve(const Rhs& rhs) const {
    return ldlt_.solve(rhs);
  }
  /// Symbolic analyses so far [-] (for tests and benchmarks).
  long analyses() const { return analyses_; }

 private:
  std::vector<int> outer_;  ///< outer index array of the analysed pattern
  std::vector<int> inner_;  ///< inner index array of the analysed pattern
  long analyses_ = 0;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
};

}  // namespace yarn_tearing
