// A yarn dropped over a thin peg: its 12.5 mm segments do not pass through the 2 mm peg (the
// contact is a point inside the segment, not a vertex), also with end weights up to 10^4 vertex
// masses swinging round it, at dt = 1e-3 and 1e-4; every step converges.
#include <gtest/gtest.h>

#include "contact_test_support.hpp"

namespace yarn_tearing::test {
namespace {

struct PegCase {
  double dt;
  double end_mass_in_vertex_masses;
  double seconds;
};

class YarnOverPeg : public ::testing::TestWithParam<PegCase> {};

TEST_P(YarnOverPeg, SegmentsStayOutAndEveryStepConverges) {
  const PegCase c = GetParam();
  YarnSpec spec = hangingYarn();  // 25 vertices, 12.5 mm segments
  spec.direction = Eigen::Vector3d::UnitX();
  // Pinned at x = -0.15 m; the peg (radius 1 mm) sits under the middle of segment 11.
  const double segment = spec.length / (spec.num_vertices - 1);
  spec.start = Eigen::Vector3d(-11.5 * segment, 0.0, 1.0e-3 + spec.radius + 1.0e-6);
  const double vertex_mass = spec.linearDensity() * segment;
  spec.end_mass = c.end_mass_in_vertex_masses * vertex_mass;
  SimulationParameters p;
  p.time_step = c.dt;
  Simulator sim(p, {spec});
  Obstacle peg = postAlongY(1.0e-3, 0.0);
  sim.setObstacles({peg});
  const int steps = static_cast<int>(std::lround(c.seconds / c.dt));
  double deepest = 0.0;
  for (int i = 0; i < steps; ++i) {
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    ASSERT_LE(sim.lastHealth().max_constraint_violation, p.constraint_tolerance) << "step " << i;
    deepest = std::max(deepest, deepestPenetration(sim, peg));
  }
  EXPECT_LE(deepest, 1e-4);
  // It hangs over the peg: the weighted end below it, the contact pressing the peg down.
  EXPECT_LT(sim.scene().vertices.position.back().z(), -0.05);
  EXPECT_LT(sim.contactWrench(0).force.z(), 0.0);
}

// Up to 10^4 vertex masses on the end, at dt = 1e-3 and 1e-4.
std::string pegCaseName(const ::testing::TestParamInfo<PegCase>& info) {
  return "end" + std::to_string(std::lround(info.param.end_mass_in_vertex_masses)) +
         "vertexmasses_" + stepName(info.param.dt);
}
INSTANTIATE_TEST_SUITE_P(Weights, YarnOverPeg,
                         ::testing::Values(PegCase{1e-3, 0.0, 1.0}, PegCase{1e-3, 10.0, 1.0},
                                           PegCase{1e-3, 100.0, 1.0}, PegCase{1e-3, 1.0e4, 1.0},
                                           PegCase{1e-4, 1.0e4, 0.3}),
                         pegCaseName);

}  // namespace
}  // namespace yarn_tearing::test
