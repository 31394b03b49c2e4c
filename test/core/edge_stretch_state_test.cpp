// EdgeStretchState::resumeFlow: an edge that flowed in the last step starts the next projection on
// its flow piece, whose limit meets the elastic one at the yield force, and leaves it again under
// a smaller multiplier; an edge that cannot flow before it breaks stays on its first piece.
#include "yarn_tearing/core/projection/edge_stretch_state.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

/// The stretch state of a 25-vertex yarn of `material` at Δt = 1 ms, every edge on its first
/// piece, with the limits it is built from.
struct YarnStretch {
  explicit YarnStretch(const Material& material) : scene(buildScene({hangingYarn(material)})) {
    computeStretchLimits(scene, parameters, limits);
    computeFlowLimits(scene, limits);
    state.reset(scene.edges, limits, parameters.time_step);
  }
  SimulationParameters parameters;
  Scene scene;
  EdgeStretchLimits limits;
  EdgeStretchState state;
};

TEST(EdgeStretchState, AnEdgeThatFlowedResumesOnItsFlowPieceContinuousAtItsYieldForce) {
  YarnStretch yarn(cottonLike());
  const std::size_t e = 3;
  const double dt = yarn.parameters.time_step;
  const double yield = yarn.limits.flow_start[e] * dt * dt;  // multiplier where it flows [kg m]
  ASSERT_GT(yield, 0.0);
  ASSERT_FALSE(yarn.state.flowing(e));
  const double elastic_shift = yarn.state.shift()[e];
  const double elastic_limit = yarn.state.limit(e, yield);

  yarn.state.resumeFlow(yarn.scene.edges, e);

  EXPECT_TRUE(yarn.state.flowing(e));
  // Past yield the edge is softer (cotton's hardening modulus is 0.87 of its Young's), and its
  // limit is continuous where the flow starts.
  EXPECT_GT(yarn.state.shift()[e], elastic_shift);
  EXPECT_NEAR(yarn.state.limit(e, yield), elastic_limit, 1e-12 * elastic_limit);
  // A multiplier well below the yield force lies off the flow piece: the projection moves the
  // edge back.
  EXPECT_TRUE(yarn.state.wouldSwitch(e, 0.5 * yield));
  EXPECT_FALSE(yarn.state.wouldSwitch(e, yield));
  yarn.state.settle(yarn.scene.edges, e, 0.5 * yield);
  EXPECT_FALSE(yarn.state.flowing(e));
  EXPECT_EQ(yarn.state.shift()[e], elastic_shift);
}

TEST(EdgeStretchState, AnEdgeThatCannotFlowBeforeItBreaksStaysOnItsFirstPiece) {
  // Linear up to its breaking point (its yield point on the same line): held at its breaking
  // length past it, never flowing.
  YarnStretch yarn(fibre("brittle", {{0.0, 0.0}, {0.01, 7.0e8}, {0.02, 1.4e9}}));
  const std::size_t e = 3;
  const double shift = yarn.state.shift()[e];
  const double base = yarn.state.baseLength()[e];

  yarn.state.resumeFlow(yarn.scene.edges, e);

  EXPECT_FALSE(yarn.state.flowing(e));
  EXPECT_EQ(yarn.state.shift()[e], shift);
  EXPECT_EQ(yarn.state.baseLength()[e], base);
}

}  // namespace
}  // namespace yarn_tearing::test
