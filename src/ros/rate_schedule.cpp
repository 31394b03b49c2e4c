#include "yarn_tearing/ros/rate_schedule.hpp"

#include <algorithm>

namespace yarn_tearing {
namespace ros_layer {
namespace {

/// Fraction of a period by which a deadline may be reached early (rounding of summed steps).
constexpr double kPeriodSlack = 1.0e-6;

}  // namespace

RateSchedule::RateSchedule(double rate) : period_(1.0 / rate) {}

void RateSchedule::restart(double now) { next_ = now; }

void RateSchedule::restartAfterPeriod(double now) { next_ = now + period_; }

bool RateSchedule::due(double now) {
  if (now < next_ - kPeriodSlack * period_) {
    return false;
  }
  next_ += period_;
  if (next_ <= now) {
    next_ = now + period_;
  }
  return true;
}

double RateSchedule::secondsUntilDue(double now) const { return std::max(0.0, next_ - now); }

}  // namespace ros_layer
}  // namespace yarn_tearing
