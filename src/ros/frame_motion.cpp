#include "yarn_tearing/ros/frame_motion.hpp"

#include <algorithm>

namespace yarn_tearing {
namespace ros_layer {

FrameMotion FrameMotion::between(const Eigen::Isometry3d& earlier, double earlier_time,
                                 const Eigen::Isometry3d& latest, double latest_time) {
  FrameMotion motion = still(latest);
  motion.time = latest_time;
  const double span = latest_time - earlier_time;
  if (!(span > 0.0)) {
    return motion;
  }
  motion.velocity = (latest.translation() - earlier.translation()) / span;
  // The rotation from the earlier orientation to the latest, in the fixed frame.
  const Eigen::AngleAxisd turn(Eigen::Quaterniond(latest.linear() * earlier.linear().transpose()));
  motion.angular_velocity = turn.axis() * (turn.angle() / span);
  motion.moving = motion.velocity.allFinite() && motion.angular_velocity.allFinite();
  if (!motion.moving) {
    motion.velocity.setZero();
    motion.angular_velocity.setZero();
  }
  return motion;
}

FrameMotion FrameMotion::still(const Eigen::Isometry3d& pose) {
  FrameMotion motion;
  motion.pose = pose;
  return motion;
}

Eigen::Isometry3d FrameMotion::extrapolated(double time, double max_ahead) const {
  const double ahead = std::min(time - this->time, max_ahead);
  if (!moving || !(ahead > 0.0)) {
    return pose;
  }
  Eigen::Isometry3d result = pose;
  result.translation() += velocity * ahead;
  const double angle = angular_velocity.norm() * ahead;
  if (angle > 0.0) {
    result.linear() =
        Eigen::AngleAxisd(angle, angular_velocity.normalized()).toRotationMatrix() * pose.linear();
  }
  return result;
}

PoseCorrection PoseCorrection::between(const Eigen::Isometry3d& was,
                                       const Eigen::Isometry3d& estimate, double start,
                                       double span) {
  PoseCorrection correction;
  correction.translation = was.translation() - estimate.translation();
  correction.rotation = Eigen::Quaterniond(was.linear() * estimate.linear().transpose());
  correction.rotation.normalize();
  correction.start = start;
  correction.span = span;
  return correction;
}

Eigen::Isometry3d PoseCorrection::applied(const Eigen::Isometry3d& estimate, double time) const {
  const double remaining = span > 0.0 ? std::clamp(1.0 - (time - start) / span, 0.0, 1.0) : 0.0;
  if (!(remaining > 0.0)) {
    return estimate;
  }
  Eigen::Isometry3d pose = estimate;
  pose.translation() += remaining * translation;
  pose.linear() = (Eigen::Quaterniond::Identity().slerp(remaining, rotation) *
                   Eigen::Quaterniond(estimate.linear()))
                      .normalized()
                      .toRotationMatrix();
  return pose;
}

Eigen::Vector3d rampedValue(const Eigen::Vector3d& value, const Eigen::Vector3d& rate, double start,
                            double end, double time, double max_span) {
  const double elapsed = std::clamp(std::min(time, end) - start, 0.0, max_span);
  return value + elapsed * rate;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
