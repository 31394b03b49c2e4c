// Break events report the edge's state at the tear (tearEventOf): never more strain than the
// edge's breaking strain, never more stress than that strain carries on the curve, however
// violently the yarn is torn; a slow pull still reports sigma_b * A at eps_b.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

/// Checks an event against the rule: strain <= the edge's breaking strain, stress <= curve(strain)
/// <= sigma_b, tension = stress * area, all finite.
void expectStateAtTear(const Simulator& sim, const TearEvent& event) {
  const Scene& scene = sim.scene();
  const Yarn& yarn = scene.yarns[event.yarn];
  const std::size_t e = yarn.first_edge + event.edge;
  const StressStrainCurve& curve = yarn.material.curve;
  const double breaking_strain = scene.edges.breaking_strain[e];
  EXPECT_LE(event.strain, breaking_strain);
  EXPECT_GE(event.stress, 0.0);
  EXPECT_LE(event.stress, curve.stressAtStrain(event.strain) * (1.0 + 1.0e-12));
  EXPECT_LE(event.stress, curve.stressAtStrain(breaking_strain) * (1.0 + 1.0e-12));
  EXPECT_DOUBLE_EQ(event.tension, event.stress * scene.edges.area[e]);
  EXPECT_TRUE(std::isfinite(event.strain_rate));
}

YarnSpec horizontalYarn() {
  YarnSpec spec = hangingYarn();
  spec.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  return spec;
}

TEST(StateAtTear, ThousandNewtonForceReportsAtMostTheBreakingPoint) {
  // 1e3 N on a cotton yarn of ~15 N strength reported strain 3.3.
  Simulator sim(parametersWithoutGravity(), {horizontalYarn()});
  sim.setAppliedForce(sim.scene().globalVertex(0, -1), Eigen::Vector3d(1.0e3, 0.0, 0.0));
  std::vector<TearEvent> events;
  for (int i = 0; i < 50; ++i) {
    sim.step();
    for (const TearEvent& e : sim.takeTearEvents()) events.push_back(e);
  }
  ASSERT_FALSE(events.empty());
  for (const TearEvent& e : events) expectStateAtTear(sim, e);
  // The first tear: the edge was stopped at its breaking length, so it reports the breaking point.
  const StressStrainCurve& curve = cottonLike().curve;
  EXPECT_NEAR(events[0].strain, curve.breakingStrain(), 1.0e-3 * curve.breakingStrain());
  EXPECT_NEAR(events[0].stress, curve.breakingStress(), 0.02 * curve.breakingStress());
}

TEST(StateAtTear, GraspThatJumpsReportsAtMostTheBreakingPoint) {
  // A grasp target jumping in one cycle reported strain 0.595, 4.5 GPa, 141 N.
  YarnSpec spec = horizontalYarn();
  spec.pinned = {0};
  Simulator sim(parametersWithoutGravity(), {spec});
  const std::uint32_t end = sim.scene().globalVertex(0, -1);
  std::vector<TearEvent> events;
  for (int i = 0; i < 20; ++i) {
    sim.setKinematicTarget(end, Eigen::Vector3d(0.3 + 0.05 * (i + 1), 0.0, 0.0));  // 50 m/s
    sim.step();
    for (const TearEvent& e : sim.takeTearEvents()) events.push_back(e);
  }
  ASSERT_FALSE(events.empty());
  for (const TearEvent& e : events) expectStateAtTear(sim, e);
}

TEST(StateAtTear, SlowPullReportsBreakingStressAtBreakingStrain) {
  // Displacement control at 1 mm/s: estimate and length agree; the event is the breaking point.
  YarnSpec spec = horizontalYarn();
  spec.num_vertices = 7;
  Simulator sim(parametersWithoutGravity(), {spec});
  const std::uint32_t end = sim.scene().globalVertex(0, -1);
  std::vector<TearEvent> events;
  while (events.empty() && sim.time() < 30.0) {
    sim.setKinematicTarget(end, Eigen::Vector3d(0.3 + 1.0e-3 * (sim.time() + 1.0e-3), 0.0, 0.0));
    sim.step();
    events = sim.takeTearEvents();
  }
  ASSERT_EQ(events.size(), 1u);
  expectStateAtTear(sim, events[0]);
  const StressStrainCurve& curve = cottonLike().curve;
  EXPECT_NEAR(events[0].strain, curve.breakingStrain(), 0.01 * curve.breakingStrain());
  EXPECT_NEAR(events[0].tension, curve.breakingStress() * kPi * 1.0e-8,
              0.01 * curve.breakingStress() * kPi * 1.0e-8);
}

}  // namespace
}  // namespace yarn_tearing::test
