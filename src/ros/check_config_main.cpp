// check_config: validates yarn_tearing_node's private parameters exactly as the node does, then
// simulates up to one second (at most 0.5 s of processor time, at least one step) and checks that
// no step left a non-finite value. Run it under the node's name to check a node's parameters
// without starting it: `rosrun yarn_tearing check_config __name:=yarn_tearing`. Exit status: 0
// valid, 1 invalid (the message names the parameter), 3 valid parameters whose simulation went
// non-finite (a bound is missing: please report it).
#include <ros/ros.h>

#include <cstdio>
#include <ctime>
#include <exception>
#include <vector>

#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/ros/node_runner.hpp"
#include "yarn_tearing/ros/simulation_config.hpp"

namespace {

constexpr double kCheckedTime = 1.0;  ///< [s] simulated
/// Processor time spent stepping at most [s]: a check run beside others (a test running several
/// at once) steps as far as one run alone.
constexpr double kStepBudget = 0.5;
constexpr int kExitNonFinite = 3;

}  // namespace

int main(int argc, char** argv) {
  using namespace yarn_tearing;
  ros::init(argc, argv, "yarn_tearing_check_config", ros::init_options::NoRosout);
  ros::NodeHandle private_nh("~");
  try {
    const ros_layer::SimulationConfig config = ros_layer::loadSimulationConfig(private_nh);
    Simulator simulator(config.parameters, config.yarns, config.fabrics);
    std::vector<Obstacle> fixed_obstacles;  // attached ones follow tf frames, absent here
    for (const ros_layer::ObstacleSpec& spec : config.obstacles) {
      if (!spec.attached()) fixed_obstacles.push_back(spec.obstacle);
    }
    simulator.setObstacles(fixed_obstacles);
    const std::clock_t start = std::clock();
    const double steps = kCheckedTime / config.parameters.time_step;
    for (double k = 0.0; k < steps && ros::ok(); k += 1.0) {
      if (k > 0.0 && static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC > kStepBudget) {
        break;
      }
      simulator.step();
      if (!simulator.lastHealth().restored_yarns.empty()) {
        std::fprintf(
            stderr, "valid parameters, but step %.0f left yarn '%s' non-finite\n", k,
            simulator.scene().yarns[simulator.lastHealth().restored_yarns[0]].name.c_str());
        return kExitNonFinite;
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "invalid configuration: %s\n", e.what());
    return ros_layer::kExitInvalidConfiguration;
  }
  return ros_layer::kExitOk;
}
