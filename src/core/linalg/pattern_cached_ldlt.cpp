#include "yarn_tearing/core/linalg/pattern_cached_ldlt.hpp"

#include <Eigen/OrderingMethods>
#include <algorithm>

namespace yarn_tearing {

std::uint64_t PatternCachedLdlt::sequenceSignature(
    const std::vector<Eigen::Triplet<double>>& entries, Eigen::Index size) {
  // FNV-1a over the size and each entry's row and column.
  constexpr std::uint64_t kPrime = 1099511628211ULL;
  std::uint64_t hash = 14695981039346656037ULL;
  const auto mix = [&](std::uint64_t value) { hash = (hash ^ value) * kPrime; };
  mix(static_cast<std::uint64_t>(size));
  for (const Eigen::Triplet<double>& t : entries) {
    mix((static_cast<std::uint64_t>(static_cast<std::uint32_t>(t.row())) << 32) |
        static_cast<std::uint32_t>(t.col()));
  }
  return hash;
}

bool PatternCachedLdlt::takeUpKept(const std::vector<Eigen::Triplet<double>>& entries,
                                   Eigen::Index size, std::uint64_t signature) {
  const auto same = [&](const std::unique_ptr<Analysis>& a) {
    if (a->signature != signature || a->new_index.size() != size ||
        a->entry_row.size() != entries.size()) {
      return false;
    }
    for (std::size_t k = 0; k < entries.size(); ++k) {
      if (entries[k].row() != a->entry_row[k] || entries[k].col() != a->entry_col[k]) return false;
    }
    return true;
  };
  const auto found = std::find_if(kept_.begin(), kept_.end(), same);
  if (found == kept_.end()) return false;
  std::rotate(kept_.begin(), found, found + 1);
  return true;
}

bool PatternCachedLdlt::placeEntries(const std::vector<Eigen::Triplet<double>>& entries) {
  Analysis& a = *kept_.front();
  const int* outer = a.upper.outerIndexPtr();
  const int* inner = a.upper.innerIndexPtr();
  a.slot.assign(entries.size(), -1);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const Eigen::Triplet<double>& t = entries[k];
    if (t.row() < t.col()) continue;  // the upper triangle is not read
    const int i = a.new_index[t.row()];
    const int j = a.new_index[t.col()];
    const int row = std::min(i, j);
    const int col = std::max(i, j);
    // Row indices within a column are sorted (setFromTriplets).
    const int* end = inner + outer[col + 1];
    const int* found = std::lower_bound(inner + outer[col], end, row);
    if (found == end || *found != row) return false;
    a.slot[k] = static_cast<int>(found - inner);
  }
  a.entry_row.resize(entries.size());
  a.entry_col.resize(entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    a.entry_row[k] = entries[k].row();
    a.entry_col[k] = entries[k].col();
  }
  return true;
}

bool PatternCachedLdlt::analyze(const std::vector<Eigen::Triplet<double>>& entries,
                                Eigen::Index size, std::uint64_t signature) {
  ++analyses_;
  // The last factorized analysis lends its ordering to one of the same size.
  const bool same_size = !kept_.empty() && kept_.front()->new_index.size() == size;
  ordered_ = !same_size || reorder_next_;
  Eigen::VectorXi last_index = ordered_ ? Eigen::VectorXi() : kept_.front()->new_index;
  // The newest analysis dropped lends its buffers (a large system's own, analysed anew); its
  // nonzero pattern is forgotten, so that the first factorization analyses this one's.
  std::unique_ptr<Analysis> reused = makeRoom();
  kept_.insert(kept_.begin(), reused ? std::move(reused) : std::make_unique<Analysis>());
  Analysis& a = *kept_.front();
  a.signature = signature;
  a.nonzero_slot.clear();
  a.nonzero_source.clear();
  if (ordered_) {
    // The ordering Eigen's SimplicialLDLT would choose: AMD on the symmetric matrix of the lower
    // triangle.
    Eigen::SparseMatrix<double> full(size, size);
    if (rows_in_use_ != nullptr) {
      std::vector<Eigen::Triplet<double>> kept;
      kept.reserve(entries.size());
      for (const Eigen::Triplet<double>& t : entries) {
        if (entryInUse(t.row(), t.col())) kept.push_back(t);
      }
      full.setFromTriplets(kept.begin(), kept.end());
    } else {
      full.setFromTriplets(entries.begin(), entries.end());
    }
    const Eigen::SparseMatrix<double> symmetric = full.selfadjointView<Eigen::Lower>();
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
    Eigen::AMDOrdering<int>()(symmetric, inverse);
    const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation =
        inverse.inverse();
    a.new_index = permutation.indices();
    reorder_next_ = false;
  } else {
    a.new_index.swap(last_index);
  }
  // The permuted upper triangle's pattern.
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(entries.size());
  for (const Eigen::Triplet<double>& t : entries) {
    if (t.row() < t.col()) continue;
    const int i = a.new_index[t.row()];
    const int j = a.new_index[t.col()];
    pattern.emplace_back(std::min(i, j), std::max(i, j), 0.0);
  }
  a.upper.resize(size, size);
  a.upper.setFromTriplets(pattern.begin(), pattern.end());
  a.upper.makeCompressed();
  if (!leave_out_zeros_) {
    ++factor_analyses_;
    if (!a.ldlt.analyzePattern(a.upper)) return false;
  }
  return placeEntries(entries);
}

PatternCachedLdlt::NonzeroFit PatternCachedLdlt::copyNonzeros() {
  Analysis& a = *kept_.front();
  if (a.nonzero_slot.size() != static_cast<std::size_t>(a.upper.nonZeros()) ||
      a.nonzero.rows() != a.upper.rows()) {
    return NonzeroFit::kNew;
  }
  const double* values = a.upper.valuePtr();
  const int* slot = a.nonzero_slot.data();
  double* kept = a.nonzero.valuePtr();
  double left_out = 0.0;  // where a value left out of the pattern goes
  Eigen::Index zeros = 0;
  int outside = 0;
  if (rows_in_use_ != nullptr && *rows_in_use_ == last_in_use_) {
    // The rows in use as in the last factorization: its pattern fits.
    const int* source = a.nonzero_source.data();
    for (std::size_t i = 0; i < a.nonzero_source.size(); ++i) kept[i] = values[source[i]];
    return NonzeroFit::kFits;
  }
  if (rows_in_use_ != nullptr) {
    // By the rows in use: an entry is kept where both its rows are (or on the diagonal).
    last_in_use_ = *rows_in_use_;
    ordered_for_rows_ = false;
    settled_ = 0;
    permuteRowsInUse();
    const int* outer = a.upper.outerIndexPtr();
    const int* inner = a.upper.innerIndexPtr();
    for (Eigen::Index j = 0; j < a.upper.outerSize(); ++j) {
      for (int k = outer[j]; k < outer[j + 1]; ++k) {
        const bool within = slot[k] >= 0;
        const bool idle = !permutedEntryInUse(inner[k], j);
        *(within ? kept + slot[k] : &left_out) = values[k];
        zeros += static_cast<Eigen::Index>(within & idle);
        outside |= static_cast<int>(!within & !idle);
      }
    }
  } else {
    // Without branches: which values are zero, and where, follows the scene, not a pattern the
    // branch predictor learns.
    for (std::size_t k = 0; k < a.nonzero_slot.size(); ++k) {
      const double value = values[k];
      const bool within = slot[k] >= 0;
      const bool zero = value == 0.0;
      *(within ? kept + slot[k] : &left_out) = value;
      zeros += static_cast<Eigen::Index>(within & zero);
      outside |= static_cast<int>(!within & !zero);
    }
  }
  if (static_cast<double>(zeros) > kMostZeroShare * static_cast<double>(a.nonzero.nonZeros())) {
    return NonzeroFit::kNew;
  }
  return outside != 0 ? NonzeroFit::kGrow : NonzeroFit::kFits;
}

bool PatternCachedLdlt::analyzeNonzeros(bool grow) {
  ++zero_free_analyses_;
  ++factor_analyses_;
  Analysis& a = *kept_.front();
  const Eigen::Index size = a.upper.rows();
  const int* outer = a.upper.outerIndexPtr();
  const int* inner = a.upper.innerIndexPtr();
  const double* values = a.upper.valuePtr();
  // Grown, the pattern keeps what it held: entries that come and go (a slack edge that turns
  // taut now and then) then stay in it instead of bringing an analysis each time they return.
  if (!grow) a.nonzero_slot.assign(static_cast<std::size_t>(a.upper.nonZeros()), -1);
  if (rows_in_use_ != nullptr) permuteRowsInUse();
  const auto in_use = [&](Eigen::Index j, int k) {
    if (rows_in_use_ == nullptr) return values[k] != 0.0 || inner[k] == j;
    return permutedEntryInUse(inner[k], j);
  };
  int kept = 0;
  a.nonzero_source.clear();
  for (Eigen::Index j = 0; j < size; ++j) {
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const bool held = grow && a.nonzero_slot[k] >= 0;
      a.nonzero_slot[k] = in_use(j, k) || held ? kept++ : -1;
      if (a.nonzero_slot[k] >= 0) a.nonzero_source.push_back(k);
    }
  }
  // Columns of upper are sorted, so are the kept entries: the arrays are filled directly.
  a.nonzero.resize(size, size);
  a.nonzero.resizeNonZeros(kept);
  int* nonzero_outer = a.nonzero.outerIndexPtr();
  int* nonzero_inner = a.nonzero.innerIndexPtr();
  nonzero_outer[0] = 0;
  for (Eigen::Index j = 0; j < size; ++j) {
    int next = nonzero_outer[j];
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      if (a.nonzero_slot[k] >= 0) nonzero_inner[next++] = inner[k];
    }
    nonzero_outer[j + 1] = next;
  }
  return a.ldlt.analyzePattern(a.nonzero);
}

bool PatternCachedLdlt::factorizeValues() {
  Analysis& a = *kept_.front();
  a.ldlt.setThreads(threads_);
  if (!leave_out_zeros_) return a.ldlt.factorize(a.upper);
  const NonzeroFit fit = copyNonzeros();
  if (fit != NonzeroFit::kFits) {
    if (!analyzeNonzeros(fit == NonzeroFit::kGrow)) return false;
    copyNonzeros();  // into the pattern just analysed
    if (rows_in_use_ != nullptr) watchRowsInUse();
  } else if (rows_in_use_ != nullptr && !ordered_for_rows_ &&
             ++settled_ == kSettledFactorizations) {
    reorder_next_ = true;  // rows in use that have settled get an ordering of their own
    reorder_listed_ = true;
  }
  return a.ldlt.factorize(a.nonzero);
}

void PatternCachedLdlt::watchRowsInUse() {
  // The rows in use change under one ordering: the first analysis after it sets the fill to
  // compare with, later ones order anew (at the next factorize()) once it has grown.
  watchFill(true);
  ordered_for_rows_ = ordered_;
  ordered_ = false;
  reorder_listed_ = reorder_next_;
  settled_ = 0;
}

void PatternCachedLdlt::permuteRowsInUse() {
  const Analysis& a = *kept_.front();
  permuted_in_use_.resize(static_cast<std::size_t>(a.new_index.size()));
  for (Eigen::Index i = 0; i < a.new_index.size(); ++i) {
    permuted_in_use_[static_cast<std::size_t>(a.new_index[i])] =
        (*rows_in_use_)[static_cast<std::size_t>(i)];
  }
}

void PatternCachedLdlt::watchFill(bool analysed) {
  if (!analysed) return;
  const Analysis& a = *kept_.front();
  const Eigen::SparseMatrix<double>& factorized = leave_out_zeros_ ? a.nonzero : a.upper;
  const double fill =
      static_cast<double>(factorNonZeros()) / static_cast<double>(factorized.nonZeros());
  if (ordered_) {
    ordered_fill_ = fill;
  } else if (fill >
             (rows_in_use_ != nullptr ? kMostIdleFillGrowth : kMostFillGrowth) * ordered_fill_) {
    reorder_next_ = true;
  }
}

bool PatternCachedLdlt::factorize(const std::vector<Eigen::Triplet<double>>& entries,
                                  Eigen::Index size) {
  direct_values_ = nullptr;
  direct_count_ = 0;
  // With one analysis kept the sequence is compared with it directly, stopping at the first
  // difference; the signature screens several.
  const std::uint64_t signature = most_kept_ > 1 ? sequenceSignature(entries, size) : 0;
  const bool analysed = reorder_listed_ || !takeUpKept(entries, size, signature);
  reorder_listed_ = false;
  if (analysed && !analyze(entries, size, signature)) {
    kept_.erase(kept_.begin());  // no sequence to take up or add to directly
    return false;
  }
  Analysis& a = *kept_.front();
  double* values = a.upper.valuePtr();
  std::fill(values, values + a.upper.nonZeros(), 0.0);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (a.slot[k] >= 0) values[a.slot[k]] += entries[k].value();
  }
  if (!factorizeValues()) return false;
  watchFill(analysed);
  return true;
}

std::unique_ptr<PatternCachedLdlt::Analysis> PatternCachedLdlt::makeRoom() {
  Eigen::Index entries = 0;
  std::size_t keep = 0;
  for (; keep < kept_.size() && keep + 1 < most_kept_; ++keep) {
    const Analysis& a = *kept_[keep];
    entries += a.upper.nonZeros() + a.nonzero.nonZeros() + a.ldlt.factorNonZeros();
    if (entries > kKeptEntries) break;
  }
  std::unique_ptr<Analysis> dropped;
  if (keep < kept_.size()) dropped = std::move(kept_[keep]);
  kept_.resize(keep);
  return dropped;
}

bool PatternCachedLdlt::beginDirect(Eigen::Index size) {
  direct_values_ = nullptr;
  direct_count_ = 0;
  if (kept_.empty() || kept_.front()->new_index.size() != size ||
      kept_.front()->entry_row.empty() || reorder_listed_) {
    return false;
  }
  cursor_ = 0;
  Analysis& a = *kept_.front();
  direct_row_ = a.entry_row.data();
  direct_col_ = a.entry_col.data();
  direct_slot_ = a.slot.data();
  direct_count_ = a.entry_row.size();
  direct_values_ = a.upper.valuePtr();
  std::fill(direct_values_, direct_values_ + a.upper.nonZeros(), 0.0);
  return true;
}

bool PatternCachedLdlt::endDirect() {
  const bool complete = direct_values_ != nullptr && cursor_ == direct_count_;
  direct_values_ = nullptr;
  direct_count_ = 0;
  return complete;
}

}  // namespace yarn_tearing
