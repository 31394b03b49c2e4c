// Breaking: a slowly rising force tears the yarn at sigma_b * pi r^2; 95 % of it never does.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

/// Top pinned, no gravity, force along +x rising at `rate` [N/s] on the last vertex.
struct RampedYarn {
  RampedYarn(const Material& material, double rate) : RampedYarn(makeSpec(material), rate) {}
  RampedYarn(const YarnSpec& yarn, double rate)
      : spec(yarn), sim(parametersWithoutGravity(), {spec}), rate(rate) {}
  static YarnSpec makeSpec(const Material& material) {
    YarnSpec s = hangingYarn(material);
    s.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
    return s;
  }
  /// Sets a constant force [N] along +x on the last vertex.
  void pullEnd(double force) {
    const auto last = static_cast<std::uint32_t>(sim.scene().vertices.size() - 1);
    sim.setAppliedForce(last, Eigen::Vector3d(force, 0.0, 0.0));
  }
  /// Steps until the first break or `max_time` [s]; returns the events.
  std::vector<TearEvent> runUntilBreak(double max_time) {
    const auto last = static_cast<std::uint32_t>(sim.scene().vertices.size() - 1);
    while (sim.time() < max_time) {
      sim.setAppliedForce(
          last, Eigen::Vector3d(rate * (sim.time() + sim.parameters().time_step), 0.0, 0.0));
      sim.step();
      std::vector<TearEvent> events = sim.takeTearEvents();
      if (!events.empty()) return events;
    }
    return {};
  }
  YarnSpec spec;
  Simulator sim;
  double rate;
};

TEST(Breaking, SlowRampBreaksAtBreakingStressTimesArea) {
  const Material material = cottonLike();
  const double breaking_force = material.curve.breakingStress() * kPi * 1.0e-8;
  RampedYarn ramp(material, breaking_force / 2.0);  // reaches it after 2 s
  const std::vector<TearEvent> events = ramp.runUntilBreak(4.0);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NEAR(events[0].tension, breaking_force, 0.01 * breaking_force);
  EXPECT_NEAR(events[0].time, 2.0, 0.02);
  EXPECT_NEAR(events[0].strain, material.curve.breakingStrain(), 0.01 * 0.071);
  EXPECT_EQ(events[0].vertex_b, events[0].vertex_a + 1);
  EXPECT_EQ(events[0].edge, events[0].vertex_a);
}

TEST(Breaking, HeldAt95PercentForTenSecondsDoesNotBreak) {
  const Material material = cottonLike();
  const double force = 0.95 * material.curve.breakingStress() * kPi * 1.0e-8;
  RampedYarn ramp(material, 0.0);
  ramp.pullEnd(force);
  std::size_t events = 0;
  while (ramp.sim.time() < 10.0) {
    ramp.sim.step();
    events += ramp.sim.takeTearEvents().size();
  }
  EXPECT_EQ(events, 0u);
  EXPECT_NEAR(ramp.sim.scene().edges.tension[10], force, 0.005 * force);
}

TEST(Breaking, WeakerYarnBreaksFirstUnderTheSameForce) {
  // The paper's Figure 4: lower modulus and breaking point tear earlier.
  YarnSpec weak = RampedYarn::makeSpec(weakLike());
  weak.name = "weak";
  YarnSpec strong = RampedYarn::makeSpec(cottonLike());
  strong.name = "strong";
  strong.start = Eigen::Vector3d(0.0, 0.1, 0.0);
  Simulator sim(parametersWithoutGravity(), {weak, strong});
  const std::uint32_t weak_end = sim.scene().globalVertex(0, -1);
  const std::uint32_t strong_end = sim.scene().globalVertex(1, -1);
  const double rate = 5.0;  // [N/s]
  // The force stays on each free end, so a torn yarn's pulled piece may tear again; what counts
  // is the first tear of each yarn.
  std::vector<TearEvent> first_of_yarn;
  std::vector<bool> torn(2, false);
  while (sim.time() < 5.0 && !(torn[0] && torn[1])) {
    const Eigen::Vector3d f(rate * (sim.time() + 1e-3), 0.0, 0.0);
    sim.setAppliedForce(weak_end, f);
    sim.setAppliedForce(strong_end, f);
    sim.step();
    for (const TearEvent& e : sim.takeTearEvents()) {
      if (torn[e.yarn]) continue;
      torn[e.yarn] = true;
      first_of_yarn.push_back(e);
    }
  }
  ASSERT_EQ(first_of_yarn.size(), 2u);
  EXPECT_EQ(first_of_yarn[0].yarn, 0u);
  EXPECT_EQ(first_of_yarn[1].yarn, 1u);
  EXPECT_LT(first_of_yarn[0].time, first_of_yarn[1].time);
  EXPECT_NEAR(first_of_yarn[0].tension, weakLike().curve.breakingStress() * kPi * 1e-8,
              0.01 * first_of_yarn[0].tension);
  EXPECT_NEAR(first_of_yarn[1].tension, cottonLike().curve.breakingStress() * kPi * 1e-8,
              0.01 * first_of_yarn[1].tension);
}

TEST(Breaking, EachPieceTearsAtMostOnceAStep) {
  // 1000 times the breaking force: the yarn shatters, but one edge per piece per step, cleanly.
  const Material material = cottonLike();
  const double force = 1000.0 * material.curve.breakingStress() * kPi * 1.0e-8;
  RampedYarn ramp(material, 0.0);
  ramp.pullEnd(force);
  ramp.sim.step();
  EXPECT_EQ(ramp.sim.takeTearEvents().size(), 1u);
  for (int i = 0; i < 200; ++i) {
    ramp.sim.step();
    ASSERT_TRUE(allFinite(ramp.sim)) << "step " << i;
    EXPECT_LE(ramp.sim.lastHealth().max_constraint_violation, 1e-6) << "step " << i;
  }
}

TEST(Breaking, ResetForgetsTheUnloadingOfEarlierTears) {
  // A piece does not tear again while a tear's unloading wave crosses it; a reset starts a new
  // history: the same pull tears the yarn at the same instant again.
  RampedYarn ramp(cottonLike(), 20.0);
  const std::vector<TearEvent> first = ramp.runUntilBreak(2.0);
  ASSERT_EQ(first.size(), 1u);
  ramp.sim.reset();
  const std::vector<TearEvent> again = ramp.runUntilBreak(2.0);
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].time, first[0].time);
  EXPECT_EQ(again[0].edge, first[0].edge);
}

TEST(Breaking, OverloadHoldsEveryEdgeAtMostAtItsBreakingLength) {
  // 1000 times the breaking force F in one step: every edge stops at its breaking length
  // L0 (1 + eps_b) (plus what the stop, 10^6 times stiffer than the yarn, gives under F:
  // 1e-6 F L0 / (E A), and the projection tolerance) instead of stretching elastically by
  // F / (E A) = 64 times its length, and one edge tears.
  const Material material = cottonLike();
  const StressStrainCurve& curve = material.curve;
  const double area = kPi * 1.0e-8;
  const double force = 1000.0 * curve.breakingStress() * area;
  RampedYarn ramp(material, 0.0);
  ramp.pullEnd(force);
  ramp.sim.step();
  EXPECT_EQ(ramp.sim.takeTearEvents().size(), 1u);
  const Scene& scene = ramp.sim.scene();
  for (std::size_t e = 0; e < scene.edges.size(); ++e) {
    const double original = scene.edges.original_rest_length[e];
    const double breaking_length = original * (1.0 + curve.breakingStrain());
    const double stop_give = 1e-6 * force * original / (curve.youngsModulus() * area);
    const double length = (scene.vertices.position[scene.edges.vertex_b[e]] -
                           scene.vertices.position[scene.edges.vertex_a[e]])
                              .norm();
    EXPECT_LE(length, (breaking_length + stop_give) * (1.0 + 1e-6)) << "edge " << e;
  }
}

TEST(Breaking, OverloadLeavesNoPlasticStrainPastTheBreakingPoint) {
  // 1000 times the breaking force on the end of a pinned yarn, then 200 steps. Edges that were
  // overloaded in a step in which their piece tore elsewhere must not keep the plastic strain
  // of a stress beyond the breaking point: at most eps_b - sigma_b / E, the curve's own.
  const Material material = cottonLike();
  const StressStrainCurve& curve = material.curve;
  const double plastic_at_break =
      curve.breakingStrain() - curve.breakingStress() / curve.youngsModulus();
  RampedYarn ramp(material, 0.0);
  ramp.pullEnd(1000.0 * curve.breakingStress() * kPi * 1.0e-8);
  for (int i = 0; i < 200; ++i) ramp.sim.step();
  const EdgeSet& edges = ramp.sim.scene().edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    EXPECT_LE(edges.plastic_strain[e], plastic_at_break * (1.0 + 1e-12)) << "edge " << e;
    EXPECT_LE(edges.rest_length[e],
              edges.original_rest_length[e] * (1.0 + plastic_at_break) * (1.0 + 1e-12))
        << "edge " << e;
  }
}

TEST(Breaking, LargeTimeStepStaysFiniteAndTearsCleanly) {
  const Material material = cottonLike();
  YarnSpec spec = hangingYarn(material);
  spec.end_mass = 0.05;
  SimulationParameters p;
  p.time_step = 1.0 / 60.0;
  Simulator sim(p, {spec});
  const auto last = static_cast<std::uint32_t>(sim.scene().vertices.size() - 1);
  std::size_t breaks = 0;
  for (int i = 0; i < 600; ++i) {
    sim.setAppliedForce(last, Eigen::Vector3d(0.0, 0.0, -2.0 * sim.time()));
    sim.step();
    breaks += sim.takeTearEvents().size();
    ASSERT_TRUE(allFinite(sim)) << "step " << i;
    EXPECT_LE(sim.lastHealth().max_constraint_violation, 1e-6) << "step " << i;
  }
  EXPECT_GE(breaks, 1u);
}

TEST(Breaking, SameInputsGiveBitwiseSameOutputs) {
  auto run = [] {
    YarnSpec spec = RampedYarn::makeSpec(cottonLike());
    spec.strength_scatter.weibull_modulus = 8.0;
    spec.strength_scatter.seed = 42;
    RampedYarn ramp(spec, 8.0);
    return ramp.runUntilBreak(5.0);
  };
  const std::vector<TearEvent> a = run();
  const std::vector<TearEvent> b = run();
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(a[0].edge, b[0].edge);
  EXPECT_EQ(a[0].time, b[0].time);
  EXPECT_EQ(a[0].tension, b[0].tension);
  EXPECT_EQ(a[0].position, b[0].position);
}

TEST(Breaking, StrengthScatterChoosesTheWeakestEdge) {
  YarnSpec spec = RampedYarn::makeSpec(cottonLike());
  spec.strength_scatter.weibull_modulus = 8.0;
  spec.strength_scatter.seed = 7;
  RampedYarn ramp(spec, 8.0);
  const EdgeSet& edges = ramp.sim.scene().edges;
  std::size_t weakest = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (edges.strength_factor[e] < edges.strength_factor[weakest]) weakest = e;
  }
  const std::vector<TearEvent> events = ramp.runUntilBreak(5.0);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].edge, weakest);
}

}  // namespace
}  // namespace yarn_tearing::test
