#pragma once

#include <csignal>

namespace yarn_tearing {
namespace ros_layer {

/// While alive, SIGINT and SIGTERM end the process at once, with status 128 + the signal (130,
/// 143) and one line on stderr. roscpp's own handler only asks the node to shut down at its next
/// check, and building a large scene (validated, then built: seconds for the scene budget)
/// checks nothing; nothing is published before it is done, so nothing is lost by leaving at
/// once. The handlers found at construction are restored on destruction.
class ExitOnInterrupt {
 public:
  ExitOnInterrupt();
  ~ExitOnInterrupt();
  ExitOnInterrupt(const ExitOnInterrupt&) = delete;
  ExitOnInterrupt& operator=(const ExitOnInterrupt&) = delete;

 private:
  struct sigaction previous_interrupt_ {};  ///< SIGINT handler before construction
  struct sigaction previous_terminate_ {};  ///< SIGTERM handler before construction
};

}  // namespace ros_layer
}  // namespace yarn_tearing
