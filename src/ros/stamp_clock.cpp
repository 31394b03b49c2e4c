#include "yarn_tearing/ros/stamp_clock.hpp"

#include <algorithm>

namespace yarn_tearing {
namespace ros_layer {

StampClock::StampClock(bool simulated_time_is_ros_time)
    : simulated_time_is_ros_time_(simulated_time_is_ros_time) {}

void StampClock::synchronize(const ros::Time& ros_now, double wall_now) {
  ros_minus_wall_ = ros_now.toSec() - wall_now;
}

ros::Time StampClock::stamp(double sim_time, const StepScheduler& scheduler,
                            const ros::Time& ros_now) const {
  if (simulated_time_is_ros_time_) {
    return ros::Time(std::max(0.0, sim_time));
  }
  if (scheduler.asFastAsPossible()) {
    return ros_now;
  }
  return ros::Time(std::max(0.0, ros_minus_wall_ + scheduler.wallTimeOf(sim_time)));
}

}  // namespace ros_layer
}  // namespace yarn_tearing
