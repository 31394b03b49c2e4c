#include "yarn_tearing/ros/node_runner.hpp"

#include <ros/ros.h>

#include <exception>
#include <memory>

#include "yarn_tearing/ros/exit_on_interrupt.hpp"
#include "yarn_tearing/ros/simulation_config.hpp"
#include "yarn_tearing/ros/yarn_tearing_node.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {
constexpr double kFlushDelay = 0.5;  ///< [s] lets a fatal message reach /rosout before exiting
/// [s] from SIGINT or SIGTERM to the exit, whatever the step in progress costs (within 1 s).
constexpr double kShutdownDeadline = 0.8;
}  // namespace

int runYarnTearingNode(int argc, char** argv) {
  ros::init(argc, argv, "yarn_tearing_node");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  std::unique_ptr<YarnTearingNode> node;
  try {
    const ExitOnInterrupt exit_while_starting;  // the scene builds without checking ros::ok()
    node = std::make_unique<YarnTearingNode>(nh, private_nh, loadSimulationConfig(private_nh));
  } catch (const std::exception& e) {
    ROS_FATAL("yarn_tearing_node: invalid configuration: %s", e.what());
    ros::WallDuration(kFlushDelay).sleep();
    return kExitInvalidConfiguration;
  }
  try {
    const ShutdownOnInterrupt shutdown_within(kShutdownDeadline);
    node->run();
  } catch (const std::exception& e) {
    ROS_FATAL("yarn_tearing_node: simulation stopped: %s", e.what());
    ros::WallDuration(kFlushDelay).sleep();
    return kExitSimulationFailed;
  }
  return kExitOk;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
