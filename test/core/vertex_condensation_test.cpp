// Newton systems with the vertices no edge stiffens eliminated (VertexCondensation): a fabric
// held at its two top corners, whose weight hangs on its top yarns, stepped with condensed and
// with whole systems.
#include <gtest/gtest.h>

#include <algorithm>

#include "fabric_support.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing::test {
namespace {

/// A side x side cotton weave, 12.5 mm between yarns, pinned at its two top corners.
Simulator heldAtCorners(int side, const SimulationParameters& parameters) {
  const double length = 0.0125 * (side - 1);
  FabricSpec spec = cottonPatch(side, side, length, length);
  spec.pinned_sides.clear();
  spec.pinned = {{0, 0}, {0, -1}};
  return Simulator(parameters, {}, {spec});
}

TEST(VertexCondensation, AFabricHeldAtItsCornersStepsAsWithWholeSystems) {
  // Released flat, it falls, swings and sags between its corners for 0.3 s at dt = 1e-3.
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  Simulator condensed = heldAtCorners(24, parameters);
  parameters.force_full_newton_systems = true;
  Simulator whole = heldAtCorners(24, parameters);
  for (int k = 0; k < 300; ++k) {
    condensed.step();
    whole.step();
    ASSERT_TRUE(condensed.lastHealth().projection_converged) << "step " << k;
    ASSERT_TRUE(whole.lastHealth().projection_converged) << "step " << k;
  }
  const Scene& a = condensed.scene();
  const Scene& b = whole.scene();
  double position_difference = 0.0;
  for (std::size_t v = 0; v < a.vertices.size(); ++v) {
    position_difference =
        std::max(position_difference, (a.vertices.position[v] - b.vertices.position[v]).norm());
  }
  double tension_difference = 0.0;
  double largest_tension = 0.0;
  for (std::size_t e = 0; e < a.edges.size(); ++e) {
    tension_difference =
        std::max(tension_difference, std::abs(a.edges.tension[e] - b.edges.tension[e]));
    largest_tension = std::max(largest_tension, std::abs(b.edges.tension[e]));
  }
  // Within the projection's tolerance: 1e-6 of a 12.5 mm edge, 1e-6 of the largest tension.
  EXPECT_LT(position_difference, 1e-6 * 0.0125);
  ASSERT_GT(largest_tension, 0.0);
  EXPECT_LT(tension_difference, 1e-6 * largest_tension);
}

}  // namespace
}  // namespace yarn_tearing::test
