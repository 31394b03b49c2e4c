#include "yarn_tearing/core/linalg/subtree_schedule.hpp"

#include <algorithm>
#include <cstddef>

namespace yarn_tearing {
namespace {

/// Subtrees whose roots the top may take in before the search stops [-]: a tree's cost sits in
/// its upper separators, so the best split is found within the first few (the 64 x 64 trouser
/// tear's Newton system: with one).
constexpr int kMostTopNodes = 16;

}  // namespace

SubtreeSchedule scheduleSubtrees(const std::vector<int>& parent, const std::vector<double>& cost) {
  const int n = static_cast<int>(parent.size());
  // Each subtree's cost, first node and size, from the leaves up (a parent after its children).
  std::vector<double> subtree(cost.begin(), cost.end());
  std::vector<int> first(static_cast<std::size_t>(n));
  std::vector<int> size(static_cast<std::size_t>(n), 1);
  for (int s = 0; s < n; ++s) first[s] = s;
  // Children by parent (compressed: child_start[p] to child_start[p + 1] in children).
  std::vector<int> child_start(static_cast<std::size_t>(n) + 1, 0);
  double total = 0.0;
  for (int s = 0; s < n; ++s) {
    const int p = parent[s];
    if (p == -1) {
      total += subtree[s];
      continue;
    }
    if (p <= s || p >= n) return {};
    subtree[p] += subtree[s];
    first[p] = std::min(first[p], first[s]);
    size[p] += size[s];
    ++child_start[p + 1];
  }
  for (int s = 0; s < n; ++s) child_start[s + 1] += child_start[s];
  std::vector<int> children(static_cast<std::size_t>(child_start[n]));
  std::vector<int> next_child(child_start.begin(), child_start.end() - 1);
  for (int s = 0; s < n; ++s) {
    if (parent[s] != -1) children[next_child[parent[s]]++] = s;
  }
  for (int s = 0; s < n; ++s) {
    if (size[s] != s - first[s] + 1) return {};  // not a postorder
  }
  std::vector<int> frontier;
  for (int s = 0; s < n; ++s) {
    if (parent[s] == -1) frontier.push_back(s);
  }
  // Grow the top by the dearest subtree's root, keeping the best split seen.
  SubtreeSchedule best;
  double best_time = total;
  std::vector<int> top;
  double top_cost = 0.0;
  std::vector<int> owner;
  for (int grown = 0; grown <= kMostTopNodes && !frontier.empty(); ++grown) {
    std::sort(frontier.begin(), frontier.end(),
              [&subtree](int a, int b) { return subtree[a] > subtree[b]; });
    double load[2] = {0.0, 0.0};
    owner.resize(frontier.size());
    for (std::size_t k = 0; k < frontier.size(); ++k) {
      owner[k] = load[1] < load[0] ? 1 : 0;
      load[owner[k]] += subtree[frontier[k]];
    }
    const double time = top_cost + std::max(load[0], load[1]);
    if (time < best_time && load[0] > 0.0 && load[1] > 0.0) {
      best_time = time;
      for (auto& ranges : best.ranges) ranges.clear();
      for (std::size_t k = 0; k < frontier.size(); ++k) {
        best.ranges[owner[k]].emplace_back(first[frontier[k]], frontier[k]);
      }
      best.top = top;
    }
    const int root = frontier.front();
    if (child_start[root] == child_start[root + 1]) break;
    frontier.erase(frontier.begin());
    frontier.insert(frontier.end(), children.begin() + child_start[root],
                    children.begin() + child_start[root + 1]);
    top.push_back(root);
    top_cost += cost[root];
  }
  if (!best.split()) return {};
  for (auto& ranges : best.ranges) std::sort(ranges.begin(), ranges.end());
  std::sort(best.top.begin(), best.top.end());
  best.time_share = best_time / total;
  return best;
}

}  // namespace yarn_tearing
