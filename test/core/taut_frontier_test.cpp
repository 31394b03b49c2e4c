// A pull that runs along many slack edges in one step: the projection must take them all in
// within one iteration (the taut frontier), on the banded and on the general path.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "yarn_tearing/core/projection/length_constraint_projection.hpp"

namespace yarn_tearing::test {
namespace {

/// A nearly inextensible fibre (E = 7.6e13 Pa), so that the constraints take back a whole
/// gravity step and the closed form below holds to 1e-4.
Material nearlyInextensible() {
  return fibre("nearly_inextensible", {{0.0, 0.0}, {0.001, 7.6e10}, {0.002, 1.0e11}});
}

/// First step of a 2000-vertex yarn released straight from rest, top pinned: every vertex but the
/// pin falls by g dt^2, so only the top edge is stretched and each edge below is pulled taut only
/// once the one above holds. The exact answer: the chain cannot stretch, so the projection takes
/// the whole fall back and each edge carries the weight below it.
void expectReleasedYarnHeldInOneIteration(bool general_path) {
  YarnSpec spec = hangingYarn(nearlyInextensible());
  spec.num_vertices = 2000;
  spec.length = 2.0;
  const SimulationParameters parameters;
  const Simulator sim(parameters, {spec});
  const Scene& scene = sim.scene();
  const double dt = parameters.time_step;
  const double fall = kGravity * dt * dt;  // [m]

  std::vector<Eigen::Vector3d> position = scene.vertices.position;
  for (std::size_t v = 1; v < position.size(); ++v) position[v].z() -= fall;
  EdgeStretchLimits limits;
  computeStretchLimits(scene, parameters, limits);
  EdgeGramSolver gram;
  gram.setTopology(scene.edges, scene.vertices.size());
  gram.forceGeneralPath(general_path);
  LengthConstraintProjection projection;
  const ProjectionResult result =
      projection.project(position, scene.vertices, scene.edges, limits, parameters, gram);

  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.iterations, 1);
  for (std::size_t v = 0; v < position.size(); ++v) {
    ASSERT_LE((position[v] - scene.vertices.position[v]).norm(), 1e-4 * fall) << "vertex " << v;
  }
  double mass_below = 0.0;
  for (std::size_t e = scene.edges.size(); e-- > 0;) {
    mass_below += scene.vertices.mass[scene.edges.vertex_b[e]];
    const double weight_below = mass_below * kGravity;
    ASSERT_NEAR(projection.constraintForce(e), weight_below, 1e-4 * weight_below) << "edge " << e;
  }
}

TEST(TautFrontier, ReleasedYarnIsHeldInOneIterationOnTheBandedPath) {
  expectReleasedYarnHeldInOneIteration(false);
}

TEST(TautFrontier, ReleasedYarnIsHeldInOneIterationOnTheGeneralPath) {
  expectReleasedYarnHeldInOneIteration(true);
}

}  // namespace
}  // namespace yarn_tearing::test
