#include "yarn_tearing/ros/obstacle_spec_loader.hpp"

#include <cctype>
#include <stdexcept>
#include <string>
#include <vector>

#include "yarn_tearing/ros/parameter_bounds.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

namespace bounds = parameter_bounds;

/// Keys every obstacle may have, whatever its shape.
const std::vector<std::string> kCommonKeys = {"name",     "shape", "friction",
                                              "position", "rpy",   "attached_frame"};

/// A ROS base name (letter, then letters, digits, '_'): it names the obstacle's topics and its
/// markers' namespace.
bool isBaseName(const std::string& name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  for (const char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

double loadSize(const ParamValue& value) {
  return value.number(bounds::kMinObstacleSize, bounds::kMaxObstacleSize, "m");
}

/// Reads the shape's sizes; returns the keys the shape has besides the common ones.
std::vector<std::string> loadShape(const ParamValue& entry, Obstacle& obstacle) {
  obstacle.shape =
      entry.member("shape").choice<ObstacleShape>({{"plane", ObstacleShape::kPlane},
                                                   {"box", ObstacleShape::kBox},
                                                   {"sphere", ObstacleShape::kSphere},
                                                   {"capsule", ObstacleShape::kCapsule}});
  switch (obstacle.shape) {
    case ObstacleShape::kPlane:
      return {};
    case ObstacleShape::kBox: {
      const ParamValue half_extents = entry.member("half_extents");
      const Eigen::Vector3d h = half_extents.vector3("m");
      if (!(h.minCoeff() >= bounds::kMinObstacleSize && h.maxCoeff() <= bounds::kMaxObstacleSize)) {
        half_extents.fail("a list of 3 half sizes [x, y, z], each in [1e-6, 1e4] [m]");
      }
      obstacle.half_extents = h;
      if (entry.has("edge_radius")) {
        // Within the smallest half extent, so that the faces stay where half_extents puts them.
        obstacle.edge_radius = entry.member("edge_radius").number(0.0, h.minCoeff(), "m");
      }
      return {"half_extents", "edge_radius"};
    }
    case ObstacleShape::kSphere:
      obstacle.radius = loadSize(entry.member("radius"));
      return {"radius"};
    case ObstacleShape::kCapsule:
      obstacle.radius = loadSize(entry.member("radius"));
      obstacle.half_length = loadSize(entry.member("half_length"));
      return {"radius", "half_length"};
  }
  return {};
}

/// `position` and `rpy` of `entry` (each optional, zero by default) as a pose [m].
Eigen::Isometry3d loadPose(const ParamValue& entry) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (entry.has("rpy")) {
    pose.linear() = rotationFromRpy(entry.member("rpy").vector3("rad")).toRotationMatrix();
  }
  if (entry.has("position")) {
    pose.translation() = entry.member("position").boundedVector3(bounds::kMaxPosition, "m");
  }
  return pose;
}

}  // namespace

Eigen::Quaterniond rotationFromRpy(const Eigen::Vector3d& rpy) {
  return Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX());
}

ObstacleSpec loadObstacleSpec(const ParamValue& entry) {
  if (!entry.isStruct()) entry.fail("a map {name, shape, <sizes>, friction, position, rpy, ...}");
  ObstacleSpec spec;
  const ParamValue name = entry.member("name");
  spec.obstacle.name = name.string(false);
  if (!isBaseName(spec.obstacle.name)) {
    name.fail("a name of letters, digits and '_' that starts with a letter (it names topics)");
  }
  std::vector<std::string> keys = kCommonKeys;
  const std::vector<std::string> shape_keys = loadShape(entry, spec.obstacle);
  keys.insert(keys.end(), shape_keys.begin(), shape_keys.end());
  entry.requireKeysIn(keys);
  if (entry.has("friction")) {
    spec.obstacle.friction = entry.member("friction").number(0.0, bounds::kMaxFriction, "");
  }
  const Eigen::Isometry3d pose = loadPose(entry);
  if (entry.has("attached_frame")) {
    spec.attached_frame = entry.member("attached_frame").string(true);  // "": not attached
    if (spec.attached_frame.size() > input_bounds::kMaxFrameName) {
      entry.member("attached_frame").fail("a tf frame name of at most 256 characters");
    }
  }
  if (spec.attached()) {
    spec.offset = pose;
  } else {
    spec.obstacle.pose = pose;
  }
  try {
    spec.obstacle.validate();
  } catch (const std::invalid_argument& e) {
    entry.fail(std::string("a valid obstacle (") + e.what() + ")");
  }
  return spec;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
