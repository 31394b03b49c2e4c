#pragma once

#include <string>

namespace yarn_tearing {
namespace ros_layer {

/// Settings of the ROS node itself (not of the physics).
struct NodeSettings {
  /// Frame of all published positions and vectors, and of forces with an empty frame_id.
  std::string frame_id = "world";
  /// Simulated seconds per wall second [-]; 0 = as fast as possible.
  double real_time_factor = 1.0;
  /// Rate of yarn_states and yarn_markers [Hz]: per wall second when real_time_factor > 0 and
  /// publish_clock is false, per simulated second otherwise.
  double publish_rate = 30.0;
  /// Publish rosgraph_msgs/Clock on /clock from the simulated time.
  bool publish_clock = false;
  /// Largest backlog the stepping loop catches up on [s of wall time]; older backlog is dropped
  /// (the simulation then runs slower than real_time_factor instead of spiralling).
  double max_lag = 0.25;
  /// Smallest drawn width of yarn segments in yarn_markers [m] (real yarns are thinner).
  double marker_width = 0.002;
  /// A tf frame whose latest transform is older than this [s, ROS time] is stale: refused as a
  /// force's frame or a new grasp's target; a grasp whose frame goes stale holds its last target
  /// and is reported once. 0 = never stale.
  double frame_timeout = 1.0;
  /// Longest time past a tf frame's latest sample that a grasp target or an attached obstacle is
  /// extrapolated at the frame's velocity [s, ROS time]; then it holds until the next sample. In
  /// [0, 10]; 0 = never extrapolated.
  double max_extrapolation = 0.1;

  /// True when publish_rate counts simulated seconds.
  bool publishesInSimulatedTime() const { return real_time_factor == 0.0 || publish_clock; }
};

}  // namespace ros_layer
}  // namespace yarn_tearing
