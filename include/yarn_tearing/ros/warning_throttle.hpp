#pragma once

#include <map>
#include <string>

namespace yarn_tearing {
namespace ros_layer {

/// Throttles warnings per distinct text: each different reason is reported at once, repeats of
/// the same text at most once per period. (ROS_WARN_THROTTLE throttles per call site, which would
/// hide every reason but the first.) Free of ROS; times are plain seconds.
class WarningThrottle {
 public:
  /// `period` [s] between two reports of the same text.
  explicit WarningThrottle(double period);

  /// True when `text` should be reported at `now` [s].
  bool shouldReport(const std::string& text, double now);

 private:
  static constexpr std::size_t kMaxTexts = 1000;  ///< forget all texts past this many

  double period_;
  std::map<std::string, double> last_report_;  ///< text -> time of its last report [s]
};

}  // namespace ros_layer
}  // namespace yarn_tearing
