#pragma once

#include <ros/callback_queue.h>
#include <ros/node_handle.h>
#include <ros/spinner.h>

#include <memory>

namespace yarn_tearing {
namespace ros_layer {

/// A callback queue served by a thread of its own. The node puts its services and a diagnostics
/// timer on it, so they answer while the stepping loop is inside a step, however long that step
/// takes; what they share with the loop is guarded by the node's mutex.
class ServiceThread {
 public:
  /// Callbacks registered through handle() go to this thread (once started).
  explicit ServiceThread(const ros::NodeHandle& nh);
  ~ServiceThread();
  ServiceThread(const ServiceThread&) = delete;
  ServiceThread& operator=(const ServiceThread&) = delete;

  /// A node handle in `nh`'s namespace whose callbacks run on this thread.
  ros::NodeHandle& handle() { return nh_; }
  /// Starts serving the queue.
  void start();
  /// Stops serving it (waits for a callback in progress); idempotent.
  void stop();

 private:
  ros::CallbackQueue queue_;
  ros::NodeHandle nh_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
