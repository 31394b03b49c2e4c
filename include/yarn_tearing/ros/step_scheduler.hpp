#pragma once

#include <cstdint>

namespace yarn_tearing {
namespace ros_layer {

/// Paces physics steps so that simulated time follows wall time times the real-time factor.
///
/// Wall time and simulated time are anchored together; stepsDue() returns how many steps of
/// `time_step` bring the simulation up to anchor_sim + (wall - anchor_wall) * factor. A backlog of
/// more than `max_lag` wall seconds is dropped (re-anchored), so a simulation slower than real time
/// runs as fast as it can instead of spiralling. Free of ROS; times are plain seconds.
class StepScheduler {
 public:
  /// `time_step` [s] > 0, `real_time_factor` [-] >= 0 (0 = as fast as possible), `max_lag` [s] > 0.
  StepScheduler(double time_step, double real_time_factor, double max_lag);

  /// True when the factor is 0: every cycle steps for as long as its wall budget allows.
  bool asFastAsPossible() const { return real_time_factor_ == 0.0; }

  /// Changes the real-time factor [-] >= 0 (live tuning); call restart() afterwards.
  void setRealTimeFactor(double real_time_factor) { real_time_factor_ = real_time_factor; }

  /// Anchors simulated time `sim_time` [s] to wall time `wall_now` [s] (start, reset, resume).
  void restart(double wall_now, double sim_time);

  /// Steps due at `wall_now` [s] when the simulation is at `sim_time` [s]; 0 when as fast as
  /// possible (use a wall budget instead).
  std::uint64_t stepsDue(double wall_now, double sim_time);

  /// Wall time [s] at which the schedule reaches simulated time `sim_time` [s] (paced only).
  double wallTimeOf(double sim_time) const {
    return anchor_wall_ + (sim_time - anchor_sim_) / real_time_factor_;
  }

  /// Simulated time [s] the simulation at `sim_time` [s] is behind the schedule at `wall_now` [s]
  /// (0 when on time or as fast as possible).
  double lag(double wall_now, double sim_time) const;

  /// Steps dropped so far because the backlog exceeded max_lag.
  std::uint64_t droppedSteps() const { return dropped_steps_; }

 private:
  double targetTime(double wall_now) const;

  double time_step_;
  double real_time_factor_;
  double max_lag_;
  double anchor_wall_ = 0.0;  ///< [s]
  double anchor_sim_ = 0.0;   ///< [s]
  std::uint64_t dropped_steps_ = 0;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
