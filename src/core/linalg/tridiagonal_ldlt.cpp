#include "yarn_tearing/core/linalg/tridiagonal_ldlt.hpp"

namespace yarn_tearing {

void TridiagonalLdlt::factorize(const std::vector<double>& diagonal,
                                const std::vector<double>& upper) {
  const std::size_t n = diagonal.size();
  lower_.resize(n);
  sweep_.resize(n);
  pivot_.resize(n);
  double previous_sweep = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    lower_[i] = i > 0 ? upper[i - 1] : 0.0;
    pivot_[i] = diagonal[i] - lower_[i] * previous_sweep;
    sweep_[i] = i + 1 < n ? upper[i] / pivot_[i] : 0.0;
    previous_sweep = sweep_[i];
  }
}

void TridiagonalLdlt::solveInPlace(double* x) const {
  const std::size_t n = pivot_.size();
  double previous = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = (x[i] - lower_[i] * previous) / pivot_[i];
    previous = x[i];
  }
  for (std::size_t i = n; i-- > 1;) x[i - 1] -= sweep_[i - 1] * x[i];
}

}  // namespace yarn_tearing
