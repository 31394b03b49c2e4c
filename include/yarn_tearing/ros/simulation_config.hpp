#pragma once

#include <ros/node_handle.h>

#include <vector>

#include "yarn_tearing/core/model/fabric_spec.hpp"
#include "yarn_tearing/core/model/yarn_spec.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"
#include "yarn_tearing/ros/node_settings.hpp"
#include "yarn_tearing/ros/obstacle_spec_loader.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Everything the node is configured with, read from its private parameters.
struct SimulationConfig {
  SimulationParameters parameters;      ///< physics parameters shared by all yarns
  std::vector<YarnSpec> yarns;          ///< the yarns of the scene, in parameter order
  std::vector<FabricSpec> fabrics;      ///< the fabrics of the scene (after the yarns), in order
  std::vector<ObstacleSpec> obstacles;  ///< what the yarns touch, in parameter order
  NodeSettings node;                    ///< timing, publishing and drawing settings
};

/// Reads and validates every parameter of the node from its private namespace (see
/// config/default.yaml). Throws ParameterError naming the parameter, the value and what is
/// allowed; also checks what the core checks (curve, yarn specs, simulation parameters), so that a
/// config that loads also builds a Simulator.
SimulationConfig loadSimulationConfig(const ros::NodeHandle& private_nh);

/// Air damping [N*s/m^2] must stay below this: the lightest yarn's mass per length / time_step
/// (explicit drag; more would reverse a velocity in one step and grow without bound).
double maxStableAirDamping(const SimulationConfig& config);

}  // namespace ros_layer
}  // namespace yarn_tearing
