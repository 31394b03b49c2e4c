// EdgeStretchState::resumeFlow: an edge that flowed in the last step starts the next projection on
// its flow piece, whose limit meets the elastic one at the yield force, and leaves it again under
// a smaller multiplier; an edge that cannot flow before it breaks stays on its first piece. An
// edge whose pieces are not built yet answers as one whose pieces are.
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

TEST(EdgeStretchState, AnEdgeWhosePiecesAreNotBuiltAnswersAsOneWhosePiecesAre) {
  // `built` has its pieces built (taken onto its flow piece and released back to its first);
  // `pending` has not: the same limits, switches and multipliers at a length, up to the stop.
  YarnStretch pending(cottonLike());
  YarnStretch built(cottonLike());
  const EdgeSet& edges = built.scene.edges;
  const std::size_t e = 3;
  built.state.resumeFlow(edges, e);
  built.state.release(edges, e);
  const double dt = built.parameters.time_step;
  const double yield = built.limits.flow_start[e] * dt * dt;  // [kg m]
  const double rest = edges.rest_length[e];
  const double breaking = rest + built.limits.max_stretch[e];
  EXPECT_EQ(pending.state.shift()[e], built.state.shift()[e]);
  EXPECT_EQ(pending.state.baseLength()[e], built.state.baseLength()[e]);
  for (const double m : {0.0, 0.5 * yield, yield, 1.5 * yield}) {
    EXPECT_EQ(pending.state.wouldSwitch(e, m), built.state.wouldSwitch(e, m)) << m;
  }
  for (const double fraction : {-0.5, 0.0, 0.001, 0.3, 0.7, 1.0, 1.2}) {
    YarnStretch fresh(cottonLike());
    const double length = rest + fraction * (breaking - rest);
    EXPECT_EQ(fresh.state.multiplierAtLength(edges, e, length),
              built.state.multiplierAtLength(edges, e, length))
        << fraction;
  }
  pending.state.release(edges, e);
  EXPECT_FALSE(pending.state.flowing(e));
  pending.state.settle(edges, e, 1.5 * yield);
  built.state.settle(edges, e, 1.5 * yield);
  EXPECT_TRUE(pending.state.flowing(e));
  EXPECT_EQ(pending.state.shift()[e], built.state.shift()[e]);
  EXPECT_EQ(pending.state.baseLength()[e], built.state.baseLength()[e]);
}

}  // namespace
}  // namespace yarn_tearing::test
