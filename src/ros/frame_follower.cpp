#include "yarn_tearing/ros/frame_follower.hpp"

#include <algorithm>

#include "yarn_tearing/ros/input_rejected.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

/// A difference is taken up over this many times the span it can have built up in (how far the
/// follower ran past the frame's latest sample, plus the velocity window): the follower then moves
/// at most a tenth of the frame's change of velocity faster than the frame.
constexpr double kCatchUp = 10.0;

}  // namespace

FrameFollower::FrameFollower(std::string frame, const FrameMotion& motion)
    : frame_(std::move(frame)), motion_(motion), pose_(motion.pose) {}

void FrameFollower::refresh(const FrameTransformer& frames) {
  FrameMotion motion;
  try {
    motion = frames.motionOf(frame_);
  } catch (const InputRejected&) {
    hold();
    throw;
  }
  follow(frames, motion);
}

void FrameFollower::hold() {
  motion_ = FrameMotion::still(pose_);
  correction_ = PoseCorrection();
}

void FrameFollower::follow(const FrameTransformer& frames, const FrameMotion& motion) {
  if (stamp_ < 0.0) {
    pose_ = motion.pose;
  } else {
    const Eigen::Isometry3d estimate = frames.poseAt(frame_, motion, ros::Time(stamp_));
    const double ahead = std::clamp(stamp_ - motion_.time, 0.0, frames.maxExtrapolation()) +
                         FrameTransformer::kVelocityWindow;
    // never faster than the difference still being taken up was: its rate stays bounded
    const double remaining = correction_.start + correction_.span - stamp_;
    const double span = std::max({frames.maxExtrapolation(), kCatchUp * ahead, remaining});
    correction_ = PoseCorrection::between(pose_, estimate, stamp_, span);
  }
  motion_ = motion;
}

const Eigen::Isometry3d& FrameFollower::poseAt(const FrameTransformer& frames,
                                               const ros::Time& stamp) {
  stamp_ = stamp.toSec();
  pose_ = correction_.applied(frames.poseAt(frame_, motion_, stamp), stamp_);
  return pose_;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
