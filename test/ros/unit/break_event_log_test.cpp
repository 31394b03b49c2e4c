#include "yarn_tearing/ros/break_event_log.hpp"

#include <gtest/gtest.h>

namespace yarn_tearing {
namespace ros_layer {
namespace {

/// Records `count` events whose edge is 100 + their order of recording.
void recordEvents(BreakEventLog& log, int count) {
  for (int i = 0; i < count; ++i) {
    BreakEvent event;
    event.edge = 100 + static_cast<int>(log.total());
    log.record(event);
    EXPECT_EQ(event.index, log.total() - 1) << "the published copy carries its index";
  }
}

TEST(BreakEventLog, NumbersEventsInOrderAndReturnsThoseFromAnIndexOn) {
  BreakEventLog log(10);
  recordEvents(log, 4);
  EXPECT_EQ(log.total(), 4u);
  const std::vector<BreakEvent> all = log.since(0);
  ASSERT_EQ(all.size(), 4u);
  for (std::uint32_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(all[i].index, i);
    EXPECT_EQ(all[i].edge, static_cast<int>(100 + i));
  }
  const std::vector<BreakEvent> later = log.since(2);
  ASSERT_EQ(later.size(), 2u);
  EXPECT_EQ(later[0].index, 2u);
  EXPECT_TRUE(log.since(4).empty());
  EXPECT_TRUE(log.since(1000).empty());
}

TEST(BreakEventLog, ClearStartsTheNumberingAgain) {
  BreakEventLog log(10);
  recordEvents(log, 3);
  log.clear();
  EXPECT_EQ(log.total(), 0u);
  EXPECT_TRUE(log.since(0).empty());
  recordEvents(log, 1);
  ASSERT_EQ(log.since(0).size(), 1u);
  EXPECT_EQ(log.since(0)[0].index, 0u);
}

TEST(BreakEventLog, BeyondItsCapacityDropsTheOldest) {
  BreakEventLog log(3);
  recordEvents(log, 5);
  EXPECT_EQ(log.total(), 5u);
  EXPECT_EQ(log.oldest(), 2u);
  const std::vector<BreakEvent> kept = log.since(0);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept.front().index, 2u);
  EXPECT_EQ(kept.back().index, 4u);
  EXPECT_EQ(log.since(3).size(), 2u);
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing
