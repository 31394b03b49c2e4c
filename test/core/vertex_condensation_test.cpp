// Newton systems with the vertices no edge stiffens eliminated (VertexCondensation): a fabric
// held at its two top corners, whose weight hangs on its top yarns, stepped with condensed and
// with whole systems.
#include <gtest/gtest.h>

#include "fabric_support.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing::test {
namespace {

TEST(VertexCondensation, AFabricHeldAtItsCornersStepsAsWithWholeSystems) {
  // Released flat, it falls, swings and sags between its corners for 0.3 s at dt = 1e-3.
  auto [condensed, whole] =
      heldAtCornersBothWays(24, &SimulationParameters::force_full_newton_systems);
  // Within the projection's tolerance: 1e-6 of a 12.5 mm edge, 1e-6 of the largest tension.
  expectSameSteps(condensed, whole, 300, 1e-6 * 0.0125, 1e-6);
}

}  // namespace
}  // namespace yarn_tearing::test
