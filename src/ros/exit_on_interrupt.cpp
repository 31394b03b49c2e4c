#include "yarn_tearing/ros/exit_on_interrupt.hpp"

#include <ros/ros.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>

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

volatile std::sig_atomic_t g_signal = 0;  ///< the signal that asked for the shutdown
struct itimerval g_deadline {};           ///< from it to the forced exit (one shot)

extern "C" void requestShutdownBeforeDeadline(int signal) {
  // ros::requestShutdown() only sets roscpp's flag (its own SIGINT handler calls it the same way);
  // setitimer(2) is one system call.
  if (g_signal == 0) {
    g_signal = signal;
    setitimer(ITIMER_REAL, &g_deadline, nullptr);
  }
  ros::requestShutdown();
}

extern "C" void exitAtDeadline(int /*alarm*/) {
  static const char kMessage[] =
      "yarn_tearing_node: a step outlasted the shutdown deadline after a signal; exiting\n";
  const ssize_t written = write(STDERR_FILENO, kMessage, sizeof(kMessage) - 1);
  static_cast<void>(written);
  _exit(128 + g_signal);
}

void install(int signal, void (*handler)(int), struct sigaction* previous) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  sigaction(signal, &action, previous);
}

}  // namespace

ExitOnInterrupt::ExitOnInterrupt() {
  install(SIGINT, exitAtOnce, &previous_interrupt_);
  install(SIGTERM, exitAtOnce, &previous_terminate_);
}

ExitOnInterrupt::~ExitOnInterrupt() {
  sigaction(SIGINT, &previous_interrupt_, nullptr);
  sigaction(SIGTERM, &previous_terminate_, nullptr);
}

ShutdownOnInterrupt::ShutdownOnInterrupt(double deadline) {
  g_signal = 0;
  const auto microseconds = static_cast<long>(std::max(deadline, 1.0e-3) * 1.0e6);
  g_deadline = {};
  g_deadline.it_value.tv_sec = microseconds / 1000000;
  g_deadline.it_value.tv_usec = microseconds % 1000000;
  install(SIGALRM, exitAtDeadline, &previous_alarm_);
  install(SIGINT, requestShutdownBeforeDeadline, &previous_interrupt_);
  install(SIGTERM, requestShutdownBeforeDeadline, &previous_terminate_);
}

ShutdownOnInterrupt::~ShutdownOnInterrupt() {
  sigaction(SIGINT, &previous_interrupt_, nullptr);
  sigaction(SIGTERM, &previous_terminate_, nullptr);
  const struct itimerval cancel {};
  setitimer(ITIMER_REAL, &cancel, nullptr);
  sigaction(SIGALRM, &previous_alarm_, nullptr);
}

}  // namespace ros_layer
}  // namespace yarn_tearing
