// Tearing over a capstan: a yarn wrapped round a post with friction, end A loaded with T1 and
// end B pulled harder and harder. Friction holds the wrap (T2 / T1 stays below e^(mu theta)), so
// the pulled side carries more than the held one and tears there, at its breaking force
// sigma_b pi r^2, while the held side still carries T1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "wrap_support.hpp"

namespace yarn_tearing::test {
namespace {

struct TearCase {
  double wrap_angle;  ///< [rad]
  double dt;          ///< [s]
};

class CapstanTear : public ::testing::TestWithParam<TearCase> {};

TEST_P(CapstanTear, BreaksOnThePulledSideAtItsBreakingForce) {
  const TearCase c = GetParam();
  constexpr double kMu = 0.3;           // [-]
  const YarnSpec spec = hangingYarn();  // cotton-like: sigma_b = 486 MPa, r = 0.1 mm
  const double breaking_force = 4.86e8 * kPi * spec.radius * spec.radius;  // 15.27 N
  // T1 such that the yarn tears before it slides: F_b / T1 = 1.43 < e^(0.3 pi / 2) = 1.60.
  const double t1 = 0.7 * breaking_force;  // [N]
  const int tail = 10;                     // chords per tail
  const WrappedYarn wrap = wrappedYarn(spec, kPostRadius, c.wrap_angle, tail, 0.2);
  SimulationParameters p = parametersWithoutGravity(c.dt);
  p.air_damping = 0.01;  // [N s/m^2]
  Simulator sim(p, wrap.scene);
  const auto last = static_cast<std::uint32_t>(sim.scene().vertices.size() - 1);
  // Both ends loaded to T1 over 50 ms without friction (past yield: the tails stretch
  // plastically), settled for 50 ms more; then friction acts and end B's pull rises at 20 N/s.
  sim.setObstacles({postAlongY(kPostRadius, 0.0)});
  for (int i = 1; i <= std::lround(0.1 / c.dt); ++i) {
    const double load = std::min(1.0, i * c.dt / 0.05) * t1;
    sim.setAppliedForce(0, load * wrap.tail_direction_a);
    sim.setAppliedForce(last, load * wrap.tail_direction_b);
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "loading, step " << i;
  }
  sim.setObstacles({postAlongY(kPostRadius, kMu)});
  const Eigen::Vector3d start = sim.scene().vertices.position[0];
  const std::size_t edges = sim.scene().edges.size();
  const double rate = 20.0;  // [N/s]
  const int steps = static_cast<int>(std::ceil(1.2 * (breaking_force - t1) / rate / c.dt));
  std::vector<TearEvent> events;
  double held_side = 0.0;  // tension of end A's edge in the step before the tear [N]
  for (int i = 1; i <= steps && events.empty(); ++i) {
    held_side = sim.scene().edges.tension.front();
    sim.setAppliedForce(last, (t1 + rate * i * c.dt) * wrap.tail_direction_b);
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    events = sim.takeTearEvents();
  }
  ASSERT_EQ(events.size(), 1u);
  // End B's tail is the last `tail` edges.
  EXPECT_GE(events[0].edge, edges - tail) << "torn edge of " << edges;
  EXPECT_NEAR(events[0].tension, breaking_force, 0.02 * breaking_force);
  EXPECT_NEAR(held_side, t1, 0.005 * t1);
  // The wrap held until the tear: end A moved by its tail's stretch only.
  EXPECT_LT((sim.scene().vertices.position[0] - start).norm(), 2e-5) << "end A moved [m]";
}

std::string tearCaseName(const ::testing::TestParamInfo<TearCase>& info) {
  return angleName(info.param.wrap_angle) + "_" + stepName(info.param.dt);
}
INSTANTIATE_TEST_SUITE_P(Angles, CapstanTear,
                         ::testing::Values(TearCase{kPi / 2.0, 1e-3}, TearCase{kPi, 1e-3},
                                           TearCase{2.0 * kPi, 1e-3}, TearCase{kPi, 1e-4},
                                           TearCase{2.0 * kPi, 1e-4}, TearCase{kPi / 2.0, 1e-2},
                                           TearCase{kPi, 1e-2}, TearCase{2.0 * kPi, 1e-2}),
                         tearCaseName);

}  // namespace
}  // namespace yarn_tearing::test
