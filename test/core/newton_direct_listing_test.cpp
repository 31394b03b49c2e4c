// StiffNewtonStep's systems on a weave listed straight into the analysed pattern: a slack edge's
// idle row is passed over by a count of the entries a taut row lists (skipIdleEntries()), so the
// count must match addEdgeRows()' listing, or every such system falls back to triplets (still
// solved, only slower). A 6 x 6 patch hanging from its first row, its free vertices moved by a
// fixed pattern, so that the pivoting passes of a Newton step release some edges and keep others:
// systems with idle rows among taut ones, of the same layout.
#include <gtest/gtest.h>

#include <cmath>

#include "fabric_support.hpp"
#include "newton_step_support.hpp"
#include "yarn_tearing/core/projection/edge_stretch_state.hpp"
#include "yarn_tearing/core/projection/stiff_newton_step.hpp"

namespace yarn_tearing::test {
namespace {

TEST(NewtonDirectListing, AWeavesSystemsWithIdleRowsListStraightIntoTheAnalysedPattern) {
  const NewtonStepInputs weave(buildScene({}, {cottonPatch(6, 6, 0.0625, 0.0625)}));
  const EdgeSet& edges = weave.scene.edges;
  const std::vector<double>& inverse_mass = weave.inverse_mass;
  const double time_step = weave.parameters.time_step;
  // Each free vertex moved by up to 2 % of a 12.5 mm edge along each axis, in a pattern that
  // stretches some edges and shortens others [m].
  std::vector<Eigen::Vector3d> predicted = weave.scene.vertices.position;
  for (std::size_t v = 0; v < predicted.size(); ++v) {
    if (inverse_mass[v] == 0.0) continue;
    const double phase = static_cast<double>(v);
    predicted[v] += 2.5e-4 * Eigen::Vector3d(std::sin(1.7 * phase), std::cos(2.3 * phase),
                                             std::sin(0.9 * phase + 0.4));
  }
  // Each Newton step from the prediction, the first with every edge taut, each later one with
  // the taut set the one before ended with: idle rows among taut ones in the same layout.
  StiffNewtonStep newton;
  const std::vector<std::uint8_t> movable(edges.size(), 1);
  std::vector<std::uint8_t> taut(edges.size(), 1);
  int idle = 0;  // free edges with idle rows in the later steps' first systems
  constexpr int kSteps = 3;
  for (int k = 0; k < kSteps; ++k) {
    EdgeStretchState state;
    state.reset(edges, weave.limits, time_step);
    std::vector<Eigen::Vector3d> position = predicted;
    std::vector<double> multiplier(edges.size(), 0.0);
    if (k > 0) {
      for (std::size_t e = 0; e < edges.size(); ++e) {
        const bool free = inverse_mass[edges.vertex_a[e]] + inverse_mass[edges.vertex_b[e]] > 0.0;
        idle += free && taut[e] == 0 ? 1 : 0;
      }
    }
    newton.beginProjection(time_step, kSlackTolerance);
    newton.apply(predicted, inverse_mass, edges, weave.incidence, state, movable, taut, position,
                 multiplier);
  }
  EXPECT_GT(idle, 0);
  // Every system after the one that analysed the layout could list directly; each that began so
  // followed the analysed sequence to its end.
  EXPECT_GE(newton.directListings(), kSteps - 1);
  EXPECT_EQ(newton.directFallbacks(), 0);
}

}  // namespace
}  // namespace yarn_tearing::test
