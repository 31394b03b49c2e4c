#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "yarn_tearing/core/linalg/subtree_schedule.hpp"

namespace yarn_tearing {

/// A supernodal LDL^T (L unit lower triangular, D diagonal, no pivoting) of a sparse symmetric
/// matrix given by its upper triangle in the order it is to be eliminated (the caller orders it:
/// PatternCachedLdlt). For quasi-definite matrices, the Newton step's KKT systems, any
/// elimination order has such a factorization.
///
/// Columns of L with the same pattern below the diagonal (a supernode: the three coordinates of
/// a vertex, a separator's chain of columns) are stored together as one dense column-major
/// block, and adjacent ones whose patterns nearly agree are joined into one, their few extra
/// entries stored as zeros (relaxed amalgamation). The factorization is left-looking: each
/// supernode gathers the updates of the supernodes below it as dense matrix products, factorizes
/// its diagonal block and solves its rows below it against it (Eigen's dense kernels). On a 2-D
/// mesh, where a scalar (simplicial) elimination spends most of its time on the separators'
/// dense fronts one entry at a time, this is several times faster.
///
/// analyzePattern() computes the elimination tree, the supernodes and where each entry of the
/// matrix lands in them; factorize() takes a matrix of the analysed pattern (the same column
/// pointers and row indices, any values).
///
/// With setThreads(2), factorize() eliminates two sets of disjoint subtrees of the supernodal
/// tree at once (scheduleSubtrees()), then the supernodes above them. Each supernode gathers its
/// updates in the order of the supernodes' eliminations that made them ready, whatever thread
/// made them, so the factor is the same to the last bit for either thread count.
class SupernodalLdlt {
 public:
  /// Analyses the pattern of `upper` (square, compressed, column-major, entries on and above the
  /// diagonal only); false when it is not of that form.
  bool analyzePattern(const Eigen::SparseMatrix<double>& upper);
  /// Factorizes `upper`, of the analysed pattern; false when a pivot is zero or not finite.
  bool factorize(const Eigen::SparseMatrix<double>& upper);
  /// Solves A x = b with the last factorization, in place (b in, x out).
  void solveInPlace(Eigen::VectorXd& x) const;
  /// Threads factorize() may use [-] (1 or 2; more count as 2). The factor does not depend on it.
  void setThreads(int threads) { threads_ = threads; }
  /// The last analysis's split over two threads, once an analysis or a factorization with two
  /// threads has made it (for tests and benchmarks).
  const SubtreeSchedule& schedule() const { return schedule_; }
  /// Nonzeros of L below the diagonal in the analysed pattern (without the zeros a relaxed
  /// supernode stores) [-].
  Eigen::Index factorNonZeros() const { return factor_nonzeros_; }
  /// The analysed factorization's cost: the sum over the columns of L of the squared nonzeros
  /// below the diagonal, the multiply-adds of its updates [-].
  double factorizationCost() const { return cost_; }
  /// Number of supernodes of the last analysis [-] (for tests and benchmarks).
  Eigen::Index supernodes() const { return static_cast<Eigen::Index>(first_column_.size()) - 1; }

 private:
  /// Checks `upper`'s form and computes its elimination tree, postorder and column counts in the
  /// postordered numbering; false when it is not of the form analyzePattern() takes.
  bool analyzeCounts(const Eigen::SparseMatrix<double>& upper);
  /// The elimination tree of `upper` (parent_), in its own order.
  void eliminationTree(const Eigen::SparseMatrix<double>& upper);
  /// A postorder of the elimination tree into `order` (order[k] the k-th column; children in
  /// the order of their numbers).
  void postorder(std::vector<int>& order);
  /// The lower triangle's pattern by columns, renumbered (lower_start_, lower_row_,
  /// lower_entry_).
  void buildLowerPattern(const Eigen::SparseMatrix<double>& upper);
  /// Column counts of L (count_, diagonal included), renumbered.
  void columnCounts();
  /// columnCounts()' test of whether column j is a leaf of row i's subtree (see there).
  int leaf(int i, int j, std::vector<int>& ancestor, int& kind);
  /// Renumbers the columns in `order` (the same fill): new_index_, and parent_ renumbered.
  void renumber(const std::vector<int>& order);
  /// Fundamental supernodes joined by relaxed amalgamation: first_column_, supernode_of_.
  void findSupernodes();
  /// Row indices of each supernode (rows_, row_start_) and the block offsets (block_start_).
  void collectRows();
  /// Where each entry of the upper triangle lands in the blocks (entry_slot_).
  void placeEntries();
  /// The scratch of one thread's eliminations.
  struct Workspace {
    std::vector<int> local_row;    ///< row -> its index in the supernode being eliminated
    std::vector<int> update_list;  ///< per supernode: first supernode waiting to update it
    std::vector<double> product;   ///< an update's dense product
    std::vector<double> scaled;    ///< an update's rows scaled by D
  };
  /// The supernodal tree (each supernode's parent: the supernode of its last column's parent in
  /// the elimination tree, -1 at roots) and each supernode's elimination cost (its updates' and
  /// its own block's multiply-adds), split over two threads: schedule_.
  void scheduleThreads();
  /// Subtracts supernode d's update from supernode s, whose rows are in work.local_row; `first`
  /// and `end` delimit d's rows within s's columns; `first` to d's last row is what it updates.
  void applyUpdate(Eigen::Index d, Eigen::Index s, Eigen::Index first, Eigen::Index end,
                   Workspace& work);
  /// Factorizes supernode s's block in place (its diagonal block and the rows below it).
  bool factorizeBlock(Eigen::Index s, Workspace& work);
  /// Eliminates supernode s: gathers the updates waiting for it, factorizes its block and puts
  /// it in the list of the next supernode its rows reach; false when a pivot fails.
  bool eliminate(Eigen::Index s, Workspace& work);
  /// Eliminates the supernodes of `ranges` in order; false when a pivot fails.
  bool eliminateRanges(const std::vector<std::pair<int, int>>& ranges, Workspace& work);
  /// Puts supernode d, whose rows from `row` on update later supernodes, in the waiting list of
  /// the supernode of that row, after those that waited in a later elimination than `key`'s.
  void wait(Eigen::Index d, Eigen::Index row, Eigen::Index key, Workspace& work);
  /// Merges the second workspace's waiting lists of the top's supernodes into the first's, in
  /// the order of the eliminations that put them there.
  void mergeWaiting();
  /// Factorizes with the split over two threads (the helper's subtrees on a second one, where
  /// one can be started); false when a pivot fails.
  bool factorizeSplit();

  /// Whether two adjacent supernodes are joined into one `columns` wide, of `stored` entries
  /// (its diagonal block's lower triangle included), `zeros` of them stored zeros.
  static bool worthJoining(Eigen::Index columns, Eigen::Index stored, Eigen::Index zeros);

  /// Columns from which an update or a block's own elimination takes Eigen's dense kernels;
  /// narrower ones take plain loops, which cost less than the kernels' set-up [-].
  static constexpr Eigen::Index kDenseProductColumns = 8;
  Eigen::Index size_ = 0;
  Eigen::Index nonzeros_ = 0;  ///< entries of the analysed upper triangle
  std::vector<int> parent_;    ///< elimination tree: parent column of each column, -1 at roots
  std::vector<int> count_;     ///< nonzeros of each column of L, its diagonal included
  /// Column j of the matrix is column new_index_[j] of the postordered one, which is factorized.
  std::vector<int> new_index_;
  std::vector<int> lower_start_;   ///< per column: where its entries start in lower_row_
  std::vector<int> lower_row_;     ///< row of each entry of the lower triangle, by columns
  std::vector<int> lower_entry_;   ///< index of each such entry in the upper triangle's values
  std::vector<int> first_column_;  ///< first column of each supernode, and size_ at the end
  std::vector<int> supernode_of_;  ///< supernode of each column
  std::vector<int> rows_;          ///< each supernode's rows, sorted (its own columns first)
  std::vector<Eigen::Index> row_start_;    ///< where each supernode's rows start in rows_
  std::vector<Eigen::Index> block_start_;  ///< where each supernode's block starts in values_
  std::vector<Eigen::Index> entry_slot_;  ///< per entry of the upper triangle: its place in values_
  Eigen::Index factor_nonzeros_ = 0;      ///< see factorNonZeros()
  double cost_ = 0.0;                     ///< see factorizationCost()
  std::vector<double> values_;            ///< the blocks of L, column-major; D on the diagonal
  std::vector<double> diagonal_;          ///< D
  // Scratch of analyzePattern().
  std::vector<int> first_descendant_;  ///< per column: postorder number of its first descendant
  std::vector<int> max_first_;         ///< per row: largest first_descendant_ of its leaves yet
  std::vector<int> previous_leaf_;     ///< per row: the last leaf of its subtree found
  std::vector<int> order_;             ///< the postorder: order_[k] is the column numbered k
  // Work arrays each phase of the analysis reuses for its own (named where it takes them).
  std::vector<int> scratch_a_;
  std::vector<int> scratch_b_;
  std::vector<int> scratch_c_;
  std::vector<int> scratch_d_;
  int threads_ = 1;           ///< see setThreads()
  SubtreeSchedule schedule_;  ///< see schedule()
  bool scheduled_ = false;    ///< schedule_ is the last analysis's
  // Scratch of factorize().
  Workspace work_[2];                 ///< the calling thread's scratch and the helper's
  std::vector<int> next_update_;      ///< per supernode: its next row that updates a later one
  std::vector<int> update_next_;      ///< per supernode: next one in the same waiting list
  std::vector<int> waited_after_;     ///< per supernode: the elimination it last waited after
  mutable Eigen::VectorXd permuted_;  ///< the right-hand side renumbered (solve)
};

}  // namespace yarn_tearing
