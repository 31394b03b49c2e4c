#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "yarn_tearing/core/linalg/supernodal_ldlt.hpp"

namespace yarn_tearing {

/// An LDL^T (no pivoting) of a sparse symmetric matrix given by its upper triangle in the order
/// it is to be eliminated, by whichever of two kernels suits its factor: the supernodal one
/// (SupernodalLdlt) where the factor has dense fronts whose products pay for its dearer analysis,
/// Eigen's simplicial one elsewhere. Each analysis measures the factor's cost (the sum over the
/// columns of L of the squared nonzeros below the diagonal) with the kernel in use; where it
/// has crossed to the other kernel's side (kSupernodalCost, kSimplicialCost: apart, so that a
/// cost near them does not switch back and forth), the other kernel analyses it again and is
/// used from then on. The supernodal analysis costs more than the simplicial one, so it pays
/// only on large factors (doc/performance.md, "Factorization kernels").
class SparseLdlt {
 public:
  /// Analyses `upper`'s pattern (square, compressed, entries on and above the diagonal); false
  /// when it is not of that form.
  bool analyzePattern(const Eigen::SparseMatrix<double>& upper);
  /// Factorizes `upper`, of the analysed pattern; false when a pivot is zero or not finite.
  bool factorize(const Eigen::SparseMatrix<double>& upper);
  /// Solves A x = b with the last factorization, in place (b in, x out).
  void solveInPlace(Eigen::VectorXd& x) const;
  /// Nonzeros of L below the diagonal in the analysed pattern [-].
  Eigen::Index factorNonZeros() const;
  /// Threads the supernodal kernel's factorizations may use [-] (SupernodalLdlt::setThreads);
  /// the simplicial kernel uses one.
  void setThreads(int threads) { supernodal_ldlt_.setThreads(threads); }
  /// Whether the supernodal kernel is in use [-] (for tests and benchmarks).
  bool supernodal() const { return supernodal_; }

  /// Factor cost (multiply-adds, the sum over the columns of L of the squared nonzeros below
  /// the diagonal) from which the simplicial kernel hands over to the supernodal one [-]: below
  /// the 32 x 32 trouser tear's Newton systems (1.5e6), whose factorizations the supernodal kernel
  /// takes in about 0.7 x the time, above the 64 x 64 hanging fabric's edge Gram matrix (9e5).
  static constexpr double kSupernodalCost = 1.4e6;
  /// Factor cost below which the supernodal kernel hands back to the simplicial one [-].
  static constexpr double kSimplicialCost = 1e6;

 private:
  /// Eigen's simplicial LDL^T, which tells its analysis's cost from the column counts its
  /// analysis keeps (SimplicialCholeskyBase's protected m_nonZerosPerCol, Eigen 3.3 and 3.4).
  class SimplicialLdlt : public Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper,
                                                      Eigen::NaturalOrdering<int>> {
   public:
    /// As SupernodalLdlt::factorizationCost() [-].
    double factorizationCost() const {
      return static_cast<double>(this->m_nonZerosPerCol.template cast<double>().squaredNorm());
    }
    /// analyzePattern() of an upper triangle already in elimination order: the elimination tree
    /// and column counts straight from it. (Eigen's analyzePattern() tests the ordering type
    /// against NaturalOrdering<Eigen::Index>, not NaturalOrdering<int>, so it expands the matrix
    /// to both triangles and copies it through an empty permutation first, the same pattern.)
    void analyzePreordered(const Eigen::SparseMatrix<double>& upper) {
      this->m_P.resize(0);
      this->m_Pinv.resize(0);
      this->analyzePattern_preordered(upper, true);
    }
  };

  /// Analyses `upper` with the kernel in use.
  bool analyzeWith(const Eigen::SparseMatrix<double>& upper);

  bool supernodal_ = false;
  SupernodalLdlt supernodal_ldlt_;
  SimplicialLdlt simplicial_ldlt_;
  mutable Eigen::VectorXd solution_;  ///< the simplicial kernel's solve
};

}  // namespace yarn_tearing
