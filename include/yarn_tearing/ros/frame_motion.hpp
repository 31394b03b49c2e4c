#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace yarn_tearing {
namespace ros_layer {

/// How a tf frame moves, from its latest sample and the one a velocity window before it: the pose
/// of that latest sample and the frame's linear and angular velocity over the window. Free of ROS;
/// times are plain seconds of ROS time.
struct FrameMotion {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();      ///< at `time` [m]
  double time = 0.0;                                           ///< stamp of `pose` [s]
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          ///< of the origin [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< in the fixed frame [rad/s]
  /// False for a static frame (stamped 0 by tf2) or one with a single sample: it stays at `pose`.
  bool moving = false;

  /// The motion from pose `earlier` at `earlier_time` [s] to pose `latest` at `latest_time` [s]
  /// (later than `earlier_time`): constant velocities between the two.
  static FrameMotion between(const Eigen::Isometry3d& earlier, double earlier_time,
                             const Eigen::Isometry3d& latest, double latest_time);
  /// A frame that stays at `pose` [m].
  static FrameMotion still(const Eigen::Isometry3d& pose);

  /// The pose at `time` [s] when `time` is after the latest sample: extrapolated at the velocities
  /// for at most `max_ahead` [s] >= 0 past it, then held; `pose` for any earlier time (those are
  /// tf2's to interpolate) and for a frame that is not moving.
  Eigen::Isometry3d extrapolated(double time, double max_ahead) const;
};

/// What takes a followed pose continuously from where it was to where a newer estimate puts it:
/// at `start` [s] the whole difference between the two, shrinking linearly to none `span` [s]
/// later. A follower whose frame's new sample shows it moved otherwise than extrapolated so
/// reaches the new estimate at the estimate's velocity plus at most difference / span, and never
/// jumps.
struct PoseCorrection {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();         ///< was - estimate at `start` [m]
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< was * estimate^-1 at start
  double start = 0.0;                                            ///< [s]
  double span = 0.0;                                             ///< [s] >= 0; 0 = none

  /// The correction from `estimate` back to `was`, both at `start` [s], fading over `span` [s].
  static PoseCorrection between(const Eigen::Isometry3d& was, const Eigen::Isometry3d& estimate,
                                double start, double span);
  /// `estimate` at `time` [s] corrected: `was` at `start`, `estimate` from start + span on.
  Eigen::Isometry3d applied(const Eigen::Isometry3d& estimate, double time) const;
};

/// `value` changing at `rate` [value/s] from simulated time `start` [s] until `end` [s] (>= start;
/// infinity: no end), evaluated at simulated time `time` [s]: value + rate * clamp(min(time, end)
/// - start, 0, max_span), with `max_span` [s] bounding the product for far times.
Eigen::Vector3d rampedValue(const Eigen::Vector3d& value, const Eigen::Vector3d& rate, double start,
                            double end, double time, double max_span);

}  // namespace ros_layer
}  // namespace yarn_tearing
