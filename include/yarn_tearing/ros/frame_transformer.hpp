#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>
#include <tf2_ros/buffer.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

#include "yarn_tearing/ros/frame_motion.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Expresses vectors and frame origins from tf2 in the simulation's frame, refusing frames that
/// are unknown, stale or placed past the bounds of input_bounds.hpp. Every exception of tf2 and of
/// ROS time arithmetic (a stamp past ROS time's range) becomes an InputRejected.
class FrameTransformer {
 public:
  /// Span [s, ROS time] before a frame's latest sample over which its velocity is measured
  /// (motionOf()): tf2 interpolates the pose at its start between the samples it holds.
  static constexpr double kVelocityWindow = 0.02;

  /// `buffer` must outlive this object; `fixed_frame` is the node's frame_id; a frame whose latest
  /// transform is older than `frame_timeout` [s] (ROS time) is stale, 0 = never (static frames,
  /// stamped 0 by tf2, never are); poseAt() extrapolates a frame at most `max_extrapolation` [s]
  /// past its latest sample.
  FrameTransformer(const tf2_ros::Buffer& buffer, std::string fixed_frame, double frame_timeout,
                   double max_extrapolation);

  const std::string& fixedFrame() const { return fixed_frame_; }
  /// Longest extrapolation past a frame's latest sample [s] (~max_extrapolation).
  double maxExtrapolation() const { return max_extrapolation_; }

  /// `vector` given in `frame` rotated into the fixed frame (rotation only, no translation) at
  /// `stamp` (zero = latest, which must not be stale). An empty `frame` or the fixed frame itself
  /// returns `vector`. Throws InputRejected when the frame cannot be resolved or is stale.
  Eigen::Vector3d rotateToFixedFrame(const Eigen::Vector3d& vector, const std::string& frame,
                                     const ros::Time& stamp) const;

  /// How `frame` moves in the fixed frame: its latest sample (which must not be stale) and its
  /// velocities over the kVelocityWindow before it; a static frame, the fixed frame and a frame
  /// with a single sample stand still. Throws InputRejected when the frame is unknown or stale, or
  /// its latest origin is not finite or farther than input_bounds::kMaxDistance from the fixed
  /// frame's, or its rotation is not finite.
  FrameMotion motionOf(const std::string& frame) const;

  /// Pose of `frame` in the fixed frame [m] at `stamp` (ROS time), given its `motion` from
  /// motionOf(): up to the latest sample tf2's interpolation between the samples it holds, after it
  /// the latest sample extrapolated at the frame's velocities for at most max_extrapolation, then
  /// held. Never throws: a stamp tf2 cannot resolve (older than its cache) gets the latest sample.
  Eigen::Isometry3d poseAt(const std::string& frame, const FrameMotion& motion,
                           const ros::Time& stamp) const;

 private:
  /// tf2's transform from `frame` to the fixed frame at `stamp`; InputRejected on failure, or
  /// when `stamp` is zero and the latest transform is stale.
  geometry_msgs::TransformStamped lookup(const std::string& frame, const ros::Time& stamp) const;

  const tf2_ros::Buffer& buffer_;
  std::string fixed_frame_;
  double frame_timeout_;      ///< [s], 0 = never stale
  double max_extrapolation_;  ///< [s] >= 0
};

}  // namespace ros_layer
}  // namespace yarn_tearing
