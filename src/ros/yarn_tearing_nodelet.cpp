#include "yarn_tearing/ros/yarn_tearing_nodelet.hpp"

#include <exception>
#include <pluginlib/class_list_macros.hpp>

#include "yarn_tearing/ros/simulation_config.hpp"

namespace yarn_tearing {
namespace ros_layer {

void YarnTearingNodelet::onInit() {
  ros::NodeHandle nh = getNodeHandle();
  ros::NodeHandle private_nh = getPrivateNodeHandle();
  nh.setCallbackQueue(&queue_);
  private_nh.setCallbackQueue(&queue_);
  try {
    node_ = std::make_unique<YarnTearingNode>(nh, private_nh, loadSimulationConfig(private_nh));
  } catch (const std::exception& e) {
    NODELET_FATAL("invalid configuration: %s", e.what());
    return;
  }
  loop_ = std::thread([this] {
    try {
      node_->run();
    } catch (const std::exception& e) {
      NODELET_FATAL("simulation stopped: %s", e.what());
    }
  });
}

YarnTearingNodelet::~YarnTearingNodelet() {
  if (node_) {
    node_->requestStop();
  }
  if (loop_.joinable()) {
    loop_.join();
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing

PLUGINLIB_EXPORT_CLASS(yarn_tearing::ros_layer::YarnTearingNodelet, nodelet::Nodelet)
