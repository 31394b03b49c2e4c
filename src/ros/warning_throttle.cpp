#include "yarn_tearing/ros/warning_throttle.hpp"

namespace yarn_tearing {
namespace ros_layer {

WarningThrottle::WarningThrottle(double period) : period_(period) {}

bool WarningThrottle::shouldReport(const std::string& text, double now) {
  const auto it = last_report_.find(text);
  if (it != last_report_.end() && now - it->second < period_) {
    return false;
  }
  if (last_report_.size() >= kMaxTexts) {
    last_report_.clear();
  }
  last_report_[text] = now;
  return true;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
