#pragma once

#include <ros/time.h>

#include <Eigen/Geometry>
#include <string>

#include "yarn_tearing/ros/frame_motion.hpp"
#include "yarn_tearing/ros/frame_transformer.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Something that follows a tf frame at each step's time: a grasp target, an attached obstacle.
/// Once per stepping cycle refresh() looks up how the frame moves (FrameTransformer::motionOf());
/// before each step poseAt() gives the frame's pose at the step's end (FrameTransformer::poseAt():
/// interpolated between its samples, extrapolated at most max_extrapolation past the latest).
/// When a new sample shows the frame moved otherwise than extrapolated, the difference is taken
/// up smoothly (PoseCorrection) over at least max_extrapolation, at least ten times the span it
/// built up in (how far the follower was past the latest sample, plus the velocity window) and at
/// least what is left of the difference still being taken up, so the
/// follower never jumps and moves at most a tenth of the frame's change of velocity faster than
/// the frame (a frame that starts at 5 cm/s: its follower at most 5.5 cm/s).
class FrameFollower {
 public:
  FrameFollower() = default;
  /// Follows `frame`, which moves as `motion` (from FrameTransformer::motionOf()); starts at its
  /// latest sample.
  FrameFollower(std::string frame, const FrameMotion& motion);

  const std::string& frame() const { return frame_; }
  /// How the frame moves, as last looked up.
  const FrameMotion& motion() const { return motion_; }
  /// Pose of the frame at the last step [m] (before the first: its latest sample when followed).
  const Eigen::Isometry3d& pose() const { return pose_; }

  /// Looks up how the frame moves now and follows that (follow()). Throws InputRejected when it
  /// cannot (FrameTransformer::motionOf()); the follower then holds (hold()).
  void refresh(const FrameTransformer& frames);
  /// Follows the frame as it moves now, `motion` (from FrameTransformer::motionOf()), taking up
  /// the difference to where the follower was as the class says.
  void follow(const FrameTransformer& frames, const FrameMotion& motion);
  /// Stands still where the frame was at the last step (its lookup failed).
  void hold();
  /// True when the frame moves and `stamp` is more than max_extrapolation past its latest sample:
  /// the follower would stand still there until a newer sample comes.
  bool outruns(const FrameTransformer& frames, const ros::Time& stamp) const {
    return motion_.moving && stamp.toSec() - motion_.time > frames.maxExtrapolation();
  }
  /// Pose of the frame at `stamp` (the ROS time of a step's end) [m]; remembered as pose().
  /// Never throws.
  const Eigen::Isometry3d& poseAt(const FrameTransformer& frames, const ros::Time& stamp);

 private:
  std::string frame_;
  FrameMotion motion_;
  PoseCorrection correction_;
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
  double stamp_ = -1.0;  ///< [s] ROS time of pose_; negative before the first step
};

}  // namespace ros_layer
}  // namespace yarn_tearing
