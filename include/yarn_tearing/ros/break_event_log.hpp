#pragma once

#include <yarn_tearing/BreakEvent.h>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

namespace yarn_tearing {
namespace ros_layer {

/// The break events published since the node started or since its last ~reset, numbered in the
/// order they were published (BreakEvent::index), so that a consumer that lost some (a subscriber
/// queue too short for a burst, a late start) can fetch them (~get_break_events). Each edge tears
/// at most once between resets, so a capacity of at least the scene's edge count keeps them all;
/// beyond it (a yarn restored after a non-finite step can tear again) the oldest are dropped.
class BreakEventLog {
 public:
  /// Keeps at most `capacity` (>= 1) events [-].
  explicit BreakEventLog(std::size_t capacity);

  /// Numbers `event` (sets its index) and keeps a copy.
  void record(BreakEvent& event);
  /// The events numbered `first` and later that are still kept, oldest first.
  std::vector<BreakEvent> since(std::uint32_t first) const;
  /// Index of the oldest event kept [-] (== total() when none is).
  std::uint32_t oldest() const;
  /// Breaks recorded since construction or the last clear(): the next break's index [-].
  std::uint32_t total() const { return total_; }
  /// Forgets every event (~reset); numbering starts again at 0.
  void clear();

 private:
  std::size_t capacity_;
  std::deque<BreakEvent> events_;
  std::uint32_t total_ = 0;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
