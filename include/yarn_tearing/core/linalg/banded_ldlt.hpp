#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace yarn_tearing {

/// LDL^T without pivoting of a symmetric banded matrix given as a list of entries (both triangles
/// listed, the lower one read; duplicates summed), in its natural order, on dense band storage:
/// O(n b^2) for half bandwidth b. For the quasi-definite Newton systems of chains, whose rows
/// are laid out vertex by vertex (b = 6: three position rows and an edge row per vertex), where
/// a general sparse LDL^T spends most of its time sorting, permuting and analysing the entries
/// rather than eliminating. LAPACK offers banded factorizations only for positive definite
/// matrices (dpbtrf) or with row pivoting (dgbtrf, which doubles the band); the system is
/// indefinite, and its order (each edge row after its vertices' rows) makes every pivot nonzero
/// without pivoting, as SimplicialLDLT in natural order relies on too.
class BandedLdlt {
 public:
  /// Factorizes the n x n matrix of `entries`; false if a pivot is zero or not finite.
  bool factorize(const std::vector<Eigen::Triplet<double>>& entries, int n);
  /// Starts assembling an n x n matrix of half bandwidth b in place: every entry zero.
  void begin(int n, int half_bandwidth);
  /// Adds `value` to entry (row, col) when it is in the lower triangle (row >= col, which must
  /// then be within the band: row - col <= b); an upper one is its mirror and skipped.
  void add(int row, int col, double value) {
    if (row >= col) at(matrix_, row, col) += value;
  }
  /// Factorizes the matrix assembled since begin(); false if a pivot is zero or not finite.
  bool factorize();
  /// Solves with the last factorization: result = A^-1 rhs.
  void solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& result) const;
  /// result = A x with the matrix of the last factorize() (kept beside the factor).
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& result) const;
  int halfBandwidth() const { return bandwidth_; }  ///< b [-]

 private:
  /// Entry (i, j), j <= i <= j + b, of column-wise lower band storage.
  double& at(std::vector<double>& band, int i, int j) const {
    return band[static_cast<std::size_t>(j) * (bandwidth_ + 1) + (i - j)];
  }

  int size_ = 0;
  int bandwidth_ = 0;
  std::vector<double> matrix_;  ///< the lower band of A
  std::vector<double> factor_;  ///< L below the diagonal (unit diagonal), D on it
};

}  // namespace yarn_tearing
