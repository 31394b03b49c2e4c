#pragma once

namespace yarn_tearing {
namespace ros_layer {

/// Exit status of runYarnTearingNode.
enum NodeExitStatus : int {
  kExitOk = 0,                    ///< ROS shut down normally
  kExitInvalidConfiguration = 1,  ///< a parameter was rejected (the fatal message names it)
  kExitSimulationFailed = 2,      ///< the simulation threw while running
};

/// The whole yarn_tearing_node program: ros::init as "yarn_tearing_node", a YarnTearingNode built
/// from the private parameters, run until ROS shuts down. Failures are reported with ROS_FATAL
/// (given 0.5 s to reach /rosout) and returned as a NodeExitStatus, the process's exit status.
/// SIGINT or SIGTERM while the configuration is validated and the scene built ends the process
/// at once with 130 or 143 (ExitOnInterrupt); afterwards, at the end of the current step.
int runYarnTearingNode(int argc, char** argv);

}  // namespace ros_layer
}  // namespace yarn_tearing
