#include "yarn_tearing/ros/frame_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace yarn_tearing {
namespace ros_layer {
namespace {

Eigen::Isometry3d at(const Eigen::Vector3d& position, double yaw = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = position;
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

TEST(FrameMotion, MeasuresConstantVelocitiesBetweenTwoSamples) {
  const FrameMotion motion =
      FrameMotion::between(at({0.0, 0.0, 0.0}, 0.0), 10.0, at({0.01, -0.02, 0.0}, 0.2), 10.5);
  ASSERT_TRUE(motion.moving);
  EXPECT_DOUBLE_EQ(motion.time, 10.5);
  EXPECT_NEAR((motion.velocity - Eigen::Vector3d(0.02, -0.04, 0.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((motion.angular_velocity - Eigen::Vector3d(0.0, 0.0, 0.4)).norm(), 0.0, 1e-12);
}

TEST(FrameMotion, ExtrapolatesAtItsVelocityForAtMostTheBound) {
  const FrameMotion motion =
      FrameMotion::between(at({0.0, 0.0, 0.0}, 0.0), 1.0, at({0.05, 0.0, 0.0}, 0.1), 2.0);
  // 0.03 s past the latest sample: 0.05 m/s * 0.03 s further, 0.1 rad/s * 0.03 s more yaw
  const Eigen::Isometry3d ahead = motion.extrapolated(2.03, 0.1);
  EXPECT_NEAR(ahead.translation().x(), 0.05 + 0.05 * 0.03, 1e-12);
  EXPECT_NEAR(Eigen::AngleAxisd(ahead.linear()).angle(), 0.1 + 0.1 * 0.03, 1e-12);
  // past the bound the pose holds where the bound took it
  EXPECT_NEAR(motion.extrapolated(7.0, 0.1).translation().x(), 0.05 + 0.05 * 0.1, 1e-12);
  EXPECT_NEAR(motion.extrapolated(7.0, 0.0).translation().x(), 0.05, 1e-15);
  // at and before the latest sample: that sample (earlier times are tf2's to interpolate)
  EXPECT_NEAR(motion.extrapolated(2.0, 0.1).translation().x(), 0.05, 1e-15);
  EXPECT_NEAR(motion.extrapolated(1.5, 0.1).translation().x(), 0.05, 1e-15);
}

TEST(FrameMotion, ExtrapolationIsContinuousAtTheLatestSample) {
  const FrameMotion motion =
      FrameMotion::between(at({1.0, 2.0, 3.0}, 0.3), 4.0, at({1.1, 2.0, 3.0}, 0.5), 4.1);
  const Eigen::Isometry3d just_after = motion.extrapolated(4.1 + 1e-9, 0.1);
  EXPECT_NEAR((just_after.translation() - motion.pose.translation()).norm(), 0.0, 1e-8);
  EXPECT_NEAR((just_after.linear() - motion.pose.linear()).norm(), 0.0, 1e-8);
}

TEST(FrameMotion, StandsStillWithoutTwoDistinctSamples) {
  const FrameMotion still = FrameMotion::still(at({0.2, 0.0, 0.0}));
  EXPECT_FALSE(still.moving);
  EXPECT_NEAR(still.extrapolated(1.0e6, 10.0).translation().x(), 0.2, 1e-15);
  // the same stamp twice has no velocity (no division by zero)
  const FrameMotion same = FrameMotion::between(at({0.0, 0.0, 0.0}), 3.0, at({1.0, 0.0, 0.0}), 3.0);
  EXPECT_FALSE(same.moving);
  EXPECT_TRUE(same.velocity.isZero(0.0));
  EXPECT_NEAR(same.extrapolated(3.05, 0.1).translation().x(), 1.0, 1e-15);
}

TEST(PoseCorrection, FadesLinearlyFromWhereItWasToTheEstimate) {
  const Eigen::Isometry3d was = at({0.5, 0.0, 0.0}, 0.2);
  const Eigen::Isometry3d estimate = at({0.5005, 0.0, 0.0}, 0.0);
  const PoseCorrection correction = PoseCorrection::between(was, estimate, 3.0, 0.1);
  const Eigen::Isometry3d at_start = correction.applied(estimate, 3.0);
  EXPECT_NEAR((at_start.translation() - was.translation()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(Eigen::AngleAxisd(at_start.linear()).angle(), 0.2, 1e-12);
  const Eigen::Isometry3d halfway = correction.applied(estimate, 3.05);
  EXPECT_NEAR(halfway.translation().x(), 0.50025, 1e-12);
  EXPECT_NEAR(Eigen::AngleAxisd(halfway.linear()).angle(), 0.1, 1e-12);
  EXPECT_NEAR((correction.applied(estimate, 3.2).translation() - estimate.translation()).norm(),
              0.0, 0.0);
  // no span: the estimate at once
  const PoseCorrection none = PoseCorrection::between(was, estimate, 3.0, 0.0);
  EXPECT_NEAR(none.applied(estimate, 3.0).translation().x(), 0.5005, 0.0);
}

TEST(RampedValue, ChangesAtItsRateBetweenStartAndEnd) {
  const Eigen::Vector3d value(1.0, 0.0, 0.0);
  const Eigen::Vector3d rate(0.0, 2.0, 0.0);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NEAR(rampedValue(value, rate, 5.0, 6.0, 4.0, 1e9).y(), 0.0, 1e-15);  // before the start
  EXPECT_NEAR(rampedValue(value, rate, 5.0, 6.0, 5.25, 1e9).y(), 0.5, 1e-15);
  EXPECT_NEAR(rampedValue(value, rate, 5.0, 6.0, 9.0, 1e9).y(), 2.0, 1e-15);   // stopped at end
  EXPECT_NEAR(rampedValue(value, rate, 5.0, inf, 9.0, 1e9).y(), 8.0, 1e-15);   // no end
  EXPECT_NEAR(rampedValue(value, rate, 5.0, inf, 1e300, 1e9).y(), 2e9, 1e-3);  // bounded span
  EXPECT_DOUBLE_EQ(rampedValue(value, rate, 5.0, inf, 9.0, 1e9).x(), 1.0);
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing
