#pragma once

#include <Eigen/Geometry>
#include <string>

#include "yarn_tearing/core/contact/obstacle.hpp"
#include "yarn_tearing/ros/param_value.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// One entry of ~obstacles: the core's obstacle and where it is.
struct ObstacleSpec {
  /// Shape, sizes [m], friction [-]; its pose [m] is the fixed pose in frame_id when
  /// `attached_frame` is empty.
  Obstacle obstacle;
  /// tf frame the obstacle moves with (a robot link, a finger); empty: fixed in frame_id.
  std::string attached_frame;
  /// With `attached_frame`: the obstacle's pose in that frame [m] (position + rotation).
  Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();

  bool attached() const { return !attached_frame.empty(); }
};

/// Reads one entry of ~obstacles (doc/node.md, "Obstacles"):
/// {name, shape (plane | box | sphere | capsule), half_extents [m] (box), radius [m] (sphere,
///  capsule), half_length [m] (capsule), friction [-], position [m], rpy [rad], attached_frame}.
/// `position` and `rpy` (R = Rz(yaw) Ry(pitch) Rx(roll), as scripts/static_frame) place the
/// obstacle's frame in frame_id, or in `attached_frame` when given. Throws ParameterError naming
/// the key, its value and what is allowed (a key that the shape has no use for is unknown).
ObstacleSpec loadObstacleSpec(const ParamValue& obstacle);

/// The rotation R = Rz(yaw) Ry(pitch) Rx(roll) of `rpy` = [roll, pitch, yaw] [rad].
Eigen::Quaterniond rotationFromRpy(const Eigen::Vector3d& rpy);

}  // namespace ros_layer
}  // namespace yarn_tearing
