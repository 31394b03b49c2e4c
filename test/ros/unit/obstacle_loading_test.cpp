#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "parameter_error_text.hpp"
#include "xmlrpc_builders.hpp"
#include "yarn_tearing/ros/obstacle_spec_loader.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

using testing::list;
using testing::parameterErrorOf;

XmlRpc::XmlRpcValue capsule() {
  XmlRpc::XmlRpcValue obstacle;
  obstacle["name"] = "peg";
  obstacle["shape"] = "capsule";
  obstacle["radius"] = 0.002;
  obstacle["half_length"] = 0.05;
  obstacle["friction"] = 0.3;
  obstacle["position"] = list({0.0, 0.1, 0.5});
  obstacle["rpy"] = list({M_PI / 2.0, 0.0, 0.0});
  return obstacle;
}

ParamValue param(const XmlRpc::XmlRpcValue& obstacle) {
  return ParamValue("/node/obstacles[1]", obstacle);
}

/// what() of the ParameterError that loading `obstacle` throws ("" when none).
std::string obstacleLoadError(const XmlRpc::XmlRpcValue& obstacle) {
  return parameterErrorOf([&] { loadObstacleSpec(param(obstacle)); });
}

TEST(ObstacleSpecLoader, LoadsAFixedCapsule) {
  const ObstacleSpec spec = loadObstacleSpec(param(capsule()));
  EXPECT_EQ(spec.obstacle.name, "peg");
  EXPECT_EQ(spec.obstacle.shape, ObstacleShape::kCapsule);
  EXPECT_DOUBLE_EQ(spec.obstacle.radius, 0.002);
  EXPECT_DOUBLE_EQ(spec.obstacle.half_length, 0.05);
  EXPECT_DOUBLE_EQ(spec.obstacle.friction, 0.3);
  EXPECT_FALSE(spec.attached());
  EXPECT_TRUE(spec.obstacle.pose.translation().isApprox(Eigen::Vector3d(0.0, 0.1, 0.5)));
  // roll pi/2 turns the capsule's axis z onto -y
  EXPECT_TRUE((spec.obstacle.pose.linear() * Eigen::Vector3d::UnitZ())
                  .isApprox(-Eigen::Vector3d::UnitY(), 1e-12));
}

TEST(ObstacleSpecLoader, RpyIsRzRyRxAsStaticFrame) {
  const Eigen::Quaterniond q = rotationFromRpy(Eigen::Vector3d(0.0, 0.0, M_PI / 2.0));
  EXPECT_TRUE((q * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  const Eigen::Quaterniond pitch = rotationFromRpy(Eigen::Vector3d(0.0, M_PI / 2.0, 0.0));
  EXPECT_TRUE((pitch * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX(), 1e-12));
}

TEST(ObstacleSpecLoader, AnAttachedObstacleKeepsItsPoseAsAnOffset) {
  XmlRpc::XmlRpcValue obstacle;
  obstacle["name"] = "finger";
  obstacle["shape"] = "box";
  obstacle["half_extents"] = list({0.01, 0.02, 0.03});
  obstacle["attached_frame"] = "gripper_link";
  obstacle["position"] = list({0.0, 0.0, -0.03});
  const ObstacleSpec spec = loadObstacleSpec(param(obstacle));
  EXPECT_TRUE(spec.attached());
  EXPECT_EQ(spec.attached_frame, "gripper_link");
  EXPECT_TRUE(spec.offset.translation().isApprox(Eigen::Vector3d(0.0, 0.0, -0.03)));
  EXPECT_TRUE(spec.obstacle.half_extents.isApprox(Eigen::Vector3d(0.01, 0.02, 0.03)));
  EXPECT_DOUBLE_EQ(spec.obstacle.friction, 0.0);     // default
  EXPECT_DOUBLE_EQ(spec.obstacle.edge_radius, 0.0);  // default: sharp
}

TEST(ObstacleSpecLoader, AnEmptyAttachedFrameIsAFixedObstacle) {
  XmlRpc::XmlRpcValue obstacle = capsule();
  obstacle["attached_frame"] = "";  // the documented default
  const ObstacleSpec spec = loadObstacleSpec(param(obstacle));
  EXPECT_FALSE(spec.attached());
  EXPECT_TRUE(spec.obstacle.pose.translation().isApprox(Eigen::Vector3d(0.0, 0.1, 0.5)));
}

/// A box of half sizes (0.02, 0.03, 0.04) [m] with edges rounded to `edge_radius` [m].
XmlRpc::XmlRpcValue boxWithEdgeRadius(double edge_radius) {
  XmlRpc::XmlRpcValue obstacle;
  obstacle["name"] = "table";
  obstacle["shape"] = "box";
  obstacle["half_extents"] = list({0.02, 0.03, 0.04});
  obstacle["edge_radius"] = edge_radius;
  return obstacle;
}

TEST(ObstacleSpecLoader, ABoxTakesItsEdgeRadius) {
  EXPECT_DOUBLE_EQ(loadObstacleSpec(param(boxWithEdgeRadius(0.005))).obstacle.edge_radius, 0.005);
}

/// A capsule with `key` set to `value`.
XmlRpc::XmlRpcValue capsuleWith(const std::string& key, const XmlRpc::XmlRpcValue& value) {
  XmlRpc::XmlRpcValue obstacle = capsule();
  obstacle[key] = value;
  return obstacle;
}

/// A box of half sizes `half_extents`, with `radius` too when it is > 0.
XmlRpc::XmlRpcValue box(const XmlRpc::XmlRpcValue& half_extents, double radius) {
  XmlRpc::XmlRpcValue obstacle;
  obstacle["name"] = "block";
  obstacle["shape"] = "box";
  obstacle["half_extents"] = half_extents;
  if (radius > 0.0) obstacle["radius"] = radius;
  return obstacle;
}

TEST(ObstacleSpecLoader, ErrorsNameTheParameterAndWhatIsAllowed) {
  const std::vector<std::pair<XmlRpc::XmlRpcValue, std::string>> cases = {
      {capsuleWith("radius", std::numeric_limits<double>::quiet_NaN()),
       "/node/obstacles[1].radius = nan: expected a finite number"},
      {capsuleWith("half_length", -0.01),
       "obstacles[1].half_length = -0.01: expected a finite number in [1e-06, 10000] [m]"},
      {capsuleWith("friction", -0.1),
       "obstacles[1].friction = -0.1: expected a finite number in "
       "[0, 10]"},
      {capsuleWith("shape", "cylinder"), "'plane' or 'box' or 'sphere' or 'capsule'"},
      {box(list({0.1, 0.1, 0.1}), 0.1),
       "obstacles[1].radius: unknown key 'radius'; allowed keys: name, shape, friction, "
       "position, rpy, attached_frame, half_extents, edge_radius"},
      {boxWithEdgeRadius(0.03),
       "obstacles[1].edge_radius = 0.03: expected a finite number in [0, 0.02] [m]"},
      {box(list({0.1, 0.0, 0.1}), 0.0),
       "obstacles[1].half_extents = [0.1, 0.0, 0.1]: expected a list of 3 half sizes"},
      {capsuleWith("name", "a peg"), "obstacles[1].name = 'a peg': expected a name of"},
      {capsuleWith("position", list({2.0e4, 0.0, 0.0})), "obstacles[1].position"},
  };
  for (const auto& [obstacle, expected] : cases) {
    const std::string error = obstacleLoadError(obstacle);
    EXPECT_NE(error.find(expected), std::string::npos) << error << "\nexpected: " << expected;
  }
}

}  // namespace
}  // namespace ros_layer
}  // namespace yarn_tearing
