#include <gtest/gtest.h>

#include "yarn_tearing/ros/clipped_text.hpp"
#include "yarn_tearing/ros/rate_schedule.hpp"
#include "yarn_tearing/ros/step_scheduler.hpp"
#include "yarn_tearing/ros/warning_throttle.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kStep = 1.0e-3;  // [s]

TEST(StepScheduler, FollowsWallTimeTimesTheFactor) {
  StepScheduler scheduler(kStep, 1.0, 0.25);
  scheduler.restart(100.0, 0.0);
  EXPECT_EQ(scheduler.stepsDue(100.0105, 0.0), 10U);
  EXPECT_EQ(scheduler.stepsDue(100.0105, 0.010), 0U);
  EXPECT_EQ(scheduler.stepsDue(100.011, 0.010), 1U);  // exactly on a step boundary

  StepScheduler twice(kStep, 2.0, 0.25);
  twice.restart(0.0, 5.0);
  EXPECT_EQ(twice.stepsDue(0.01, 5.0), 20U);
  EXPECT_EQ(twice.droppedSteps(), 0U);
}

TEST(StepScheduler, DropsBacklogBeyondMaxLag) {
  StepScheduler scheduler(kStep, 1.0, 0.1);
  scheduler.restart(0.0, 0.0);
  const std::uint64_t due = scheduler.stepsDue(1.0, 0.0);  // 1 s behind, 0.1 s allowed
  EXPECT_NEAR(static_cast<double>(due), 100.0, 1.0);
  EXPECT_NEAR(static_cast<double>(scheduler.droppedSteps()), 900.0, 1.0);
  // Caught up on what was kept: nothing more is due until wall time moves on.
  EXPECT_EQ(scheduler.stepsDue(1.0, due * kStep), 0U);
}

TEST(StepScheduler, LagIsTheSimulatedTimeBehindTheSchedule) {
  StepScheduler scheduler(kStep, 2.0, 0.25);
  scheduler.restart(10.0, 1.0);
  EXPECT_NEAR(scheduler.lag(10.1, 1.05), 0.15, 1e-12);  // due 1.2 s at 10.1 s wall
  EXPECT_EQ(scheduler.lag(10.1, 1.3), 0.0);             // ahead: not behind
  StepScheduler fast(kStep, 0.0, 0.25);
  fast.restart(0.0, 0.0);
  EXPECT_EQ(fast.lag(100.0, 0.0), 0.0);
}

TEST(StepScheduler, AsFastAsPossibleLeavesPacingToTheCaller) {
  StepScheduler scheduler(kStep, 0.0, 0.25);
  EXPECT_TRUE(scheduler.asFastAsPossible());
  scheduler.restart(0.0, 0.0);
  EXPECT_EQ(scheduler.stepsDue(10.0, 0.0), 0U);
}

TEST(RateSchedule, IsDueOncePerPeriodAndSkipsMissedPeriods) {
  RateSchedule schedule(10.0);
  schedule.restart(0.0);
  EXPECT_TRUE(schedule.due(0.0));
  EXPECT_FALSE(schedule.due(0.05));
  EXPECT_NEAR(schedule.secondsUntilDue(0.05), 0.05, 1e-12);
  EXPECT_TRUE(schedule.due(0.1));
  EXPECT_TRUE(schedule.due(0.55));  // missed 0.2 .. 0.5: one message, not four
  EXPECT_FALSE(schedule.due(0.6));
  EXPECT_TRUE(schedule.due(0.65));
}

TEST(RateSchedule, ToleratesRoundingOfSummedSteps) {
  RateSchedule schedule(50.0);
  schedule.restart(0.0);
  ASSERT_TRUE(schedule.due(0.0));
  double t = 0.0;
  int published = 0;
  for (int i = 0; i < 1000; ++i) {  // 1 s of 1 ms steps
    t += kStep;
    published += schedule.due(t) ? 1 : 0;
  }
  EXPECT_EQ(published, 50);
}

TEST(WarningThrottle, ReportsEachReasonOncePerPeriodAndCountsTheRest) {
  WarningThrottle throttle(2.0, 3);
  EXPECT_TRUE(throttle.shouldReport(0, 0.0));
  EXPECT_TRUE(throttle.shouldReport(1, 0.1));
  for (int i = 0; i < 9999; ++i) {
    EXPECT_FALSE(throttle.shouldReport(0, 0.2 + 1.0e-4 * i));
  }
  EXPECT_TRUE(throttle.shouldReport(0, 2.5));
  EXPECT_EQ(throttle.heldBack(0), 9999u);
  EXPECT_TRUE(throttle.shouldReport(2, 2.5));
  EXPECT_FALSE(throttle.shouldReport(7, 2.6));  // past the set: shares the last key
}

TEST(ClippedText, ClipsLongNamesAndKeepsShortOnes) {
  EXPECT_EQ(clipped("yarn"), "yarn");
  const std::string clip = clipped(std::string(200000, 'x'));
  EXPECT_LE(clip.size(), kMaxQuotedName + 20);
  EXPECT_NE(clip.find("200000 chars"), std::string::npos) << clip;
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing
