#pragma once

#include <nodelet/nodelet.h>
#include <ros/callback_queue.h>

#include <memory>
#include <thread>

#include "yarn_tearing/ros/yarn_tearing_node.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// The simulator as a nodelet (`yarn_tearing/YarnTearingNodelet`): the same YarnTearingNode as
/// yarn_tearing_node, with the same parameters, topics and services (in the nodelet's namespace
/// and private namespace). Its stepping loop runs on a thread of its own with its own callback
/// queue, so it never blocks the manager's threads. An invalid configuration is reported with
/// NODELET_FATAL naming the parameter; the nodelet then stays idle (a manager cannot exit for it).
class YarnTearingNodelet : public nodelet::Nodelet {
 public:
  /// Stops the stepping loop and waits for its thread.
  ~YarnTearingNodelet() override;

 private:
  void onInit() override;

  ros::CallbackQueue queue_;  ///< topics, services and timers of the simulator
  std::unique_ptr<YarnTearingNode> node_;
  std::thread loop_;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
