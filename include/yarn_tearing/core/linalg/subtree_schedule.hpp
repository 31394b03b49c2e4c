#pragma once

#include <utility>
#include <vector>

namespace yarn_tearing {

/// A split of a factorization's elimination over two threads. The subtrees of an elimination
/// tree share no work until they reach a common ancestor, so two sets of disjoint subtrees can be
/// eliminated at once, one set per thread, and the ancestors above them (the top) afterwards.
struct SubtreeSchedule {
  /// Per thread: its subtrees as ranges [first, last] of the postordered nodes, ascending.
  std::vector<std::pair<int, int>> ranges[2];
  /// The nodes eliminated after both threads' subtrees, ascending.
  std::vector<int> top;
  /// Estimated time of the split elimination over the one-thread elimination's [-] (1 with no
  /// split).
  double time_share = 1.0;

  /// Whether there is a split (both threads have subtrees).
  bool split() const { return !ranges[0].empty() && !ranges[1].empty(); }
};

/// The split of the tree `parent` (parent[s] of node s, -1 at a root; numbered in a postorder,
/// so that each subtree is a range of numbers ending at its root) whose estimated time is least,
/// each node's elimination costing cost[s] (any unit): the top grows from the roots by the
/// subtree of largest cost until the subtrees below it, shared out largest first to the less
/// loaded thread, are as balanced as the top's growth allows. No split (an empty schedule) where
/// the tree is not numbered in a postorder.
SubtreeSchedule scheduleSubtrees(const std::vector<int>& parent, const std::vector<double>& cost);

}  // namespace yarn_tearing
