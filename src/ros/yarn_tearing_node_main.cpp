#include <ros/ros.h>

#include <exception>
#include <memory>

#include "yarn_tearing/ros/simulation_config.hpp"
#include "yarn_tearing/ros/yarn_tearing_node.hpp"

namespace {
constexpr double kFlushDelay = 0.5;  ///< [s] lets a fatal message reach /rosout before exiting
}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "yarn_tearing_node");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  std::unique_ptr<yarn_tearing::ros_layer::YarnTearingNode> node;
  try {
    node = std::make_unique<yarn_tearing::ros_layer::YarnTearingNode>(
        nh, private_nh, yarn_tearing::ros_layer::loadSimulationConfig(private_nh));
  } catch (const std::exception& e) {
    ROS_FATAL("yarn_tearing_node: invalid configuration: %s", e.what());
    ros::WallDuration(kFlushDelay).sleep();
    return 1;
  }
  try {
    node->run();
  } catch (const std::exception& e) {
    ROS_FATAL("yarn_tearing_node: simulation stopped: %s", e.what());
    ros::WallDuration(kFlushDelay).sleep();
    return 2;
  }
  return 0;
}
