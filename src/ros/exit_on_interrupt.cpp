#include "yarn_tearing/ros/exit_on_interrupt.hpp"

#include <unistd.h>

namespace yarn_tearing {
namespace ros_layer {
namespace {

extern "C" void exitAtOnce(int signal) {
  // Only async-signal-safe calls here: write(2) and _exit(2).
  static const char kMessage[] = "yarn_tearing_node: interrupted while starting; exiting\n";
  const ssize_t written = write(STDERR_FILENO, kMessage, sizeof(kMessage) - 1);
  static_cast<void>(written);
  _exit(128 + signal);
}

}  // namespace

ExitOnInterrupt::ExitOnInterrupt() {
  struct sigaction action {};
  action.sa_handler = exitAtOnce;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previous_interrupt_);
  sigaction(SIGTERM, &action, &previous_terminate_);
}

ExitOnInterrupt::~ExitOnInterrupt() {
  sigaction(SIGINT, &previous_interrupt_, nullptr);
  sigaction(SIGTERM, &previous_terminate_, nullptr);
}

}  // namespace ros_layer
}  // namespace yarn_tearing
