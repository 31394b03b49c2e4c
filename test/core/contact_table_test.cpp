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

// On a frictionless table the table pushes only along its normal: a yarn pulled along it by a
// force F moves its centre of mass exactly as a free body, x_n = x_0 + v_0 n dt + (F/M) dt^2
// n (n + 1) / 2 (the integrator's discrete law of a constant acceleration), while the table
// carries its weight and no horizontal force. (The resting yarn's vertices are kept on the face by
// the contact fast path, RestingContacts; a point new to the step takes the Newton steps.)
TEST(YarnOnFrictionlessTable, PulledAlongMovesAsAFreeBody) {
  YarnSpec spec = hangingYarn();
  spec.pinned = {};
  spec.num_vertices = 25;
  spec.direction = Eigen::Vector3d::UnitX();
  spec.start = Eigen::Vector3d(0.0, 0.0, spec.radius + 0.005);
  SimulationParameters p;
  p.time_step = 1e-3;
  Simulator sim(p, {spec});
  sim.setObstacles({obstacleAt(ObstacleShape::kPlane, Eigen::Vector3d::Zero(), 0.0)});
  const double mass = totalMass(sim);
  const double weight = mass * kGravity;
  for (int i = 0; i < 1000; ++i) sim.step();  // lands and settles
  const auto centre = [&](const std::vector<Eigen::Vector3d>& x) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t v = 0; v < x.size(); ++v) sum += sim.scene().vertices.mass[v] * x[v];
    return Eigen::Vector3d(sum / mass);
  };
  const Eigen::Vector3d x0 = centre(sim.scene().vertices.position);
  const Eigen::Vector3d v0 = centre(sim.scene().vertices.velocity);
  const double force = weight;  // along the yarn, at its far end
  sim.setAppliedForce(static_cast<std::uint32_t>(spec.num_vertices - 1),
                      force * Eigen::Vector3d::UnitX());
  const int steps = 500;
  for (int n = 1; n <= steps; ++n) {
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << n;
    EXPECT_NEAR(-sim.contactWrench(0).force.z(), weight, 0.005 * weight) << "step " << n;
    EXPECT_NEAR(sim.contactWrench(0).force.x(), 0.0, 1e-9 * weight) << "step " << n;
    EXPECT_NEAR(sim.contactWrench(0).force.y(), 0.0, 1e-9 * weight) << "step " << n;
  }
  const double dt = p.time_step;
  const double expected =
      x0.x() + v0.x() * steps * dt + force / mass * dt * dt * steps * (steps + 1) / 2.0;
  const Eigen::Vector3d x = centre(sim.scene().vertices.position);
  EXPECT_NEAR(x.x(), expected, 1e-9 * (expected - x0.x())) << "moved " << x.x() - x0.x() << " m";
  EXPECT_NEAR(x.y(), x0.y(), 1e-12);
  EXPECT_LE(deepestPenetration(sim, sim.obstacles()[0]), 1e-4);
}

// setObstacles keeps the contacts' friction states for the same solids at the same poses.
TEST(ObstacleGeometry, SameSolidAtTheSamePoseWhateverItsFrictionOrName) {
  const Obstacle post = obstacleAt(ObstacleShape::kCapsule, Eigen::Vector3d::Zero(), 0.0);
  Obstacle rough = post;
  rough.friction = 0.3;
  rough.name = "rough";
  EXPECT_TRUE(post.sameGeometry(rough));
  Obstacle moved = post;
  moved.pose.translation().x() += 1e-9;
  EXPECT_FALSE(post.sameGeometry(moved));
  Obstacle thicker = post;
  thicker.radius *= 1.5;
  EXPECT_FALSE(post.sameGeometry(thicker));
  Obstacle box = post;
  box.shape = ObstacleShape::kBox;
  EXPECT_FALSE(post.sameGeometry(box));
}

std::string tableCaseName(const ::testing::TestParamInfo<TableCase>& info) {
  return std::to_string(info.param.vertices) + "vertices_mu" +
         std::to_string(std::lround(10 * info.param.mu)) + "_" + stepName(info.param.dt);
}
INSTANTIATE_TEST_SUITE_P(Table, YarnOnTable,
                         ::testing::Values(TableCase{1e-3, 25, 0.3}, TableCase{1e-4, 25, 0.3},
                                           TableCase{1e-3, 100, 0.3}, TableCase{1e-3, 25, 0.0}),
                         tableCaseName);

}  // namespace
}  // namespace yarn_tearing::test
