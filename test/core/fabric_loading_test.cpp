// A fabric under load against closed forms: a hanging patch's supports carry its weight, a strip
// pulled along the warp tears across it at the warp yarns' breaking force times their number.
#include <gtest/gtest.h>

#include "fabric_support.hpp"

namespace yarn_tearing::test {
namespace {

/// Sum of the support forces of the fabric's vertices in `row` [N].
Eigen::Vector3d rowSupport(const Simulator& sim, int row) {
  const Fabric& fabric = sim.scene().fabrics[0];
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int c = 0; c < static_cast<int>(fabric.ends); ++c) {
    sum += sim.supportForce(sim.scene().fabricVertex(0, row, c));
  }
  return sum;
}

TEST(FabricLoading, HangingFabricsSupportsCarryItsWeight) {
  for (const double crimp : {0.0, 0.05}) {
    SimulationParameters p;
    p.air_damping = 0.05;
    FabricSpec spec = cottonPatch(10, 8, 0.05, 0.04);
    spec.warp_crimp = crimp;
    spec.weft_crimp = crimp;
    Simulator sim(p, {}, {spec});
    for (int i = 0; i < 3000; ++i) {
      sim.step();
      ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    }
    double weight = 0.0;
    for (double m : sim.scene().vertices.mass) weight += m * kGravity;
    const Eigen::Vector3d support = rowSupport(sim, 0);
    EXPECT_NEAR(-support.z(), weight, 0.005 * weight) << "crimp " << crimp;
    EXPECT_NEAR(support.x(), 0.0, 0.005 * weight);
    EXPECT_NEAR(support.y(), 0.0, 0.005 * weight);
  }
}

/// Draws a strip's last row along the warp at `speed` [m/s] (first row pinned) until it has torn
/// apart; returns the largest pull the last row's grips felt before the first break [N] and the
/// events. (In the step of a break the edge has reached its breaking length, where the length
/// constraint is a stop 10^6 times stiffer than the yarn: that step's support force is the stop's
/// and is not a load the fabric carried; doc/method.md, "Breaking-length stop".)
double pullStripUntilTorn(Simulator& sim, double speed, std::vector<TearEvent>& events) {
  const Scene& scene = sim.scene();
  const Fabric& fabric = scene.fabrics[0];
  const Eigen::Vector3d warp(0.0, 0.0, -1.0);
  const std::vector<std::uint32_t> grip = lastRow(scene);
  const std::vector<Eigen::Vector3d> start = positionsOf(scene, grip);
  double peak = 0.0;
  const double dt = sim.parameters().time_step;
  for (int i = 1; i < 200000 && events.size() < fabric.ends; ++i) {
    for (std::size_t k = 0; k < grip.size(); ++k) {
      sim.setKinematicTarget(grip[k], start[k] + speed * i * dt * warp);
    }
    sim.step();
    EXPECT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    const std::vector<TearEvent> now = sim.takeTearEvents();
    if (events.empty() && now.empty()) peak = std::max(peak, -rowSupport(sim, -1).dot(warp));
    events.insert(events.end(), now.begin(), now.end());
  }
  return peak;
}

TEST(FabricLoading, StripPulledAlongTheWarpTearsAtTheWarpYarnsBreakingForceTimesTheirNumber) {
  for (const double crimp : {0.0, 0.04}) {
    SimulationParameters p;
    p.gravity.setZero();
    FabricSpec spec = cottonPatch(6, 9, 0.025, 0.04);
    spec.warp_crimp = crimp;
    spec.weft_crimp = crimp;
    Simulator sim(p, {}, {spec});
    std::vector<TearEvent> events;
    const double peak = pullStripUntilTorn(sim, 0.01, events);
    const double expected = spec.ends * breakingForce(spec.warp);
    EXPECT_NEAR(peak, expected, 0.05 * expected) << "crimp " << crimp;
    // It tears across the warp: each warp yarn once, no weft segment.
    ASSERT_EQ(events.size(), static_cast<std::size_t>(spec.ends));
    std::vector<int> per_yarn(spec.ends, 0);
    for (const TearEvent& e : events) {
      EXPECT_EQ(e.fabric, 0);
      EXPECT_EQ(e.segment.family, FabricFamily::kWarp);
      ++per_yarn[e.segment.yarn];
      EXPECT_LE(e.tension, breakingForce(spec.warp) * (1.0 + 1e-12));
    }
    for (int count : per_yarn) EXPECT_EQ(count, 1);
  }
}

}  // namespace
}  // namespace yarn_tearing::test
