#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cstdint>
#include <memory>
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
/// kMostFillGrowth since the last AMD ordering; a new size always reorders. With
/// keepAnalyses(n), the last n analyses are kept (within kKeptEntries), each with its own
/// factorization, and a matrix listing the same (row, column) sequence as one of them takes it
/// up again: a Newton step with contact rows whose pivoting passes go through the same few
/// systems every step (a patch draped over a ball: four sizes a step) analyses each once, not
/// once a pass. Other systems keep one: a tearing fabric's patterns seldom return, and keeping
/// its analyses costs it 10-40 % (side by side).
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
/// a 64 x 64 fabric to twice the nonzeros of the taut edges' own pattern.)
///
/// With leaveOutIdleRows(), the caller says instead which rows are in use: the entries off the
/// diagonal of the others (idle rows) are left out, every other entry is kept even when it is zero,
/// and an ordering is computed from the entries kept rather than from all listed ones. A system
/// listed once with every entry it may ever use (an edge Gram matrix over all edges, those not in
/// use idle) then keeps its listed pattern, and a change of the rows in use brings only an analysis
/// of the entries kept, in the same ordering, until the fill grows past kMostIdleFillGrowth or rows
/// in use stay the same for kSettledFactorizations (then the next factorize() orders anew;
/// beginDirect() refuses until it has). Copies start without an analysis (Eigen's solvers
/// cannot be copied) and without idle rows (the vector belongs to the original's owner).
class PatternCachedLdlt {
 public:
  PatternCachedLdlt() = default;
  PatternCachedLdlt(const PatternCachedLdlt& other)
      : leave_out_zeros_(other.leave_out_zeros_),
        most_kept_(other.most_kept_),
        threads_(other.threads_) {}
  PatternCachedLdlt& operator=(const PatternCachedLdlt& other) {
    leave_out_zeros_ = other.leave_out_zeros_;
    rows_in_use_ = nullptr;
    most_kept_ = other.most_kept_;
    threads_ = other.threads_;
    kept_.clear();
    direct_values_ = nullptr;
    direct_count_ = 0;
    return *this;
  }

  /// From now on, leaves entries that are exactly zero out of the factorization (see above).
  void leaveOutZeros() { leave_out_zeros_ = true; }
  /// From now on, leaves the entries off the diagonal of the rows that `in_use` marks 0 (idle;
  /// 1 for a row in use, read at each factorization: it must outlive them) out of the
  /// factorization, and orders by the others (see above).
  void leaveOutIdleRows(const std::vector<std::uint8_t>* in_use) {
    leave_out_zeros_ = true;
    rows_in_use_ = in_use;
  }
  /// Keeps the last `most` analyses (at least 1, the default) to be taken up again (see above).
  void keepAnalyses(std::size_t most) { most_kept_ = std::max<std::size_t>(most, 1); }
  /// Threads the factorizations may use [-] (SparseLdlt::setThreads); the factors do not depend
  /// on it.
  void setThreads(int threads) { threads_ = threads; }

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
    if (cursor_ >= direct_count_ || direct_row_[cursor_] != row || direct_col_[cursor_] != col) {
      return false;
    }
    addNext(value);
    return true;
  }
  /// addDirect() of the nine entries (row + i, col + j) of `block`, row by row; false when the
  /// sequence does not have them next. A block's first and last entries are checked: entries of
  /// one 3 x 3 block at (row, col) are listed together, and no other entry of a listing of such
  /// blocks at the rows of distinct vertices is (row, col) or (row + 2, col + 2) nine entries on.
  template <typename Block>
  bool addDirectBlock(int row, int col, const Block& block) {
    if (cursor_ + 9 > direct_count_ || direct_row_[cursor_] != row || direct_col_[cursor_] != col ||
        direct_row_[cursor_ + 8] != row + 2 || direct_col_[cursor_ + 8] != col + 2) {
      return false;
    }
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) addNext(block(i, j));
    }
    return true;
  }
  /// Passes over the next `count` entries of the sequence as zeros (an idle row's, with
  /// leaveOutIdleRows()); false when the sequence has fewer left.
  bool skipDirect(std::size_t count) {
    if (cursor_ + count > direct_count_) return false;
    cursor_ += count;
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
    const Analysis& a = *kept_.front();
    const Eigen::Index size = a.new_index.size();
    permuted_.resize(size);
    for (Eigen::Index i = 0; i < size; ++i) permuted_[a.new_index[i]] = rhs[i];
    a.ldlt.solveInPlace(permuted_);
    Eigen::VectorXd result(size);
    for (Eigen::Index i = 0; i < size; ++i) result[i] = permuted_[a.new_index[i]];
    return result;
  }
  /// Symbolic analyses so far [-] (for tests and benchmarks).
  long analyses() const { return analyses_; }
  /// Analyses of the nonzero entries' pattern so far (leaveOutZeros()) [-].
  long zeroFreeAnalyses() const { return zero_free_analyses_; }
  /// Symbolic analyses of the factor (elimination tree, column counts, the supernodal kernel's
  /// supernodes) so far, of the listed pattern or, with leaveOutZeros(), of its nonzeros [-].
  long factorAnalyses() const { return factor_analyses_; }
  /// Nonzeros of the last factor's L [-] (for tests and benchmarks).
  Eigen::Index factorNonZeros() const {
    return kept_.empty() ? 0 : kept_.front()->ldlt.factorNonZeros();
  }

 private:
  /// Adds `value` to the sequence's next entry (where the factorization reads it) and moves on.
  void addNext(double value) {
    const int slot = direct_slot_[cursor_++];
    if (slot >= 0) direct_values_[slot] += value;
  }
  /// One symbolic analysis with the factorization of its pattern.
  struct Analysis {
    std::uint64_t signature = 0;  ///< sequenceSignature() of its (row, column) sequence
    std::vector<int> entry_row;   ///< row of each entry of the sequence
    std::vector<int> entry_col;   ///< column of each entry of the sequence
    /// Per entry: its index in upper's values, -1 for an entry of the upper triangle (not read).
    std::vector<int> slot;
    Eigen::VectorXi new_index;  ///< row i of the matrix is row new_index[i] of the permuted one
    Eigen::SparseMatrix<double> upper;  ///< upper triangle of P A P^T
    /// With leaveOutZeros(): upper without its zero entries off the diagonal, as last analysed.
    Eigen::SparseMatrix<double> nonzero;
    /// Per value of upper: its index in nonzero's values, -1 when left out.
    std::vector<int> nonzero_slot;
    /// Per value of nonzero: its index in upper's values.
    std::vector<int> nonzero_source;
    SparseLdlt ldlt;
  };

  /// A hash of the size and the (row, column) sequence of `entries`.
  static std::uint64_t sequenceSignature(const std::vector<Eigen::Triplet<double>>& entries,
                                         Eigen::Index size);
  /// Moves the kept analysis whose sequence `entries` lists (`signature` its
  /// sequenceSignature()) to the front of kept_; false when none does.
  bool takeUpKept(const std::vector<Eigen::Triplet<double>>& entries, Eigen::Index size,
                  std::uint64_t signature);
  /// Puts a new analysis of `entries` at the front of kept_ (makeRoom() drops the oldest beyond
  /// most_kept_): orders, builds the permuted upper triangle's pattern and each entry's slot.
  bool analyze(const std::vector<Eigen::Triplet<double>>& entries, Eigen::Index size,
               std::uint64_t signature);
  /// Finds each entry's slot in the front analysis's pattern and keeps the sequence; false when
  /// one is not in it.
  bool placeEntries(const std::vector<Eigen::Triplet<double>>& entries);

  /// How the front analysis's upper values fit its analysed nonzero pattern.
  enum class NonzeroFit {
    kFits,  ///< every nonzero value within it, at most kMostZeroShare of its entries zero now
    kGrow,  ///< a nonzero value outside it, the share of zeros within bounds
    kNew,   ///< more zeros than kMostZeroShare, or no analysis of this pattern
  };
  /// Copies the front analysis's upper values into its nonzero pattern's values (those within
  /// it) and says how they fit it; copies nothing for kNew of a pattern not analysed.
  NonzeroFit copyNonzeros();
  /// Builds the front analysis's nonzero pattern from its upper values and diagonal, with
  /// `grow` also from the entries it held, and analyses it.
  bool analyzeNonzeros(bool grow);
  /// Factorizes the front analysis's upper, or with leaveOutZeros() its nonzero entries.
  bool factorizeValues();
  /// Whether the entry (row, col) of the listed matrix is in use (leaveOutIdleRows()).
  bool entryInUse(int row, int col) const {
    return row == col || ((*rows_in_use_)[static_cast<std::size_t>(row)] != 0 &&
                          (*rows_in_use_)[static_cast<std::size_t>(col)] != 0);
  }
  /// The same for the entry (row, col) of the front analysis's permuted matrix (after
  /// permuteRowsInUse()).
  bool permutedEntryInUse(int row, Eigen::Index col) const {
    return row == col || (permuted_in_use_[static_cast<std::size_t>(row)] != 0 &&
                          permuted_in_use_[static_cast<std::size_t>(col)] != 0);
  }
  /// With leaveOutIdleRows(): per row of the front analysis's permuted matrix, whether it is in
  /// use (permuted_in_use_).
  void permuteRowsInUse();
  /// With leaveOutIdleRows(), after an analysis of the entries in use: watchFill() on it, and
  /// the next factorize() orders anew when the fill has grown.
  void watchRowsInUse();

  /// After factorizing a new analysis: its fill per matrix entry, or whether it has grown past
  /// kMostFillGrowth of the last ordering's (then the next analysis orders anew).
  void watchFill(bool analysed);

  /// Growth of the factor's fill per matrix entry, since the last ordering, that brings a new
  /// one [-].
  static constexpr double kMostFillGrowth = 1.1;
  /// Share of the entries of the analysed nonzero pattern that may be zero before it is analysed
  /// anew (leaveOutZeros()) [-].
  static constexpr double kMostZeroShare = 0.3;
  /// Most stored entries (patterns and factors) of the analyses kept beside the one in use [-]
  /// (about 6 MB): a large system keeps only the one in use.
  static constexpr Eigen::Index kKeptEntries = 500000;
  /// Before a new analysis: keeps the newest analyses, fewer than most_kept_ and within
  /// kKeptEntries, and drops the others; returns the newest dropped one (null if none), whose
  /// buffers the new analysis reuses.
  std::unique_ptr<Analysis> makeRoom();
  bool leave_out_zeros_ = false;  ///< see leaveOutZeros()
  /// The rows in use (leaveOutIdleRows()), or null when zeros are left out by their value.
  const std::vector<std::uint8_t>* rows_in_use_ = nullptr;
  std::vector<std::uint8_t> permuted_in_use_;  ///< *rows_in_use_ in the permuted order
  /// *rows_in_use_ when the front analysis's nonzero pattern was last checked against them.
  std::vector<std::uint8_t> last_in_use_;
  /// The analysis of the nonzeros grew the fill past kMostFillGrowth (leaveOutIdleRows()): the
  /// next factorize() orders anew even when its sequence is the front analysis's.
  bool reorder_listed_ = false;
  /// With leaveOutIdleRows(): the ordering in use was made for the rows in use now.
  bool ordered_for_rows_ = false;
  /// With leaveOutIdleRows(): factorizations since the rows in use last changed [-].
  int settled_ = 0;
  /// Factorizations after which rows in use that have not changed get an ordering of their own
  /// (leaveOutIdleRows()) [-]: a fabric at rest keeps its slack edges for thousands of steps.
  static constexpr int kSettledFactorizations = 16;
  /// kMostFillGrowth for leaveOutIdleRows(), whose rows in use change in most factorizations [-].
  static constexpr double kMostIdleFillGrowth = 2.0;
  std::size_t most_kept_ = 1;  ///< see keepAnalyses()
  int threads_ = 1;            ///< see setThreads()
  bool ordered_ = false;       ///< the last analysis computed its ordering
  bool reorder_next_ = true;   ///< the next analysis computes a new ordering
  double ordered_fill_ = 0.0;  ///< factor nonzeros per matrix nonzero at the last ordering [-]
  /// The kept analyses, the last factorized first.
  std::vector<std::unique_ptr<Analysis>> kept_;
  std::size_t cursor_ = 0;  ///< the next entry addDirect() expects
  /// The front analysis's sequence (rows, columns, slots; direct_count_ entries) while entries
  /// are added directly: addDirect() runs once per entry of every Newton system.
  const int* direct_row_ = nullptr;
  const int* direct_col_ = nullptr;
  const int* direct_slot_ = nullptr;
  std::size_t direct_count_ = 0;
  double* direct_values_ = nullptr;  ///< the front's upper values while entries are added directly
  long zero_free_analyses_ = 0;
  long factor_analyses_ = 0;
  mutable Eigen::VectorXd permuted_;  ///< a right-hand side in the permuted order
  long analyses_ = 0;
};

}  // namespace yarn_tearing
