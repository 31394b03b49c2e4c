// Newton systems solved by refinement with the last factorization of the same layout
// (StiffNewtonStep::solveWithLastFactor): a fabric held at its two top corners, whose layout
// (rows, taut set, eliminated vertices) holds from step to step once it hangs, stepped with and
// without them.
#include <gtest/gtest.h>

#include "fabric_support.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing::test {
namespace {

/// Newton systems factorized over the next `steps` steps of `sim` [-].
int factorizationsOver(Simulator& sim, int steps) {
  int factorizations = 0;
  for (int k = 0; k < steps; ++k) {
    sim.step();
    factorizations += sim.lastHealth().factorizations;
  }
  return factorizations;
}

TEST(LastFactorization, AFabricHeldAtItsCornersStepsAsWithFreshFactorizations) {
  // Released flat, it falls, swings and sags between its corners for 0.3 s at dt = 1e-3.
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  Simulator reusing = heldAtCorners(24, parameters);
  parameters.force_fresh_factorizations = true;
  Simulator fresh = heldAtCorners(24, parameters);
  // Within the projection's tolerance: 1e-6 of a 12.5 mm edge, 1e-6 of the largest tension.
  expectSameSteps(reusing, fresh, 300, 1e-6 * 0.0125, 1e-6);
}

TEST(LastFactorization, AHangingFabricIsFactorizedInFewOfItsSteps) {
  // Once it hangs (0.5 s, as BM_FabricHeldAtCorners), most steps take a Newton step whose system
  // has the last one's layout, solved without a factorization.
  constexpr int kSteps = 100;
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  Simulator reusing = heldAtCorners(24, parameters);
  parameters.force_fresh_factorizations = true;
  Simulator fresh = heldAtCorners(24, parameters);
  while (reusing.time() < 0.5) reusing.step();
  while (fresh.time() < 0.5) fresh.step();
  EXPECT_GE(factorizationsOver(fresh, kSteps), kSteps);
  EXPECT_LT(factorizationsOver(reusing, kSteps), kSteps / 2);
}

}  // namespace
}  // namespace yarn_tearing::test
