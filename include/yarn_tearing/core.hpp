/// The simulation core's public interface in one include: the simulator, the scene it steps, the
/// specs that build yarns, fabrics and obstacles, the materials and the break events it reports.
/// No ROS header; link yarn_tearing_core.
#pragma once

#include "yarn_tearing/core/contact/obstacle.hpp"
#include "yarn_tearing/core/material/material.hpp"
#include "yarn_tearing/core/material/stress_strain_curve.hpp"
#include "yarn_tearing/core/model/fabric_spec.hpp"
#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/model/yarn_spec.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/core/tearing/tear_event.hpp"
