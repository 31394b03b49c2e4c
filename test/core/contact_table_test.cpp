// A yarn lying on a table (a plane): it does not sink, the table carries its weight, and with
// friction it does not creep. A table raised into a hanging yarn's end carries it at its speed, and
// a torn end pulled onto one lands and rests there.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

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

/// "dt1em3_25vertices": a case of a time step [s] and a vertex count [-].
std::string stepAndVerticesName(const ::testing::TestParamInfo<std::tuple<double, int>>& info) {
  return stepName(std::get<0>(info.param)) + "_" + std::to_string(std::get<1>(info.param)) +
         "vertices";
}

// A frictionless table raised at 1 cm/s into the lowest vertex of a hanging yarn (2 or 25
// vertices) lifts it: from 50 ms after it arrives (its edge's elastic stretch under its weight,
// 0.13 um with 2 vertices, lets it go in a hop) that vertex rides on the table, at its height plus
// the yarn's radius and at its speed, and no vertex moves faster than 2 x the table.
class RaisedTable : public ::testing::TestWithParam<std::tuple<double, int>> {};

TEST_P(RaisedTable, LiftsAHangingYarnsEndAtItsSpeed) {
  const auto [dt, vertices] = GetParam();
  YarnSpec spec = hangingYarn();
  spec.num_vertices = vertices;
  SimulationParameters p;
  p.time_step = dt;
  Simulator sim(p, {spec});
  const std::uint32_t end = static_cast<std::uint32_t>(vertices - 1);
  const std::vector<Eigen::Vector3d>& x = sim.scene().vertices.position;
  const std::vector<Eigen::Vector3d>& v = sim.scene().vertices.velocity;
  const double speed = 0.01;                             // [m/s]
  const double start = x[end].z() - spec.radius - 1e-3;  // 1 mm below the end [m]
  sim.setObstacles({obstacleAt(ObstacleShape::kPlane, Eigen::Vector3d(0.0, 0.0, start), 0.0)});
  const int steps = static_cast<int>(std::lround(0.2 / dt));     // lifted by 2 mm
  const int settled = static_cast<int>(std::lround(0.15 / dt));  // 50 ms after it arrives
  double fastest = 0.0;                                          // [m/s]
  for (int i = 1; i <= steps; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation().z() = start + speed * i * dt;
    sim.setObstaclePose(0, pose);
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    for (const Eigen::Vector3d& velocity : v) fastest = std::max(fastest, velocity.norm());
    if (i < settled) continue;
    EXPECT_NEAR(x[end].z(), pose.translation().z() + spec.radius, 1e-6 * spec.radius)
        << "step " << i;
    EXPECT_NEAR(v[end].z(), speed, 1e-6 * speed) << "step " << i;
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_LE(fastest, 2.0 * speed);
}

INSTANTIATE_TEST_SUITE_P(Steps, RaisedTable,
                         ::testing::Combine(::testing::Values(1e-4, 1e-3, 1e-2),
                                            ::testing::Values(2, 25)),
                         stepAndVerticesName);

// A hanging yarn whose last edge is weak (a quarter of the yarn's strength), its end pulled down by
// twice that edge's breaking force towards a frictionless table 5 mm below: the edge tears, and the
// end, a lone vertex now, flies onto the table and stays there, at the table plus the yarn's
// radius, the table carrying the pull and the vertex's weight; on its way it is never faster than
// the pull and gravity can throw it over the drop and the torn edge's stretch plus the yarn's
// snap-back speed (2, 3 and 25 vertices).
class TornEndOnTable : public ::testing::TestWithParam<std::tuple<double, int>> {};

TEST_P(TornEndOnTable, LandsAndRestsOnIt) {
  const auto [dt, vertices] = GetParam();
  YarnSpec spec = hangingYarn();
  spec.num_vertices = vertices;
  spec.length = 0.0125 * (vertices - 1);
  Scene scene = buildScene({spec});
  const std::uint32_t end = static_cast<std::uint32_t>(vertices - 1);
  const double weak = 0.25;  // the last edge's share of the yarn's strength [-]
  scene.edges.strength_factor.back() = weak;
  SimulationParameters p;
  p.time_step = dt;
  Simulator sim(p, std::move(scene));
  const VertexSet& v = sim.scene().vertices;
  const double table = v.position[end].z() - 0.005;  // [m]
  sim.setObstacles({obstacleAt(ObstacleShape::kPlane, Eigen::Vector3d(0.0, 0.0, table), 0.0)});
  const StressStrainCurve& curve = spec.material.curve;
  const double pull = 2.0 * weak * curve.breakingStress() * kPi * spec.radius * spec.radius;  // [N]
  sim.setAppliedForce(end, Eigen::Vector3d(0.0, 0.0, -pull));
  const double mass = v.mass[end];
  const double acceleration = pull / mass + kGravity;  // [m/s^2]
  // Pulled over the drop and the torn edge's stretch, plus a snap-back [m/s].
  const double drop = 0.005 + 0.0125 * curve.breakingStrain();  // [m]
  const double fastest = std::sqrt(2.0 * acceleration * drop) + spec.material.snapBackSpeed();
  std::size_t tears = 0;
  for (int i = 0; i < static_cast<int>(std::lround(0.05 / dt)); ++i) {
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    ASSERT_LE(v.velocity[end].norm(), fastest) << "step " << i;
    tears += sim.takeTearEvents().size();
  }
  EXPECT_EQ(tears, 1u);
  EXPECT_NEAR(v.position[end].z(), table + spec.radius, 1e-6 * spec.radius);
  EXPECT_LE(v.velocity[end].norm(), 1e-6);
  const double carried = pull + mass * kGravity;  // [N]
  EXPECT_NEAR(-sim.contactWrench(0).force.z(), carried, 1e-6 * carried);
}

INSTANTIATE_TEST_SUITE_P(Steps, TornEndOnTable,
                         ::testing::Combine(::testing::Values(1e-4, 1e-3, 1e-2),
                                            ::testing::Values(2, 3, 25)),
                         stepAndVerticesName);

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
