#include "yarn_tearing/ros/frame_transformer.hpp"

#include <tf2/exceptions.h>

#include <Eigen/Geometry>
#include <sstream>

#include "yarn_tearing/ros/clipped_text.hpp"
#include "yarn_tearing/ros/input_bounds.hpp"
#include "yarn_tearing/ros/input_rejected.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr std::size_t kMaxTfReason = 160;  ///< [characters] of tf2's exception text quoted

/// The unit quaternion of tf's `q` for `frame`; InputRejected (kNotFinite) when it has none.
Eigen::Quaterniond rotationOf(const std::string& frame, const geometry_msgs::Quaternion& q) {
  const Eigen::Quaterniond rotation(q.w, q.x, q.y, q.z);
  if (!rotation.coeffs().allFinite() || !(rotation.norm() > 0.0)) {
    throw InputRejected(RefusalReason::kNotFinite,
                        "frame '" + clipped(frame) + "' has no valid rotation");
  }
  return rotation.normalized();
}

/// tf's translation `t` of `frame` [m]; InputRejected unless finite and within
/// input_bounds::kMaxDistance of the fixed frame's origin.
Eigen::Vector3d boundedOrigin(const std::string& frame, const geometry_msgs::Vector3& t) {
  const Eigen::Vector3d origin(t.x, t.y, t.z);
  requireBoundedVector(origin, input_bounds::kMaxDistance,
                       "origin of frame '" + clipped(frame) + "'", "m");
  return origin;
}

/// tf's `transform` of `frame` as a pose; InputRejected as rotationOf() and boundedOrigin().
Eigen::Isometry3d poseOf(const std::string& frame, const geometry_msgs::Transform& transform) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotationOf(frame, transform.rotation).toRotationMatrix();
  pose.translation() = boundedOrigin(frame, transform.translation);
  return pose;
}

}  // namespace

FrameTransformer::FrameTransformer(const tf2_ros::Buffer& buffer, std::string fixed_frame,
                                   double frame_timeout, double max_extrapolation)
    : buffer_(buffer),
      fixed_frame_(std::move(fixed_frame)),
      frame_timeout_(frame_timeout),
      max_extrapolation_(max_extrapolation) {}

geometry_msgs::TransformStamped FrameTransformer::lookup(const std::string& frame,
                                                         const ros::Time& stamp) const {
  if (frame.size() > input_bounds::kMaxFrameName) {
    throw InputRejected(RefusalReason::kUnknownFrame,
                        "frame name '" + clipped(frame) + "' longer than " +
                            std::to_string(input_bounds::kMaxFrameName) + " characters");
  }
  geometry_msgs::TransformStamped transform;
  try {
    transform = buffer_.lookupTransform(fixed_frame_, frame, stamp);
  } catch (const tf2::TransformException& e) {
    throw InputRejected(RefusalReason::kUnknownFrame, "cannot look up frame '" + clipped(frame) +
                                                          "' in '" + fixed_frame_ +
                                                          "': " + clipped(e.what(), kMaxTfReason));
  } catch (const std::exception& e) {  // ROS time arithmetic on a stamp past its range
    throw InputRejected(RefusalReason::kTimeOutOfRange,
                        "cannot look up frame '" + clipped(frame) + "' in '" + fixed_frame_ +
                            "' at " + std::to_string(stamp.toSec()) +
                            " s: " + clipped(e.what(), kMaxTfReason));
  }
  const ros::Time updated = transform.header.stamp;
  if (stamp.isZero() && frame_timeout_ > 0.0 && !updated.isZero()) {
    // in seconds, not ros::Duration: a stamp far from now is out of a Duration's range
    const double age = ros::Time::now().toSec() - updated.toSec();
    if (age > frame_timeout_) {
      std::ostringstream text;
      text << "frame '" << clipped(frame) << "' last updated " << age << " s ago (frame_timeout "
           << frame_timeout_ << " s)";
      throw InputRejected(RefusalReason::kStaleFrame, text.str());
    }
  }
  return transform;
}

Eigen::Vector3d FrameTransformer::rotateToFixedFrame(const Eigen::Vector3d& vector,
                                                     const std::string& frame,
                                                     const ros::Time& stamp) const {
  if (frame.empty() || frame == fixed_frame_) {
    return vector;
  }
  return rotationOf(frame, lookup(frame, stamp).transform.rotation) * vector;
}

FrameMotion FrameTransformer::motionOf(const std::string& frame) const {
  if (frame == fixed_frame_) {
    return FrameMotion::still(Eigen::Isometry3d::Identity());
  }
  const geometry_msgs::TransformStamped latest = lookup(frame, ros::Time(0));
  FrameMotion motion = FrameMotion::still(poseOf(frame, latest.transform));
  const double latest_time = latest.header.stamp.toSec();
  motion.time = latest_time;
  if (latest.header.stamp.isZero() || latest_time <= kVelocityWindow) {
    return motion;  // static (or stamped at the very start of ROS time): stands still
  }
  try {
    const ros::Time earlier_stamp(latest_time - kVelocityWindow);
    const Eigen::Isometry3d earlier = poseOf(frame, lookup(frame, earlier_stamp).transform);
    return FrameMotion::between(earlier, earlier_stamp.toSec(), motion.pose, latest_time);
  } catch (const InputRejected&) {
    return motion;  // a single sample so far (nothing before it to measure a velocity over)
  }
}

Eigen::Isometry3d FrameTransformer::poseAt(const std::string& frame, const FrameMotion& motion,
                                           const ros::Time& stamp) const {
  const double time = stamp.toSec();
  if (!motion.moving) {
    return motion.pose;
  }
  if (time > motion.time) {
    return motion.extrapolated(time, max_extrapolation_);
  }
  try {
    return poseOf(frame, lookup(frame, stamp).transform);
  } catch (const InputRejected&) {
    return motion.pose;  // older than tf2's cache
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
