// A yarn lying on a table (a plane): it does not sink, the table carries its weight, and with
// friction it does not creep.
#include <gtest/gtest.h>

#include "contact_test_support.hpp"

namespace yarn_tearing::test {
namespace {

struct TableCase {
  double dt;
  int vertices;
  double mu;
};

class YarnOnTable : public ::testing::TestWithParam<TableCase> {};

TEST_P(YarnOnTable, RestsWithoutSinkingOrDrifting) {
  const TableCase c = GetParam();
  YarnSpec spec = hangingYarn();
  spec.pinned = {};
  spec.num_vertices = c.vertices;
  spec.direction = Eigen::Vector3d::UnitX();
  spec.start = Eigen::Vector3d(0.0, 0.0, spec.radius + 0.005);  // dropped from 5 mm
  SimulationParameters p;
  p.time_step = c.dt;
  Simulator sim(p, {spec});
  const Obstacle table = obstacleAt(ObstacleShape::kPlane, Eigen::Vector3d::Zero(), c.mu);
  sim.setObstacles({table});
  const double weight = totalMass(sim) * kGravity;
  const int per_second = static_cast<int>(std::lround(1.0 / c.dt));
  for (int i = 0; i < per_second; ++i) {  // lands and settles within 1 s
    sim.step();
    ASSERT_LE(deepestPenetration(sim, table), 1e-4) << "step " << i;
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
  }
  const std::vector<Eigen::Vector3d> settled = sim.scene().vertices.position;
  double max_penetration = 0.0;
  double max_drift = 0.0;
  for (int i = 0; i < 10 * per_second; ++i) {
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    max_penetration = std::max(max_penetration, deepestPenetration(sim, table));
    EXPECT_NEAR(-sim.contactWrench(0).force.z(), weight, 0.005 * weight) << "step " << i;
  }
  for (std::size_t v = 0; v < settled.size(); ++v) {
    max_drift = std::max(max_drift, (sim.scene().vertices.position[v] - settled[v]).norm());
  }
  EXPECT_LE(max_penetration, 1e-4);
  if (c.mu > 0.0) {
    EXPECT_LE(max_drift, 1e-6) << "drift over 10 s [m]";
  }
  EXPECT_NEAR(sim.contactWrench(0).force.x(), 0.0, 1e-9 * weight);
}

INSTANTIATE_TEST_SUITE_P(Table, YarnOnTable,
                         ::testing::Values(TableCase{1e-3, 25, 0.3}, TableCase{1e-4, 25, 0.3},
                                           TableCase{1e-3, 100, 0.3}, TableCase{1e-3, 25, 0.0}));

}  // namespace
}  // namespace yarn_tearing::test
