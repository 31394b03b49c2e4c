// Newton systems solved by refinement with the last factorization of the same layout
// (StiffNewtonStep::solveWithLastFactor): a fabric held at its two top corners, whose layout
// (rows, taut set, eliminated vertices) holds from step to step once it hangs, stepped with and
// without them; the symbolic analyses StepHealth counts while the layout changes and once it
// holds.
#include <gtest/gtest.h>

#include <cmath>

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

class LastFactorizationAtStep : public ::testing::TestWithParam<double> {};

TEST_P(LastFactorizationAtStep, AFabricHeldAtItsCornersStepsAsWithFreshFactorizations) {
  // Released flat, it falls, swings and sags between its corners for 0.3 s.
  auto [reusing, fresh] =
      heldAtCornersBothWays(24, &SimulationParameters::force_fresh_factorizations, GetParam());
  // Within the projection's tolerance: 1e-6 of a 12.5 mm edge, 1e-6 of the largest tension.
  expectSameSteps(reusing, fresh, static_cast<int>(std::lround(0.3 / GetParam())), 1e-6 * 0.0125,
                  1e-6);
}

// At 1e-2 the released patch's steps part at round-off (their projections converge or are
// substepped by a hair), with whole and condensed systems as much: no shared trajectory there.
INSTANTIATE_TEST_SUITE_P(TimeSteps, LastFactorizationAtStep, ::testing::Values(1e-4, 1e-3),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return stepName(info.param);
                         });

TEST(LastFactorization, AHangingFabricIsFactorizedInFewOfItsSteps) {
  // Once it hangs (0.5 s, as BM_FabricHeldAtCorners), most steps take a Newton step whose system
  // has the last one's layout, solved without a factorization.
  constexpr int kSteps = 100;
  auto [reusing, fresh] =
      heldAtCornersBothWays(24, &SimulationParameters::force_fresh_factorizations);
  while (reusing.time() < 0.5) reusing.step();
  while (fresh.time() < 0.5) fresh.step();
  EXPECT_GE(factorizationsOver(fresh, kSteps), kSteps);
  EXPECT_LT(factorizationsOver(reusing, kSteps), kSteps / 2);
}

TEST(LastFactorization, AHangingFabricsSystemsAreAnalysedWhileItsLayoutChangesOnly) {
  // Released flat, its taut set and eliminated vertices change as it falls and swings: new
  // patterns, analysed; hanging, its systems keep their layout and their analysis.
  SimulationParameters parameters;
  parameters.force_fresh_factorizations = true;  // every system factorized, its pattern known
  Simulator fresh = heldAtCorners(24, parameters);
  int falling = 0;
  while (fresh.time() < 0.1) {
    fresh.step();
    falling += fresh.lastHealth().analyses;
    EXPECT_LE(fresh.lastHealth().analyses, fresh.lastHealth().factorizations);
  }
  EXPECT_GT(falling, 0);
  while (fresh.time() < 0.5) fresh.step();
  int hanging = 0;
  int factorized = 0;
  for (int k = 0; k < 100; ++k) {
    fresh.step();
    hanging += fresh.lastHealth().analyses;
    factorized += fresh.lastHealth().factorizations;
  }
  EXPECT_GE(factorized, 100);
  EXPECT_LT(hanging, factorized / 10);
}

}  // namespace
}  // namespace yarn_tearing::test
