#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace yarn_tearing {
namespace ros_layer {

/// The period of the node's throttled warnings [s]: at most one report per reason in it.
constexpr double kWarnPeriod = 2.0;

/// Throttles warnings per reason from a fixed set of `num_keys` (e.g. topic x RefusalReason):
/// the first of each key is reported at once, then at most one per period, with the count of
/// the ones held back in between. Memory is fixed however many different messages arrive
/// (ROS_WARN_THROTTLE throttles per call site, which would hide every reason but the first).
/// Free of ROS; times are plain seconds.
class WarningThrottle {
 public:
  /// `period` [s] between two reports of the same key; keys are 0 .. num_keys - 1.
  WarningThrottle(double period, std::size_t num_keys);

  /// True when a warning of `key` should be reported at `now` [s]; otherwise counts it as held
  /// back. Keys past num_keys share the last one.
  bool shouldReport(std::size_t key, double now);
  /// Warnings of `key` held back before the one just reported (valid right after shouldReport()
  /// returned true).
  std::uint64_t heldBack(std::size_t key) const;

 private:
  std::size_t index(std::size_t key) const;

  double period_;
  std::vector<double> last_report_;       ///< per key: time of its last report [s] (-inf)
  std::vector<std::uint64_t> held_back_;  ///< per key: held back since that report
  std::vector<std::uint64_t> last_held_;  ///< per key: held back before that report
};

}  // namespace ros_layer
}  // namespace yarn_tearing
