// StiffNewtonStep's pivoting on a pushing edge: a taut edge whose solve would push its ends apart
// leaves the taut set where that push would move them by more than the slack tolerance, and
// releasedMove() reports the move, (w_a + w_b) times the push; a smaller push counts as none (the
// edge stays taut, its multiplier 0, held at its length). A hanging 25-vertex yarn at rest, one
// vertex moved up along the yarn by `shift`, every edge taut, one Newton step.
#include <gtest/gtest.h>

#include "newton_step_support.hpp"
#include "test_support.hpp"
#include "yarn_tearing/core/projection/edge_stretch_state.hpp"
#include "yarn_tearing/core/projection/stiff_newton_step.hpp"

namespace yarn_tearing::test {
namespace {

/// The yarn's edge that the moved vertex ends: its vertex b moves toward its vertex a.
constexpr std::size_t kPushed = 10;

/// One Newton step of hangingYarn() at rest, vertex b of edge kPushed moved up by `shift` [m]
/// (its edge shorter, the next one longer by as much), every edge taut with multiplier 0.
struct PushedYarn : NewtonStepInputs {
  explicit PushedYarn(double shift) : NewtonStepInputs(buildScene({hangingYarn()})) {
    const EdgeSet& edges = scene.edges;
    state.reset(edges, limits, parameters.time_step);
    position = scene.vertices.position;
    position[edges.vertex_b[kPushed]].z() += shift;
    predicted = position;
    movable.assign(edges.size(), 1);
    taut.assign(edges.size(), 1);
    multiplier.assign(edges.size(), 0.0);
    newton.beginProjection(parameters.time_step, kSlackTolerance);
    newton.apply(predicted, inverse_mass, edges, incidence, state, movable, taut, position,
                 multiplier);
  }
  /// The pushed edge's rest length [m]: hangingYarn()'s length over its edges.
  static double restLength() {
    const YarnSpec spec = hangingYarn();
    return spec.length / static_cast<double>(spec.num_vertices - 1);
  }
  /// Edge e's length after the step [m].
  double length(std::size_t e) const {
    return (position[scene.edges.vertex_b[e]] - position[scene.edges.vertex_a[e]]).norm();
  }

  EdgeStretchState state;
  StiffNewtonStep newton;
  std::vector<Eigen::Vector3d> predicted;
  std::vector<Eigen::Vector3d> position;
  std::vector<std::uint8_t> movable;
  std::vector<std::uint8_t> taut;
  std::vector<double> multiplier;
};

TEST(NewtonPush, AnEdgeWhosePushWouldMoveItsEndsPastTheToleranceIsReleasedWithThatMove) {
  const double rest = PushedYarn::restLength();
  const double shift = 1e-3 * rest;  // 10^4 times the slack tolerance
  PushedYarn yarn(shift);
  const EdgeSet& edges = yarn.scene.edges;
  // Held at their lengths, the edges from the pin to vertex 11 would push it back down (the chain
  // below it has no other support): each carries the push, so each is released.
  for (std::size_t e = 0; e <= kPushed; ++e) {
    EXPECT_EQ(yarn.taut[e], 0) << "edge " << e;
    EXPECT_EQ(yarn.multiplier[e], 0.0) << "edge " << e;
    EXPECT_GT(yarn.newton.releasedMove(e), kSlackTolerance * rest) << "edge " << e;
  }
  // The pushed edge's push p is at most vertex 11's momentum m s (the compliance of the edges
  // above gives way a little), so its move (w_a + w_b) p at most 2 s: the two masses are equal.
  const double w_a = yarn.inverse_mass[edges.vertex_a[kPushed]];
  const double w_b = yarn.inverse_mass[edges.vertex_b[kPushed]];
  ASSERT_EQ(w_a, w_b);
  EXPECT_LE(yarn.newton.releasedMove(kPushed), 2.0 * shift);
  EXPECT_GT(yarn.newton.releasedMove(kPushed), shift);
  // Released, the edge stays slack; the chain below it, free, keeps its momentum (zero) while
  // its stretched first edge is pulled back to its length.
  EXPECT_LT(yarn.length(kPushed), rest);
  EXPECT_NEAR(yarn.length(kPushed + 1), rest, 1e-6 * rest);
  EXPECT_GT(yarn.multiplier[kPushed + 1], 0.0);
  EXPECT_EQ(yarn.newton.releasedMove(kPushed + 1), 0.0);
  double momentum = 0.0;  // [kg m]: mass times move, along z
  double mass = 0.0;      // [kg]
  for (std::size_t v = edges.vertex_b[kPushed]; v < yarn.position.size(); ++v) {
    const double m = 1.0 / yarn.inverse_mass[v];
    momentum += m * (yarn.position[v].z() - yarn.predicted[v].z());
    mass += m;
  }
  EXPECT_NEAR(momentum, 0.0, 1e-9 * mass * shift);
}

TEST(NewtonPush, APushBelowTheToleranceCountsAsNoneAndKeepsTheEdgeTautAtItsLength) {
  const double rest = PushedYarn::restLength();
  const double shift = 0.1 * kSlackTolerance * rest;
  PushedYarn yarn(shift);
  EXPECT_EQ(yarn.taut[kPushed], 1);
  EXPECT_EQ(yarn.multiplier[kPushed], 0.0);
  EXPECT_EQ(yarn.newton.releasedMove(kPushed), 0.0);
  // Kept as an equality, its solve pushed it back to its length.
  EXPECT_NEAR(yarn.length(kPushed), rest, kSlackTolerance * rest);
}

}  // namespace
}  // namespace yarn_tearing::test
