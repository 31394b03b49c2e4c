#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>
#include <tf2_ros/buffer.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

namespace yarn_tearing {
namespace ros_layer {

/// Expresses vectors and frame origins from tf2 in the simulation's frame, refusing frames that
/// are unknown, stale or placed past the bounds of input_bounds.hpp.
class FrameTransformer {
 public:
  /// `buffer` must outlive this object; `fixed_frame` is the node's frame_id; a frame whose latest
  /// transform is older than `frame_timeout` [s] (ROS time) is stale, 0 = never (static frames,
  /// stamped 0 by tf2, never are).
  FrameTransformer(const tf2_ros::Buffer& buffer, std::string fixed_frame, double frame_timeout);

  const std::string& fixedFrame() const { return fixed_frame_; }

  /// `vector` given in `frame` rotated into the fixed frame (rotation only, no translation) at
  /// `stamp` (zero = latest, which must not be stale). An empty `frame` or the fixed frame itself
  /// returns `vector`. Throws InputRejected when the frame cannot be resolved or is stale.
  Eigen::Vector3d rotateToFixedFrame(const Eigen::Vector3d& vector, const std::string& frame,
                                     const ros::Time& stamp) const;

  /// Origin of `frame` in the fixed frame [m] at the latest available time. Throws InputRejected
  /// when the frame is unknown or stale, or its origin is not finite or farther than
  /// input_bounds::kMaxDistance from the fixed frame's.
  Eigen::Vector3d originInFixedFrame(const std::string& frame) const;

  /// Pose of `frame` in the fixed frame [m] at the latest available time (identity for the fixed
  /// frame). Throws InputRejected as originInFixedFrame(), or when the rotation is not finite.
  Eigen::Isometry3d poseInFixedFrame(const std::string& frame) const;

 private:
  /// tf2's transform from `frame` to the fixed frame at `stamp`; InputRejected on failure, or
  /// when `stamp` is zero and the latest transform is stale.
  geometry_msgs::TransformStamped lookup(const std::string& frame, const ros::Time& stamp) const;

  const tf2_ros::Buffer& buffer_;
  std::string fixed_frame_;
  double frame_timeout_;  ///< [s], 0 = never stale
};

}  // namespace ros_layer
}  // namespace yarn_tearing
