#include "yarn_tearing/core/linalg/pattern_cached_ldlt.hpp"

#include <Eigen/OrderingMethods>
#include <algorithm>

namespace yarn_tearing {

bool PatternCachedLdlt::samePattern(const std::vector<Eigen::Triplet<double>>& entries,
                                    Eigen::Index size) const {
  if (new_index_.size() != size || entry_row_.size() != entries.size()) return false;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (entries[k].row() != entry_row_[k] || entries[k].col() != entry_col_[k]) return false;
  }
  return true;
}

bool PatternCachedLdlt::placeEntries(const std::vector<Eigen::Triplet<double>>& entries) {
  const int* outer = upper_.outerIndexPtr();
  const int* inner = upper_.innerIndexPtr();
  slot_.assign(entries.size(), -1);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const Eigen::Triplet<double>& t = entries[k];
    if (t.row() < t.col()) continue;  // the upper triangle is not read
    const int i = new_index_[t.row()];
    const int j = new_index_[t.col()];
    const int row = std::min(i, j);
    const int col = std::max(i, j);
    // Row indices within a column are sorted (setFromTriplets).
    const int* end = inner + outer[col + 1];
    const int* found = std::lower_bound(inner + outer[col], end, row);
    if (found == end || *found != row) return false;
    slot_[k] = static_cast<int>(found - inner);
  }
  entry_row_.resize(entries.size());
  entry_col_.resize(entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    entry_row_[k] = entries[k].row();
    entry_col_[k] = entries[k].col();
  }
  return true;
}

bool PatternCachedLdlt::analyze(const std::vector<Eigen::Triplet<double>>& entries,
                                Eigen::Index size) {
  ++analyses_;
  entry_row_.clear();
  entry_col_.clear();
  ordered_ = new_index_.size() != size || reorder_next_;
  if (ordered_) {
    // The ordering Eigen's SimplicialLDLT would choose: AMD on the symmetric matrix of the lower
    // triangle.
    Eigen::SparseMatrix<double> full(size, size);
    full.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SparseMatrix<double> symmetric = full.selfadjointView<Eigen::Lower>();
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
    Eigen::AMDOrdering<int>()(symmetric, inverse);
    const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation =
        inverse.inverse();
    new_index_ = permutation.indices();
    reorder_next_ = false;
  }
  // The permuted upper triangle's pattern.
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(entries.size());
  for (const Eigen::Triplet<double>& t : entries) {
    if (t.row() < t.col()) continue;
    const int i = new_index_[t.row()];
    const int j = new_index_[t.col()];
    pattern.emplace_back(std::min(i, j), std::max(i, j), 0.0);
  }
  upper_.resize(size, size);
  upper_.setFromTriplets(pattern.begin(), pattern.end());
  upper_.makeCompressed();
  nonzero_slot_.clear();
  if (!leave_out_zeros_ && !ldlt_.analyzePattern(upper_)) return false;
  return placeEntries(entries);
}

PatternCachedLdlt::NonzeroFit PatternCachedLdlt::nonzerosFitAnalysed() const {
  if (nonzero_slot_.size() != static_cast<std::size_t>(upper_.nonZeros()) ||
      nonzero_.rows() != upper_.rows()) {
    return NonzeroFit::kNew;
  }
  const double* values = upper_.valuePtr();
  Eigen::Index zeros = 0;
  bool outside = false;
  for (std::size_t k = 0; k < nonzero_slot_.size(); ++k) {
    if (nonzero_slot_[k] < 0) {
      outside = outside || values[k] != 0.0;
    } else if (values[k] == 0.0) {
      ++zeros;
    }
  }
  if (static_cast<double>(zeros) > kMostZeroShare * static_cast<double>(nonzero_.nonZeros())) {
    return NonzeroFit::kNew;
  }
  return outside ? NonzeroFit::kGrow : NonzeroFit::kFits;
}

bool PatternCachedLdlt::analyzeNonzeros(bool grow) {
  ++zero_free_analyses_;
  const Eigen::Index size = upper_.rows();
  const int* outer = upper_.outerIndexPtr();
  const int* inner = upper_.innerIndexPtr();
  const double* values = upper_.valuePtr();
  // Grown, the pattern keeps what it held: entries that come and go (a slack edge that turns
  // taut now and then) then stay in it instead of bringing an analysis each time they return.
  if (!grow) nonzero_slot_.assign(static_cast<std::size_t>(upper_.nonZeros()), -1);
  int kept = 0;
  for (Eigen::Index j = 0; j < size; ++j) {
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const bool held = grow && nonzero_slot_[k] >= 0;
      nonzero_slot_[k] = values[k] != 0.0 || inner[k] == j || held ? kept++ : -1;
    }
  }
  // Columns of upper_ are sorted, so are the kept entries: the arrays are filled directly.
  nonzero_.resize(size, size);
  nonzero_.resizeNonZeros(kept);
  int* nonzero_outer = nonzero_.outerIndexPtr();
  int* nonzero_inner = nonzero_.innerIndexPtr();
  nonzero_outer[0] = 0;
  for (Eigen::Index j = 0; j < size; ++j) {
    int next = nonzero_outer[j];
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      if (nonzero_slot_[k] >= 0) nonzero_inner[next++] = inner[k];
    }
    nonzero_outer[j + 1] = next;
  }
  return ldlt_.analyzePattern(nonzero_);
}

bool PatternCachedLdlt::factorizeValues() {
  if (!leave_out_zeros_) return ldlt_.factorize(upper_);
  const NonzeroFit fit = nonzerosFitAnalysed();
  if (fit != NonzeroFit::kFits && !analyzeNonzeros(fit == NonzeroFit::kGrow)) return false;
  const double* values = upper_.valuePtr();
  double* kept = nonzero_.valuePtr();
  for (std::size_t k = 0; k < nonzero_slot_.size(); ++k) {
    if (nonzero_slot_[k] >= 0) kept[nonzero_slot_[k]] = values[k];
  }
  return ldlt_.factorize(nonzero_);
}

void PatternCachedLdlt::watchFill(bool analysed) {
  if (!analysed) return;
  const Eigen::SparseMatrix<double>& factorized = leave_out_zeros_ ? nonzero_ : upper_;
  const double fill =
      static_cast<double>(factorNonZeros()) / static_cast<double>(factorized.nonZeros());
  if (ordered_) {
    ordered_fill_ = fill;
  } else if (fill > kMostFillGrowth * ordered_fill_) {
    reorder_next_ = true;
  }
}

bool PatternCachedLdlt::factorize(const std::vector<Eigen::Triplet<double>>& entries,
                                  Eigen::Index size) {
  direct_values_ = nullptr;
  const bool analysed = !samePattern(entries, size);
  if (analysed && !analyze(entries, size)) {
    entry_row_.clear();
    entry_col_.clear();
    return false;
  }
  double* values = upper_.valuePtr();
  std::fill(values, values + upper_.nonZeros(), 0.0);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (slot_[k] >= 0) values[slot_[k]] += entries[k].value();
  }
  if (!factorizeValues()) return false;
  watchFill(analysed);
  return true;
}

bool PatternCachedLdlt::beginDirect(Eigen::Index size) {
  direct_values_ = nullptr;
  if (new_index_.size() != size || entry_row_.empty()) return false;
  cursor_ = 0;
  direct_values_ = upper_.valuePtr();
  std::fill(direct_values_, direct_values_ + upper_.nonZeros(), 0.0);
  return true;
}

bool PatternCachedLdlt::endDirect() {
  const bool complete = direct_values_ != nullptr && cursor_ == entry_row_.size();
  direct_values_ = nullptr;
  return complete;
}

}  // namespace yarn_tearing
