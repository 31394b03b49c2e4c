// scheduleSubtrees(): the split of an elimination tree over two threads on small trees whose best
// split is known, and no split where the numbering is not a postorder.
#include "yarn_tearing/core/linalg/subtree_schedule.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace yarn_tearing::test {
namespace {

using Ranges = std::vector<std::pair<int, int>>;

TEST(SubtreeSchedule, SplitsTwoEqualSubtreesBelowTheirRoot) {
  // 0 1 -> 2 and 3 4 -> 5, both -> 6.
  const std::vector<int> parent = {2, 2, 6, 5, 5, 6, -1};
  const std::vector<double> cost = {1.0, 1.0, 2.0, 1.0, 1.0, 2.0, 4.0};
  const SubtreeSchedule schedule = scheduleSubtrees(parent, cost);
  ASSERT_TRUE(schedule.split());
  EXPECT_EQ(schedule.top, std::vector<int>{6});
  const Ranges left = {{0, 2}};
  const Ranges right = {{3, 5}};
  EXPECT_TRUE((schedule.ranges[0] == left && schedule.ranges[1] == right) ||
              (schedule.ranges[0] == right && schedule.ranges[1] == left));
  // 4 + 4 of 12 on one thread, then the root's 4.
  EXPECT_DOUBLE_EQ(schedule.time_share, 8.0 / 12.0);
}

TEST(SubtreeSchedule, GoesDownAnUnevenTreeToBalanceIt) {
  // The root 8 over a heavy subtree (7 over {0, 2} and {3, 4, 5, 6}) and a light leaf 1: the
  // best split takes 8 and 7 into the top and shares the two subtrees below 7 and the leaf out.
  // 0 -> 2, 1 -> 8, 2 -> 7, 3 4 -> 5, 5 -> 6, 6 -> 7, 7 -> 8.
  const std::vector<int> parent = {2, 8, 7, 5, 5, 6, 7, 8, -1};
  const std::vector<double> cost = {4.0, 1.0, 4.0, 2.0, 2.0, 2.0, 2.0, 1.0, 1.0};
  // Numbered in a postorder except that 1 (a root's leaf) sits inside: 0 1 2 is no subtree
  // range of 2, whose subtree is {0, 2}.
  EXPECT_FALSE(scheduleSubtrees(parent, cost).split());
  // The same tree numbered in a postorder: 0 -> 1, 2 3 -> 4, 4 -> 5, 1 5 -> 6, 6 7 -> 8.
  const std::vector<int> postordered = {1, 6, 4, 4, 5, 6, 8, 8, -1};
  const std::vector<double> costs = {4.0, 4.0, 2.0, 2.0, 2.0, 2.0, 1.0, 1.0, 1.0};
  const SubtreeSchedule schedule = scheduleSubtrees(postordered, costs);
  ASSERT_TRUE(schedule.split());
  // Top 6 and 8; subtrees {0, 1} (8), {2..5} (8) and {7} (1) shared out as 9 against 8.
  EXPECT_EQ(schedule.top, (std::vector<int>{6, 8}));
  EXPECT_DOUBLE_EQ(schedule.time_share, (2.0 + 9.0) / 19.0);
  const Ranges with_leaf = {{0, 1}, {7, 7}};
  const Ranges without = {{2, 5}};
  const Ranges with_leaf_b = {{2, 5}, {7, 7}};
  const Ranges without_b = {{0, 1}};
  const auto is = [&schedule](const Ranges& a, const Ranges& b) {
    return (schedule.ranges[0] == a && schedule.ranges[1] == b) ||
           (schedule.ranges[0] == b && schedule.ranges[1] == a);
  };
  EXPECT_TRUE(is(with_leaf, without) || is(with_leaf_b, without_b));
}

TEST(SubtreeSchedule, LeavesAChainUnsplit) {
  const std::vector<int> chain = {1, 2, 3, -1};
  EXPECT_FALSE(scheduleSubtrees(chain, {1.0, 1.0, 1.0, 1.0}).split());
}

}  // namespace
}  // namespace yarn_tearing::test
