#pragma once

#include <utility>
#include <vector>

#include "yarn_tearing/core/model/edge_incidence.hpp"
#include "yarn_tearing/core/projection/edge_stretch_limits.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing::test {

/// The stretch per rest length past which pivoting takes an edge in [-], and the push's move per
/// rest length below which it counts as none.
constexpr double kSlackTolerance = 1e-7;

/// What StiffNewtonStep::apply() reads of a scene at the default parameters, for tests that
/// drive Newton steps directly: its stretch limits, edge incidence and inverse masses.
struct NewtonStepInputs {
  explicit NewtonStepInputs(Scene built) : scene(std::move(built)) {
    computeStretchLimits(scene, parameters, limits);
    incidence.build(scene.edges, scene.vertices.size());
    for (std::size_t v = 0; v < scene.vertices.size(); ++v) {
      inverse_mass.push_back(scene.vertices.inverseMass(v));
    }
  }

  SimulationParameters parameters;
  Scene scene;
  EdgeStretchLimits limits;
  EdgeIncidence incidence;
  std::vector<double> inverse_mass;  ///< per vertex [1/kg]
};

}  // namespace yarn_tearing::test
