#pragma once

#include <vector>

namespace yarn_tearing {

/// LDL^T of a symmetric positive definite tridiagonal matrix by Thomas elimination, O(n): the
/// matrix has diagonal d_i and off-diagonal u_i between rows i and i + 1 (0 where two rows are
/// not coupled, which splits the matrix into independent blocks). No pivoting: the matrix must
/// be positive definite.
class TridiagonalLdlt {
 public:
  /// Factorizes the matrix of `diagonal` (d_i) and `upper` (u_i, the last one unused); both of
  /// the matrix's size.
  void factorize(const std::vector<double>& diagonal, const std::vector<double>& upper);
  /// Solves in place: `x` holds b on entry and the solution on exit (the factorized size).
  void solveInPlace(double* x) const;

 private:
  std::vector<double> lower_;  ///< u_{i-1}, the coupling to the row above (0 for row 0)
  std::vector<double> sweep_;  ///< u_i / p_i
  std::vector<double> pivot_;  ///< p_i = d_i - u_{i-1} sweep_{i-1}
};

}  // namespace yarn_tearing
