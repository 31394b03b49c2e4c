#pragma once

namespace yarn_tearing {
namespace ros_layer {

/// A periodic deadline on any clock (wall or simulated seconds): due() is true once per period.
/// Missed periods are skipped rather than bunched. Free of ROS.
class RateSchedule {
 public:
  /// `rate` [Hz] > 0.
  explicit RateSchedule(double rate);

  /// The next deadline is `now` [s] (due at once).
  void restart(double now);
  /// The next deadline is one period after `now` [s] (a restart that must not publish at once).
  void restartAfterPeriod(double now);
  /// True when `now` [s] reached the deadline, which then moves on by one period.
  bool due(double now);
  /// Seconds from `now` until the deadline (0 when due).
  double secondsUntilDue(double now) const;

 private:
  double period_;      ///< [s]
  double next_ = 0.0;  ///< [s]
};

}  // namespace ros_layer
}  // namespace yarn_tearing
