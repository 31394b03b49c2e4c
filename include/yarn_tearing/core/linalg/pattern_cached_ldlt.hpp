#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "yarn_tearing/core/linalg/sparse_ldlt.hpp"

namespace yarn_tearing {

/// A sparse LDL^T of a symmetric matrix given as a list of entries (both triangles listed, the
/// lower one read; duplicates summed), with an AMD fill-reducing ordering (a SparseLdlt
/// underneath). The symbolic part (the permuted upper triangle's pattern, where each entry lands
/// in it, the elimination tree and column counts) is kept while the entries fall within the
/// analysed pattern: their values are then scattered straight into the permuted matrix and only
/// the numeric factorization runs (no triplet sort, no compression, no permuted copy per
/// factorization). An entry outside it brings a new analysis, which keeps the last ordering
/// (a set of taut edges that changes a little from step to step, as a hanging fabric's slack
/// weft does, hardly changes the fill) until the factor's fill per matrix entry has grown by
/// kMostFillGrowth since the last AMD ordering; a new size always reorders.
///
/// With leaveOutZeros(), entries whose value is exactly zero (and that are not on the diagonal)
/// are left out of the factorization: the listed pattern still fixes the ordering and the
/// slots, but the elimination runs on the pattern of the nonzero entries only, analysed with the
/// same ordering (elimination tree and column counts, no new ordering) whenever a nonzero falls
/// outside the last such analysis (the pattern then grows by it, keeping what it held) or the
/// analysed pattern holds more than kMostZeroShare of unused entries (then it is analysed anew
/// from the nonzeros alone). Leaving out exact zeros is the same matrix eliminated in the same
/// order: the factor differs only in the order its round-off is summed. (A Newton system that keeps
/// an idle row of stored zeros for every slack edge so that its pattern holds filled the factor of
/// a 64 x 64 fabric to twice the nonzeros of the taut edges' own pattern.) Copies start without an
/// analysis (Eigen's solvers cannot be copied).
class PatternCachedLdlt {
 public:
  PatternCachedLdlt() = default;
  PatternCachedLdlt(const PatternCachedLdlt& other) : leave_out_zeros_(other.leave_out_zeros_) {}
  PatternCachedLdlt& operator=(const PatternCachedLdlt& other) {
    leave_out_zeros_ = other.leave_out_zeros_;
    entry_row_.clear();
    entry_col_.clear();
    direct_values_ = nullptr;
    new_index_.resize(0);
    upper_.resize(0, 0);
    nonzero_.resize(0, 0);
    return *this;
  }

  /// From now on, leaves entries that are exactly zero out of the factorization (see above).
  void leaveOutZeros() { leave_out_zeros_ = true; }

  /// Factorizes the size x size matrix of `entries`; false when the factorization fails.
  bool factorize(const std::vector<Eigen::Triplet<double>>& entries, Eigen::Index size);

  /// Starts listing the entries of a size x size matrix straight into the analysed pattern, in
  /// the (row, column) sequence of the last factorize() (addDirect(), endDirect(), then
  /// factorizeDirect()): no list is built, sorted or compared. False when there is no such
  /// sequence for this size.
  bool beginDirect(Eigen::Index size);
  /// Adds `value` to the next entry, (row, col), as factorize() would (the lower triangle read,
  /// duplicates summed); false when (row, col) is not the next entry of that sequence (the
  /// caller then lists the entries for factorize()).
  bool addDirect(int row, int col, double value) {
    if (cursor_ >= entry_row_.size() || entry_row_[cursor_] != row || entry_col_[cursor_] != col) {
      return false;
    }
    const int slot = slot_[cursor_++];
    if (slot >= 0) direct_values_[slot] += value;
    return true;
  }
  /// Whether the entries added since beginDirect() were the whole sequence (not only its start);
  /// when false, the caller lists the entries for factorize().
  bool endDirect();
  /// Factorizes the entries added since beginDirect(), after endDirect() was true; false when
  /// the factorization fails.
  bool factorizeDirect() { return factorizeValues(); }
  /// Solves with the last factorization.
  template <typename Rhs>
  Eigen::VectorXd solve(const Rhs& rhs) const {
    const Eigen::Index size = new_index_.size();
    permuted_.resize(size);
    for (Eigen::Index i = 0; i < size; ++i) permuted_[new_index_[i]] = rhs[i];
    ldlt_.solveInPlace(permuted_);
    Eigen::VectorXd result(size);
    for (Eigen::Index i = 0; i < size; ++i) result[i] = permuted_[new_index_[i]];
    return result;
  }
  /// Symbolic analyses so far [-] (for tests and benchmarks).
  long analyses() const { return analyses_; }
  /// Analyses of the nonzero entries' pattern so far (leaveOutZeros()) [-].
  long zeroFreeAnalyses() const { return zero_free_analyses_; }
  /// Nonzeros of the last factor's L [-] (for tests and benchmarks).
  Eigen::Index factorNonZeros() const { return ldlt_.factorNonZeros(); }

 private:
  /// Orders, builds the permuted upper triangle's pattern and each entry's slot in it.
  bool analyze(const std::vector<Eigen::Triplet<double>>& entries, Eigen::Index size);
  /// Finds each entry's slot in the analysed pattern and keeps the sequence; false when one is
  /// not in it.
  bool placeEntries(const std::vector<Eigen::Triplet<double>>& entries);
  /// Whether `entries` has the (row, column) sequence last placed.
  bool samePattern(const std::vector<Eigen::Triplet<double>>& entries, Eigen::Index size) const;

  /// How upper_'s values fit nonzero_'s analysed pattern.
  enum class NonzeroFit {
    kFits,  ///< every nonzero value within it, at most kMostZeroShare of its entries zero now
    kGrow,  ///< a nonzero value outside it, the share of zeros within bounds
    kNew,   ///< more zeros than kMostZeroShare, or no analysis of this pattern
  };
  NonzeroFit nonzerosFitAnalysed() const;
  /// Builds nonzero_ from upper_'s nonzero values and diagonal, with `grow` also from the
  /// entries it held, and analyses it.
  bool analyzeNonzeros(bool grow);
  /// Factorizes upper_, or with leaveOutZeros() its nonzero entries (nonzero_).
  bool factorizeValues();

  /// After factorizing a new analysis: its fill per matrix entry, or whether it has grown past
  /// kMostFillGrowth of the last ordering's (then the next analysis orders anew).
  void watchFill(bool analysed);

  /// Growth of the factor's fill per matrix entry, since the last ordering, that brings a new
  /// one [-].
  static constexpr double kMostFillGrowth = 1.1;
  /// Share of the entries of the analysed nonzero pattern that may be zero before it is analysed
  /// anew (leaveOutZeros()) [-].
  static constexpr double kMostZeroShare = 0.3;
  bool leave_out_zeros_ = false;  ///< see leaveOutZeros()
  bool ordered_ = false;          ///< the last analysis computed its ordering
  bool reorder_next_ = true;      ///< the next analysis computes a new ordering
  double ordered_fill_ = 0.0;     ///< factor nonzeros per matrix nonzero at the last ordering [-]
  std::vector<int> entry_row_;    ///< row of each entry last placed
  std::vector<int> entry_col_;    ///< column of each entry last placed
  /// Per entry: its index in upper_'s values, -1 for an entry of the upper triangle (not read).
  std::vector<int> slot_;
  std::size_t cursor_ = 0;           ///< the next entry addDirect() expects
  double* direct_values_ = nullptr;  ///< upper_'s values while entries are added directly
  Eigen::VectorXi new_index_;  ///< row i of the matrix is row new_index_[i] of the permuted one
  Eigen::SparseMatrix<double> upper_;  ///< upper triangle of P A P^T
  /// With leaveOutZeros(): upper_ without its zero entries off the diagonal, as last analysed.
  Eigen::SparseMatrix<double> nonzero_;
  /// Per value of upper_: its index in nonzero_'s values, -1 when left out.
  std::vector<int> nonzero_slot_;
  long zero_free_analyses_ = 0;
  mutable Eigen::VectorXd permuted_;  ///< a right-hand side in the permuted order
  long analyses_ = 0;
  SparseLdlt ldlt_;
};

}  // namespace yarn_tearing
