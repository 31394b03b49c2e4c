#include "yarn_tearing/ros/step_scheduler.hpp"

#include <algorithm>
#include <cmath>

namespace yarn_tearing {
namespace ros_layer {
namespace {

/// Fraction of a step by which simulated time may fall short of a step boundary and still count
/// as there (absorbs the rounding of summed time steps).
constexpr double kStepSlack = 1.0e-6;

}  // namespace

StepScheduler::StepScheduler(double time_step, double real_time_factor, double max_lag)
    : time_step_(time_step), real_time_factor_(real_time_factor), max_lag_(max_lag) {}

void StepScheduler::restart(double wall_now, double sim_time) {
  anchor_wall_ = wall_now;
  anchor_sim_ = sim_time;
}

double StepScheduler::targetTime(double wall_now) const {
  return anchor_sim_ + (wall_now - anchor_wall_) * real_time_factor_;
}

double StepScheduler::lag(double wall_now, double sim_time) const {
  return asFastAsPossible() ? 0.0 : std::max(0.0, targetTime(wall_now) - sim_time);
}

std::uint64_t StepScheduler::stepsDue(double wall_now, double sim_time) {
  if (asFastAsPossible()) {
    return 0;
  }
  const double max_backlog = max_lag_ * real_time_factor_;  // [s] simulated
  const double backlog = targetTime(wall_now) - sim_time;
  if (backlog > max_backlog + time_step_) {
    dropped_steps_ += static_cast<std::uint64_t>((backlog - max_backlog) / time_step_);
    restart(wall_now, sim_time + max_backlog);
  }
  const double steps = std::floor((targetTime(wall_now) - sim_time) / time_step_ + kStepSlack);
  return steps > 0.0 ? static_cast<std::uint64_t>(steps) : 0;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
