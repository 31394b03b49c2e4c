#include "yarn_tearing/ros/break_event_log.hpp"

#include <algorithm>

namespace yarn_tearing {
namespace ros_layer {

BreakEventLog::BreakEventLog(std::size_t capacity)
    : capacity_(std::max<std::size_t>(capacity, 1)) {}

void BreakEventLog::record(BreakEvent& event) {
  event.index = total_++;
  if (events_.size() == capacity_) events_.pop_front();
  events_.push_back(event);
}

std::uint32_t BreakEventLog::oldest() const {
  return total_ - static_cast<std::uint32_t>(events_.size());
}

std::vector<BreakEvent> BreakEventLog::since(std::uint32_t first) const {
  const std::uint32_t from = std::max(first, oldest());
  if (from >= total_) return {};
  return std::vector<BreakEvent>(events_.begin() + (from - oldest()), events_.end());
}

void BreakEventLog::clear() {
  events_.clear();
  total_ = 0;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
