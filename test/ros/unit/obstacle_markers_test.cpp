#include "yarn_tearing/ros/obstacle_markers.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace yarn_tearing {
namespace ros_layer {
namespace {

using visualization_msgs::Marker;

Obstacle capsuleAt(const Eigen::Vector3d& position) {
  Obstacle o;
  o.name = "peg";
  o.shape = ObstacleShape::kCapsule;
  o.radius = 0.002;
  o.half_length = 0.05;
  o.pose.translation() = position;
  return o;
}

TEST(ObstacleMarkers, ACapsuleIsACylinderClosedBySpheres) {
  const Obstacle peg = capsuleAt(Eigen::Vector3d(0.1, 0.2, 0.3));
  const std::vector<Marker> markers = obstacleMarkers(peg, ContactWrench{}, "world", ros::Time(1));
  ASSERT_EQ(markers.size(), 4U);
  for (const Marker& m : markers) {
    EXPECT_EQ(m.ns, "obstacles/peg");
    EXPECT_EQ(m.header.frame_id, "world");
  }
  EXPECT_EQ(markers[0].id, 0);
  EXPECT_EQ(markers[0].type, Marker::CYLINDER);
  EXPECT_DOUBLE_EQ(markers[0].scale.x, 0.004);
  EXPECT_DOUBLE_EQ(markers[0].scale.z, 0.1);
  EXPECT_EQ(markers[1].type, Marker::SPHERE);
  EXPECT_DOUBLE_EQ(markers[1].pose.position.z, 0.25);
  EXPECT_DOUBLE_EQ(markers[2].pose.position.z, 0.35);
  EXPECT_EQ(markers[3].id, 3);
  EXPECT_EQ(markers[3].action, Marker::DELETE);  // no force, no arrow
}

TEST(ObstacleMarkers, APlaneIsAThinSlabUnderItsSurface) {
  Obstacle table;
  table.name = "table";
  table.shape = ObstacleShape::kPlane;
  const std::vector<Marker> markers = obstacleMarkers(table, ContactWrench{}, "w", ros::Time(1));
  ASSERT_EQ(markers.size(), 2U);
  EXPECT_EQ(markers[0].type, Marker::CUBE);
  EXPECT_DOUBLE_EQ(markers[0].pose.position.z + 0.5 * markers[0].scale.z, 0.0);
  EXPECT_DOUBLE_EQ(markers[0].scale.x, kPlaneMarkerSize);
}

TEST(ObstacleMarkers, TheArrowEndsOnTheForcesLineOfAction) {
  const Obstacle peg = capsuleAt(Eigen::Vector3d(1.0, 0.0, 0.0));
  ContactWrench wrench;  // 0.01 N down applied at (1.0, 0.03, 0.0): torque r x F about the origin
  wrench.force = Eigen::Vector3d(0.0, 0.0, -0.01);
  wrench.torque = Eigen::Vector3d(0.0, 0.03, 0.0).cross(wrench.force);
  const Marker arrow = obstacleMarkers(peg, wrench, "world", ros::Time(1)).back();
  EXPECT_EQ(arrow.type, Marker::ARROW);
  EXPECT_EQ(arrow.action, Marker::ADD);
  ASSERT_EQ(arrow.points.size(), 2U);
  EXPECT_NEAR(arrow.points[1].x, 1.0, 1e-12);
  EXPECT_NEAR(arrow.points[1].y, 0.03, 1e-12);
  EXPECT_NEAR(arrow.points[1].z, 0.0, 1e-12);
  // pointing down (along the force), 1 cm + 2 cm per decade above 0.1 mN: 5 cm at 10 mN
  EXPECT_NEAR(arrow.points[0].z - arrow.points[1].z, 0.05, 1e-12);
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing
