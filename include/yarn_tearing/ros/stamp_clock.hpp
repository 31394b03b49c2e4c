#pragma once

#include <ros/time.h>

#include "yarn_tearing/ros/step_scheduler.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// The stamps of published messages: the ROS time at which a simulated instant happens.
///
/// - /use_sim_time set and this node publishing /clock: the simulated time is ROS time, so the
///   stamp of simulated instant t is t.
/// - otherwise, paced (real_time_factor > 0): the ROS time at which the scheduler runs that
/// instant,
///   start time + t / real_time_factor (re-anchored on reset, resume and dropped backlog, so stamps
///   keep up with ROS time and never go back).
/// - otherwise, as fast as possible: the ROS time at which the message is built.
/// The simulated time itself travels in the messages' sim_time fields.
class StampClock {
 public:
  /// `simulated_time_is_ros_time`: /use_sim_time is set and this node publishes /clock.
  explicit StampClock(bool simulated_time_is_ros_time);

  /// Reads the offset between ROS time `ros_now` and the scheduler's wall clock `wall_now` [s],
  /// both taken at the same moment; kept until the next call (start, reset, resume).
  void synchronize(const ros::Time& ros_now, double wall_now);

  /// Stamp of simulated instant `sim_time` [s] paced by `scheduler`; `ros_now` is the current ROS
  /// time (used when as fast as possible).
  ros::Time stamp(double sim_time, const StepScheduler& scheduler, const ros::Time& ros_now) const;

 private:
  bool simulated_time_is_ros_time_;
  double ros_minus_wall_ = 0.0;  ///< [s] ROS time minus the scheduler's wall time
};

}  // namespace ros_layer
}  // namespace yarn_tearing
