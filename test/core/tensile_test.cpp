// A tensile test: one end pinned, the other grasped (kinematic) and drawn away at constant speed.
// The taut span between the two holders moves no free vertex sideways, so its tension comes from
// the constraint force; it must still tear at sigma_b * pi r^2 and at the breaking strain.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

TEST(Tensile, DrawnAtConstantSpeedTearsAtTheBreakingPoint) {
  const Material material = cottonLike();
  YarnSpec spec = hangingYarn(material);
  spec.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  Simulator sim(parametersWithoutGravity(), {spec});
  const std::uint32_t grasped = sim.scene().globalVertex(0, -1);
  const Eigen::Vector3d start = sim.scene().vertices.position[grasped];
  const double speed = 0.02;  // [m/s]: strain rate 0.067 /s
  std::vector<TearEvent> events;
  while (events.empty() && sim.time() < 3.0) {
    const double t = sim.time() + sim.parameters().time_step;
    sim.setKinematicTarget(grasped, start + Eigen::Vector3d(speed * t, 0.0, 0.0));
    sim.step();
    events = sim.takeTearEvents();
    // Both holders feel the tension of the yarn between them.
    if (events.empty()) {
      EXPECT_NEAR(sim.supportForce(0).x(), sim.scene().edges.tension[0], 1e-6);
    }
  }
  ASSERT_EQ(events.size(), 1u);
  const double breaking_force = material.curve.breakingStress() * kPi * 1.0e-8;
  EXPECT_NEAR(events[0].tension, breaking_force, 0.01 * breaking_force);
  EXPECT_NEAR(events[0].strain, material.curve.breakingStrain(),
              0.01 * material.curve.breakingStrain());
  // The imposed elongation at the break is the breaking strain (elastic + plastic) times L0.
  EXPECT_NEAR(speed * events[0].time, material.curve.breakingStrain() * spec.length,
              0.02 * material.curve.breakingStrain() * spec.length);
}

}  // namespace
}  // namespace yarn_tearing::test
