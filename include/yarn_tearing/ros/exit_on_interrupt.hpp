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

/// While alive, SIGINT and SIGTERM ask the node to shut down (ros::requestShutdown(), as roscpp's
/// own SIGINT handler does) and, should it still be running `deadline` [s] later
/// (a step that costs more than that checks no ROS flag), end the process then with status
/// 128 + the signal and one line on stderr. A node stepping normally ends within one stepping
/// cycle, and the exit falls back to the deadline only inside a step that long. The handlers
/// found at construction are restored, and a pending deadline cancelled, on destruction.
class ShutdownOnInterrupt {
 public:
  explicit ShutdownOnInterrupt(double deadline);
  ~ShutdownOnInterrupt();
  ShutdownOnInterrupt(const ShutdownOnInterrupt&) = delete;
  ShutdownOnInterrupt& operator=(const ShutdownOnInterrupt&) = delete;

 private:
  struct sigaction previous_interrupt_ {};  ///< SIGINT handler before construction
  struct sigaction previous_terminate_ {};  ///< SIGTERM handler before construction
  struct sigaction previous_alarm_ {};      ///< SIGALRM handler before construction
};

}  // namespace ros_layer
}  // namespace yarn_tearing
