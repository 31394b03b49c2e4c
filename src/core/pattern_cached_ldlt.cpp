#include "yarn_tearing/core/pattern_cached_ldlt.hpp"

#include <algorithm>

namespace yarn_tearing {

bool PatternCachedLdlt::factorize(const Eigen::SparseMatrix<double>& matrix) {
  const auto outer_size = static_cast<std::size_t>(matrix.outerSize()) + 1;
  const auto nonzeros = static_cast<std::size_t>(matrix.nonZeros());
  const int* outer = matrix.outerIndexPtr();
  const int* inner = matrix.innerIndexPtr();
  const bool same = outer_.size() == outer_size && inner_.size() == nonzeros &&
                    std::equal(outer_.begin(), outer_.end(), outer) &&
                    std::equal(inner_.begin(), inner_.end(), inner);
  if (!same) {
    ldlt_.analyzePattern(matrix);
    ++analyses_;
    if (ldlt_.info() != Eigen::Success) {
      outer_.clear();
      inner_.clear();
      return false;
    }
    outer_.assign(outer, outer + outer_size);
    inner_.assign(inner, inner + nonzeros);
  }
  ldlt_.factorize(matrix);
  return ldlt_.info() == Eigen::Success;
}

}  // namespace yarn_tearing
