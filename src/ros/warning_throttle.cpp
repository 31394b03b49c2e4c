#include "yarn_tearing/ros/warning_throttle.hpp"

#include <algorithm>
#include <limits>

namespace yarn_tearing {
namespace ros_layer {

WarningThrottle::WarningThrottle(double period, std::size_t num_keys)
    : period_(period),
      last_report_(std::max<std::size_t>(num_keys, 1), -std::numeric_limits<double>::infinity()),
      held_back_(last_report_.size(), 0),
      last_held_(last_report_.size(), 0) {}

std::size_t WarningThrottle::index(std::size_t key) const {
  return std::min(key, last_report_.size() - 1);
}

bool WarningThrottle::shouldReport(std::size_t key, double now) {
  const std::size_t i = index(key);
  if (now - last_report_[i] < period_) {
    ++held_back_[i];
    return false;
  }
  last_report_[i] = now;
  last_held_[i] = held_back_[i];
  held_back_[i] = 0;
  return true;
}

std::uint64_t WarningThrottle::heldBack(std::size_t key) const { return last_held_[index(key)]; }

}  // namespace ros_layer
}  // namespace yarn_tearing
