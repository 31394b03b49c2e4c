#include "yarn_tearing/ros/stamp_clock.hpp"

#include <gtest/gtest.h>

#include "yarn_tearing/ros/step_scheduler.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kClockStep = 1.0e-3;  // [s]
constexpr double kRosStart = 1.8e9;    // [s] a wall-clock ROS time
constexpr double kWallStart = 5000.0;  // [s] the scheduler's (steady) wall clock at the same moment
constexpr double kTolerance = 1.0e-6;  // [s] double rounding at 1.8e9 s

TEST(StampClock, SimulatedTimeIsRosTimeUnderItsOwnClock) {
  const StepScheduler scheduler(kClockStep, 1.0, 0.25);
  const StampClock clock(/*simulated_time_is_ros_time=*/true);
  EXPECT_DOUBLE_EQ(clock.stamp(2.5, scheduler, ros::Time(7.0)).toSec(), 2.5);
}

TEST(StampClock, PacedStampIsStartPlusSimulatedTimeOverFactor) {
  StepScheduler scheduler(kClockStep, 2.0, 0.25);
  scheduler.restart(kWallStart, 0.0);
  StampClock clock(false);
  clock.synchronize(ros::Time(kRosStart), kWallStart);
  // start time + t / real_time_factor, whatever ROS time the message is built at
  EXPECT_NEAR(clock.stamp(3.0, scheduler, ros::Time(kRosStart + 9.0)).toSec(), kRosStart + 1.5,
              kTolerance);
}

TEST(StampClock, StaysMonotonicWhenBacklogIsDropped) {
  StepScheduler scheduler(kClockStep, 1.0, 0.1);
  scheduler.restart(kWallStart, 0.0);
  StampClock clock(false);
  clock.synchronize(ros::Time(kRosStart), kWallStart);
  const double before = clock.stamp(0.5, scheduler, ros::Time()).toSec();
  // 2 s of wall time later the simulation is still at 0.5 s: the backlog beyond 0.1 s is dropped
  scheduler.stepsDue(kWallStart + 2.0, 0.5);
  const double after = clock.stamp(0.5 + kClockStep, scheduler, ros::Time()).toSec();
  EXPECT_GT(after, before);
  // the re-anchored schedule runs 0.5 s at the wall time 0.1 s (max_lag) before now
  EXPECT_NEAR(clock.stamp(0.5, scheduler, ros::Time()).toSec(), kRosStart + 1.9, kTolerance);
}

TEST(StampClock, AsFastAsPossibleStampsTheBuildTime) {
  StepScheduler scheduler(kClockStep, 0.0, 0.25);
  scheduler.restart(kWallStart, 0.0);
  StampClock clock(false);
  clock.synchronize(ros::Time(kRosStart), kWallStart);
  EXPECT_DOUBLE_EQ(clock.stamp(40.0, scheduler, ros::Time(kRosStart + 0.3)).toSec(),
                   kRosStart + 0.3);
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing
