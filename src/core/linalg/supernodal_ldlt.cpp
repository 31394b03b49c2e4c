#include "yarn_tearing/core/linalg/supernodal_ldlt.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <new>
#include <system_error>
#include <thread>

namespace yarn_tearing {
namespace {

using ConstBlock = Eigen::Map<const Eigen::MatrixXd>;
using Block = Eigen::Map<Eigen::MatrixXd>;

}  // namespace

bool SupernodalLdlt::worthJoining(Eigen::Index columns, Eigen::Index stored, Eigen::Index zeros) {
  // Relaxed amalgamation after CHOLMOD's defaults (4, 16, 48 columns; 0.8, 0.1, 0.05 of zeros),
  // but supernodes of up to 4 columns with at most 20 % zeros where CHOLMOD joins them freely:
  // on the Newton systems here the free joins stored 1.5 times the factor's nonzeros, which the
  // solves paid for, while the factorization gained nothing measurable.
  const double share = static_cast<double>(zeros) / static_cast<double>(stored);
  if (columns <= 4) return share < 0.2;
  if (columns <= 16) return share < 0.8;
  if (columns <= 48) return share < 0.1;
  return columns <= 256 && share < 0.05;
}

void SupernodalLdlt::eliminationTree(const Eigen::SparseMatrix<double>& upper) {
  const int* outer = upper.outerIndexPtr();
  const int* inner = upper.innerIndexPtr();
  const int n = static_cast<int>(size_);
  // Liu's algorithm with path compression, from the upper triangle's columns.
  parent_.assign(n, -1);
  std::vector<int>& ancestor = scratch_a_;
  ancestor.assign(n, -1);
  for (int j = 0; j < n; ++j) {
    for (int p = outer[j]; p < outer[j + 1]; ++p) {
      for (int i = inner[p]; i != -1 && i < j;) {
        const int next = ancestor[i];
        ancestor[i] = j;
        if (next == -1) parent_[i] = j;
        i = next;
      }
    }
  }
}

void SupernodalLdlt::postorder(std::vector<int>& order) {
  const int n = static_cast<int>(size_);
  std::vector<int>& child_start = scratch_a_;
  std::vector<int>& children = scratch_b_;
  std::vector<int>& next_child = scratch_c_;
  child_start.assign(n + 1, 0);
  for (int j = 0; j < n; ++j) {
    if (parent_[j] >= 0) ++child_start[parent_[j] + 1];
  }
  for (int j = 0; j < n; ++j) child_start[j + 1] += child_start[j];
  children.resize(static_cast<std::size_t>(child_start[n]));
  next_child.assign(child_start.begin(), child_start.end() - 1);
  for (int j = 0; j < n; ++j) {
    if (parent_[j] >= 0) children[next_child[parent_[j]]++] = j;
  }
  // Depth first from each root, a column after its children.
  order.clear();
  next_child.assign(child_start.begin(), child_start.end() - 1);
  std::vector<int>& stack = scratch_d_;
  for (int root = 0; root < n; ++root) {
    if (parent_[root] != -1) continue;
    stack.assign(1, root);
    while (!stack.empty()) {
      const int j = stack.back();
      if (next_child[j] < child_start[j + 1]) {
        stack.push_back(children[next_child[j]++]);
      } else {
        stack.pop_back();
        order.push_back(j);
      }
    }
  }
}

void SupernodalLdlt::buildLowerPattern(const Eigen::SparseMatrix<double>& upper) {
  const int* outer = upper.outerIndexPtr();
  const int* inner = upper.innerIndexPtr();
  const int n = static_cast<int>(size_);
  const auto number = [this](int j) { return new_index_[j]; };
  // Column k of the lower triangle: the rows i >= k of the entries (k, i) of the upper one.
  lower_start_.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    for (int p = outer[i]; p < outer[i + 1]; ++p) {
      ++lower_start_[std::min(number(inner[p]), number(i)) + 1];
    }
  }
  for (int j = 0; j < n; ++j) lower_start_[j + 1] += lower_start_[j];
  lower_row_.resize(static_cast<std::size_t>(nonzeros_));
  lower_entry_.resize(static_cast<std::size_t>(nonzeros_));
  std::vector<int>& fill = scratch_a_;
  fill.assign(lower_start_.begin(), lower_start_.end() - 1);
  for (int i = 0; i < n; ++i) {
    for (int p = outer[i]; p < outer[i + 1]; ++p) {
      const int a = number(inner[p]);
      const int b = number(i);
      const int at = fill[std::min(a, b)]++;
      lower_row_[at] = std::max(a, b);
      lower_entry_[at] = p;
    }
  }
}

int SupernodalLdlt::leaf(int i, int j, std::vector<int>& ancestor, int& kind) {
  // Whether j is a leaf of row i's subtree (kind 1 its first, 2 a later one); for a later leaf,
  // the least common ancestor of it and the leaf before.
  kind = 0;
  if (i <= j || first_descendant_[j] <= max_first_[i]) return -1;
  max_first_[i] = first_descendant_[j];
  const int previous = previous_leaf_[i];
  previous_leaf_[i] = j;
  kind = previous == -1 ? 1 : 2;
  if (kind == 1) return i;
  int q = previous;
  while (q != ancestor[q]) q = ancestor[q];
  for (int s = previous; s != q;) {
    const int next = ancestor[s];
    ancestor[s] = q;
    s = next;
  }
  return q;
}

void SupernodalLdlt::columnCounts() {
  // Gilbert, Ng and Peyton's algorithm (as in Davis's CSparse): the counts from the row
  // subtrees' leaves, in time nearly linear in the matrix's entries rather than the factor's.
  // The numbering is a postorder of the tree.
  const int n = static_cast<int>(size_);
  first_descendant_.assign(n, -1);
  count_.assign(n, 0);
  for (int k = 0; k < n; ++k) {
    int j = k;
    count_[j] = first_descendant_[j] == -1 ? 1 : 0;  // a leaf of the tree
    for (; j != -1 && first_descendant_[j] == -1; j = parent_[j]) first_descendant_[j] = k;
  }
  max_first_.assign(n, -1);
  previous_leaf_.assign(n, -1);
  std::vector<int>& ancestor = scratch_b_;
  ancestor.resize(n);
  for (int i = 0; i < n; ++i) ancestor[i] = i;
  for (int j = 0; j < n; ++j) {
    if (parent_[j] != -1) --count_[parent_[j]];
    for (int p = lower_start_[j]; p < lower_start_[j + 1]; ++p) {
      int kind = 0;
      const int q = leaf(lower_row_[p], j, ancestor, kind);
      if (kind >= 1) ++count_[j];
      if (kind == 2) --count_[q];
    }
    if (parent_[j] != -1) ancestor[j] = parent_[j];
  }
  // A parent's number is larger than its children's.
  for (int j = 0; j < n; ++j) {
    if (parent_[j] != -1) count_[parent_[j]] += count_[j];
  }
}

void SupernodalLdlt::renumber(const std::vector<int>& order) {
  const int n = static_cast<int>(size_);
  new_index_.resize(n);
  for (int k = 0; k < n; ++k) new_index_[order[k]] = k;
  std::vector<int>& parent = scratch_a_;
  parent.resize(n);
  for (int j = 0; j < n; ++j) parent[new_index_[j]] = parent_[j] < 0 ? -1 : new_index_[parent_[j]];
  parent_.swap(parent);
}

void SupernodalLdlt::findSupernodes() {
  const int n = static_cast<int>(size_);
  first_column_.clear();
  // The current supernode: its columns and the nonzeros of L in it (without stored zeros).
  Eigen::Index columns = 0;
  Eigen::Index real = 0;
  for (int j = 0; j < n;) {
    // The fundamental supernode from j: each column the next one's child, the pattern of each
    // the next one's and its own row.
    int last = j;
    Eigen::Index next_real = count_[j];
    while (last + 1 < n && parent_[last] == last + 1 && count_[last] == count_[last + 1] + 1) {
      ++last;
      next_real += count_[last];
    }
    const Eigen::Index next_columns = last - j + 1;
    const Eigen::Index next_rows = count_[j];
    // Joined to the supernode before when that one's last column is a child of j: the joined
    // rows are its columns and j's pattern.
    bool join = columns > 0 && parent_[j - 1] == j;
    if (join) {
      const Eigen::Index joined_columns = columns + next_columns;
      const Eigen::Index joined_rows = columns + next_rows;
      const Eigen::Index stored =
          joined_columns * joined_rows - joined_columns * (joined_columns - 1) / 2;
      join = worthJoining(joined_columns, stored, stored - real - next_real);
    }
    if (join) {
      columns += next_columns;
      real += next_real;
    } else {
      first_column_.push_back(j);
      columns = next_columns;
      real = next_real;
    }
    j = last + 1;
  }
  first_column_.push_back(n);
  supernode_of_.resize(n);
  for (std::size_t s = 0; s + 1 < first_column_.size(); ++s) {
    for (int j = first_column_[s]; j < first_column_[s + 1]; ++j) {
      supernode_of_[j] = static_cast<int>(s);
    }
  }
}

void SupernodalLdlt::collectRows() {
  const int n = static_cast<int>(size_);
  const int supernodes = static_cast<int>(first_column_.size()) - 1;
  // The supernodes below each one (whose last column's parent is among its columns).
  std::vector<int>& child_head = scratch_a_;
  std::vector<int>& child_next = scratch_b_;
  child_head.assign(supernodes, -1);
  child_next.assign(supernodes, -1);
  for (int s = supernodes - 1; s >= 0; --s) {
    const int parent = parent_[first_column_[s + 1] - 1];
    if (parent < 0) continue;
    const int t = supernode_of_[parent];
    child_next[s] = child_head[t];
    child_head[t] = s;
  }
  // A supernode's rows: its columns, then, sorted, the rows below them of its columns' entries
  // and of the rows of the supernodes below it.
  std::vector<int>& mark = scratch_c_;
  mark.assign(n, -1);
  row_start_.assign(supernodes + 1, 0);
  block_start_.assign(supernodes + 1, 0);
  rows_.clear();
  for (int s = 0; s < supernodes; ++s) {
    const int first = first_column_[s];
    const int last = first_column_[s + 1] - 1;
    for (int j = first; j <= last; ++j) rows_.push_back(j);
    const std::size_t below = rows_.size();
    const auto add = [&](int i) {
      if (i > last && mark[i] != s) {
        mark[i] = s;
        rows_.push_back(i);
      }
    };
    for (int j = first; j <= last; ++j) {
      for (int p = lower_start_[j]; p < lower_start_[j + 1]; ++p) add(lower_row_[p]);
    }
    for (int c = child_head[s]; c != -1; c = child_next[c]) {
      for (Eigen::Index r = row_start_[c]; r < row_start_[c + 1]; ++r) add(rows_[r]);
    }
    std::sort(rows_.begin() + static_cast<std::ptrdiff_t>(below), rows_.end());
    row_start_[s + 1] = static_cast<Eigen::Index>(rows_.size());
    const Eigen::Index rows = row_start_[s + 1] - row_start_[s];
    block_start_[s + 1] = block_start_[s] + rows * (last - first + 1);
  }
}

void SupernodalLdlt::placeEntries() {
  const int supernodes = static_cast<int>(first_column_.size()) - 1;
  entry_slot_.resize(static_cast<std::size_t>(nonzeros_));
  for (int s = 0; s < supernodes; ++s) {
    const Eigen::Index rows = row_start_[s + 1] - row_start_[s];
    for (Eigen::Index r = 0; r < rows; ++r)
      work_[0].local_row[rows_[row_start_[s] + r]] = static_cast<int>(r);
    for (int k = first_column_[s]; k < first_column_[s + 1]; ++k) {
      const Eigen::Index column = block_start_[s] + (k - first_column_[s]) * rows;
      for (int p = lower_start_[k]; p < lower_start_[k + 1]; ++p) {
        entry_slot_[lower_entry_[p]] = column + work_[0].local_row[lower_row_[p]];
      }
    }
  }
}

bool SupernodalLdlt::analyzeCounts(const Eigen::SparseMatrix<double>& upper) {
  if (upper.rows() != upper.cols() || !upper.isCompressed()) return false;
  size_ = upper.rows();
  nonzeros_ = upper.nonZeros();
  const int* outer = upper.outerIndexPtr();
  const int* inner = upper.innerIndexPtr();
  for (Eigen::Index j = 0; j < size_; ++j) {
    for (int p = outer[j]; p < outer[j + 1]; ++p) {
      if (inner[p] > j) return false;  // not the upper triangle
    }
  }
  // Renumbered in a postorder of the elimination tree (the same fill; a column's last child
  // right before it, so that the two can share a supernode), and analysed in that numbering.
  eliminationTree(upper);
  postorder(order_);
  renumber(order_);
  buildLowerPattern(upper);
  columnCounts();
  factor_nonzeros_ = 0;
  cost_ = 0.0;
  for (const int count : count_) {
    factor_nonzeros_ += count - 1;
    cost_ += static_cast<double>(count - 1) * (count - 1);
  }
  return true;
}

bool SupernodalLdlt::analyzePattern(const Eigen::SparseMatrix<double>& upper) {
  first_column_.clear();
  scheduled_ = false;
  if (!analyzeCounts(upper)) return false;
  findSupernodes();
  work_[0].local_row.assign(static_cast<std::size_t>(size_), 0);
  collectRows();
  placeEntries();
  const std::size_t supernodes = first_column_.size() - 1;
  values_.resize(static_cast<std::size_t>(block_start_[supernodes]));
  diagonal_.resize(static_cast<std::size_t>(size_));
  next_update_.resize(supernodes);
  for (Workspace& work : work_) work.update_list.resize(supernodes);
  waited_after_.resize(supernodes);
  if (threads_ > 1) scheduleThreads();
  update_next_.resize(supernodes);
  return true;
}

void SupernodalLdlt::scheduleThreads() {
  const int supernodes = static_cast<int>(first_column_.size()) - 1;
  std::vector<int>& tree = scratch_a_;
  tree.resize(supernodes);
  std::vector<double> cost(static_cast<std::size_t>(supernodes), 0.0);
  for (int d = 0; d < supernodes; ++d) {
    // Its parent: the supernode of its last column's parent, as in collectRows().
    const int parent = parent_[first_column_[d + 1] - 1];
    tree[d] = parent < 0 ? -1 : supernode_of_[parent];
    const Eigen::Index columns = first_column_[d + 1] - first_column_[d];
    const Eigen::Index rows = row_start_[d + 1] - row_start_[d];
    const int* row = rows_.data() + row_start_[d];
    cost[d] += static_cast<double>(columns * columns * rows);
    // d's rows below its columns, in runs of one later supernode's columns each, update it.
    for (Eigen::Index first = columns; first < rows;) {
      const int s = supernode_of_[row[first]];
      Eigen::Index end = first;
      while (end < rows && row[end] < first_column_[s + 1]) ++end;
      cost[s] += static_cast<double>((end - first) * (rows - first) * columns);
      first = end;
    }
  }
  schedule_ = scheduleSubtrees(tree, cost);
  scheduled_ = true;
}

void SupernodalLdlt::applyUpdate(Eigen::Index d, Eigen::Index s, Eigen::Index first,
                                 Eigen::Index end, Workspace& work) {
  const Eigen::Index d_first = first_column_[d];
  const Eigen::Index d_columns = first_column_[d + 1] - d_first;
  const Eigen::Index d_rows = row_start_[d + 1] - row_start_[d];
  const int* d_row = rows_.data() + row_start_[d];
  const double* source = values_.data() + block_start_[d];
  // Rows first.. of d update s; rows first..end of them fall in s's columns.
  const Eigen::Index width = end - first;
  const Eigen::Index height = d_rows - first;
  if (work.scaled.size() < static_cast<std::size_t>(width * d_columns)) {
    work.scaled.resize(static_cast<std::size_t>(width * d_columns));
  }
  if (work.product.size() < static_cast<std::size_t>(height * width)) {
    work.product.resize(static_cast<std::size_t>(height * width));
  }
  // product = L_d(first.., :) D_d L_d(first..end, :)^T, its lower trapezoid needed.
  if (d_columns >= kDenseProductColumns && width >= kDenseProductColumns) {
    Block scaled(work.scaled.data(), width, d_columns);
    const ConstBlock block(source, d_rows, d_columns);
    const Eigen::Map<const Eigen::VectorXd> pivots(diagonal_.data() + d_first, d_columns);
    scaled.noalias() = block.middleRows(first, width) * pivots.asDiagonal();
    Block product(work.product.data(), height, width);
    product.noalias() = block.bottomRows(height) * scaled.transpose();
  } else {
    // Narrow updates (the edge rows' and vertices' own): plain loops, no kernel set-up.
    for (Eigen::Index q = 0; q < width; ++q) {
      double* column = work.product.data() + q * height;
      std::fill(column + q, column + height, 0.0);
      for (Eigen::Index k = 0; k < d_columns; ++k) {
        const double* l = source + k * d_rows + first;
        const double factor = l[q] * diagonal_[d_first + k];
        if (factor == 0.0) continue;
        for (Eigen::Index r = q; r < height; ++r) column[r] += l[r] * factor;
      }
    }
  }
  const Eigen::Index s_first = first_column_[s];
  const Eigen::Index s_rows = row_start_[s + 1] - row_start_[s];
  double* target = values_.data() + block_start_[s];
  for (Eigen::Index q = 0; q < width; ++q) {
    double* column = target + (d_row[first + q] - s_first) * s_rows;
    const double* update = work.product.data() + q * height;
    for (Eigen::Index r = q; r < height; ++r) column[work.local_row[d_row[first + r]]] -= update[r];
  }
}

bool SupernodalLdlt::factorizeBlock(Eigen::Index s, Workspace& work) {
  const Eigen::Index first = first_column_[s];
  const Eigen::Index columns = first_column_[s + 1] - first;
  const Eigen::Index rows = row_start_[s + 1] - row_start_[s];
  double* values = values_.data() + block_start_[s];
  if (work.scaled.size() < static_cast<std::size_t>(columns)) {
    work.scaled.resize(static_cast<std::size_t>(columns));
  }
  // Left-looking LDL^T of the block's columns, its rows below the diagonal block included.
  for (Eigen::Index k = 0; k < columns; ++k) {
    double* column = values + k * rows;
    for (Eigen::Index j = 0; j < k; ++j)
      work.scaled[j] = diagonal_[first + j] * values[j * rows + k];
    if (k >= kDenseProductColumns) {
      const ConstBlock left(values, rows, k);
      const Eigen::Map<const Eigen::VectorXd> scaled(work.scaled.data(), k);
      Eigen::Map<Eigen::VectorXd>(column + k, rows - k).noalias() -=
          left.bottomRows(rows - k) * scaled;
    } else {
      for (Eigen::Index j = 0; j < k; ++j) {
        const double* l = values + j * rows;
        const double factor = work.scaled[j];
        for (Eigen::Index r = k; r < rows; ++r) column[r] -= l[r] * factor;
      }
    }
    const double pivot = column[k];
    if (pivot == 0.0 || !std::isfinite(pivot)) return false;
    diagonal_[first + k] = pivot;
    const double inverse = 1.0 / pivot;
    for (Eigen::Index r = k + 1; r < rows; ++r) column[r] *= inverse;
  }
  return true;
}

void SupernodalLdlt::wait(Eigen::Index d, Eigen::Index row, Eigen::Index key, Workspace& work) {
  next_update_[d] = static_cast<int>(row);
  waited_after_[d] = static_cast<int>(key);
  // Each list runs from the latest elimination's waiting to the earliest's (a thread's own
  // eliminations come in order, so it puts its waiting at the head).
  int* link = &work.update_list[supernode_of_[rows_[row_start_[d] + row]]];
  while (*link != -1 && waited_after_[*link] > key) link = &update_next_[*link];
  update_next_[d] = *link;
  *link = static_cast<int>(d);
}

bool SupernodalLdlt::eliminate(Eigen::Index s, Workspace& work) {
  const Eigen::Index rows = row_start_[s + 1] - row_start_[s];
  const int* row = rows_.data() + row_start_[s];
  for (Eigen::Index r = 0; r < rows; ++r) work.local_row[row[r]] = static_cast<int>(r);
  const int last = first_column_[s + 1] - 1;
  for (int d = work.update_list[s]; d != -1;) {
    const int next = update_next_[d];
    const Eigen::Index d_rows = row_start_[d + 1] - row_start_[d];
    const int* d_row = rows_.data() + row_start_[d];
    const Eigen::Index first = next_update_[d];
    Eigen::Index end = first;
    while (end < d_rows && d_row[end] <= last) ++end;
    applyUpdate(d, s, first, end, work);
    if (end < d_rows) wait(d, end, s, work);
    d = next;
  }
  if (!factorizeBlock(s, work)) return false;
  const Eigen::Index columns = first_column_[s + 1] - first_column_[s];
  if (rows > columns) wait(s, columns, s, work);
  return true;
}

bool SupernodalLdlt::eliminateRanges(const std::vector<std::pair<int, int>>& ranges,
                                     Workspace& work) {
  for (const auto& [first, last] : ranges) {
    for (int s = first; s <= last; ++s) {
      if (!eliminate(s, work)) return false;
    }
  }
  return true;
}

void SupernodalLdlt::mergeWaiting() {
  for (const int s : schedule_.top) {
    int* link = &work_[0].update_list[s];
    int other = work_[1].update_list[s];
    while (other != -1) {
      if (*link == -1 || waited_after_[*link] < waited_after_[other]) {
        const int next = update_next_[other];
        update_next_[other] = *link;
        *link = other;
        other = next;
      }
      link = &update_next_[*link];
    }
  }
}

bool SupernodalLdlt::factorizeSplit() {
  Workspace& helper_work = work_[1];
  helper_work.local_row.resize(static_cast<std::size_t>(size_));
  std::fill(helper_work.update_list.begin(), helper_work.update_list.end(), -1);
  bool helper_done = true;
  const auto helper = [this, &helper_work, &helper_done] {
    // An exception must not leave a thread: a failed allocation fails the factorization.
    try {
      helper_done = eliminateRanges(schedule_.ranges[1], helper_work);
    } catch (const std::bad_alloc&) {
      helper_done = false;
    }
  };
  std::thread thread;
  try {
    thread = std::thread(helper);
  } catch (const std::system_error&) {
    // No second thread to be had: the helper's eliminations follow on this one.
  }
  const bool done = eliminateRanges(schedule_.ranges[0], work_[0]);
  if (thread.joinable()) {
    thread.join();
  } else {
    helper();
  }
  if (!done || !helper_done) return false;
  mergeWaiting();
  for (const int s : schedule_.top) {
    if (!eliminate(s, work_[0])) return false;
  }
  return true;
}

bool SupernodalLdlt::factorize(const Eigen::SparseMatrix<double>& upper) {
  if (first_column_.empty() || upper.rows() != size_ || upper.nonZeros() != nonzeros_) {
    return false;
  }
  std::fill(values_.begin(), values_.end(), 0.0);
  const double* entries = upper.valuePtr();
  for (Eigen::Index p = 0; p < nonzeros_; ++p) values_[entry_slot_[p]] += entries[p];
  std::fill(work_[0].update_list.begin(), work_[0].update_list.end(), -1);
  if (threads_ > 1) {
    if (!scheduled_) scheduleThreads();
    if (schedule_.split()) return factorizeSplit();
  }
  const Eigen::Index supernodes = static_cast<Eigen::Index>(first_column_.size()) - 1;
  for (Eigen::Index s = 0; s < supernodes; ++s) {
    if (!eliminate(s, work_[0])) return false;
  }
  return true;
}

void SupernodalLdlt::solveInPlace(Eigen::VectorXd& rhs) const {
  permuted_.resize(size_);
  for (Eigen::Index j = 0; j < size_; ++j) permuted_[new_index_[j]] = rhs[j];
  double* x = permuted_.data();
  const Eigen::Index supernodes = static_cast<Eigen::Index>(first_column_.size()) - 1;
  // L y = b, column by column (the rows of a supernode's columns are its first rows).
  for (Eigen::Index s = 0; s < supernodes; ++s) {
    const Eigen::Index first = first_column_[s];
    const Eigen::Index columns = first_column_[s + 1] - first;
    const Eigen::Index rows = row_start_[s + 1] - row_start_[s];
    const int* row = rows_.data() + row_start_[s];
    const double* values = values_.data() + block_start_[s];
    for (Eigen::Index k = 0; k < columns; ++k) {
      const double* l = values + k * rows;
      const double y = x[first + k];
      if (y == 0.0) continue;
      for (Eigen::Index r = k + 1; r < rows; ++r) x[row[r]] -= l[r] * y;
    }
  }
  for (Eigen::Index j = 0; j < size_; ++j) x[j] /= diagonal_[j];
  // L^T x = y, backwards.
  for (Eigen::Index s = supernodes - 1; s >= 0; --s) {
    const Eigen::Index first = first_column_[s];
    const Eigen::Index columns = first_column_[s + 1] - first;
    const Eigen::Index rows = row_start_[s + 1] - row_start_[s];
    const int* row = rows_.data() + row_start_[s];
    const double* values = values_.data() + block_start_[s];
    for (Eigen::Index k = columns - 1; k >= 0; --k) {
      const double* l = values + k * rows;
      double sum = 0.0;
      for (Eigen::Index r = k + 1; r < rows; ++r) sum += l[r] * x[row[r]];
      x[first + k] -= sum;
    }
  }
  for (Eigen::Index j = 0; j < size_; ++j) rhs[j] = permuted_[new_index_[j]];
}

}  // namespace yarn_tearing
