#include "yarn_tearing/ros/obstacle_move_limit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(ObstacleMoveLimit, StepLimitIsTheShareOfTheShortestSegment) {
  YarnSpec thread;  // 0.3 m in 2 edges: 0.15 m segments
  thread.name = "thread";
  thread.length = 0.3;
  thread.num_vertices = 3;
  FabricSpec cloth;  // 0.1 m over 4 ends: 1/30 m weft segments, the shortest
  cloth.name = "cloth";
  cloth.warp_crimp = 0.0;
  cloth.weft_crimp = 0.0;
  cloth.ends = 4;
  cloth.picks = 3;
  cloth.weft_length = 0.1;
  cloth.warp_length = 0.1;
  EXPECT_DOUBLE_EQ(obstacleStepLimit(buildScene({thread}, {cloth})),
                   kObstacleStepFraction * 0.1 / 3.0);
  EXPECT_EQ(obstacleStepLimit(Scene{}), std::numeric_limits<double>::infinity());
}

TEST(ObstacleMoveLimit, ACloseTargetIsReached) {
  Eigen::Isometry3d from = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d to = Eigen::Isometry3d::Identity();
  to.translate(Eigen::Vector3d(0.003, 0.004, 0.0));  // 5 mm away
  to.rotate(Eigen::AngleAxisd(kPi / 2.0, Eigen::Vector3d::UnitZ()));
  const Eigen::Isometry3d moved = limitedObstacleMove(from, to, 0.005);
  EXPECT_TRUE(moved.isApprox(to, 1e-15));
}

TEST(ObstacleMoveLimit, AFarTargetIsApproachedByTheLimitTurningByTheSameShare) {
  Eigen::Isometry3d from = Eigen::Isometry3d::Identity();
  from.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
  Eigen::Isometry3d to = Eigen::Isometry3d::Identity();
  to.translation() = Eigen::Vector3d(1.0, 1000.0, 0.0);  // a frame teleported 1 km
  to.linear() = Eigen::AngleAxisd(kPi / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const double limit = 0.5;  // [m]: 1/2000 of the way
  const Eigen::Isometry3d moved = limitedObstacleMove(from, to, limit);
  EXPECT_NEAR((moved.translation() - Eigen::Vector3d(1.0, 0.5, 0.0)).norm(), 0.0, 1e-12);
  const Eigen::AngleAxisd turned(moved.rotation());
  EXPECT_NEAR(turned.angle(), (kPi / 2.0) * limit / 1000.0, 1e-12);
  EXPECT_NEAR(std::abs(turned.axis().z()), 1.0, 1e-12);
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing
