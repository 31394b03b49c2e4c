// Live tuning (Simulator::setParameters, used by the node's dynamic_reconfigure): new parameters
// act from the next step; invalid ones are refused and the old ones kept.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

TEST(LiveParameters, InvalidParametersAreRefusedAndTheOldOnesKept) {
  Simulator sim(parametersWithoutGravity(), {hangingYarn()});
  SimulationParameters bad = sim.parameters();
  bad.regularization = 1.0;  // allowed: [0, 1)
  EXPECT_THROW(sim.setParameters(bad), std::invalid_argument);
  EXPECT_EQ(sim.parameters().regularization, SimulationParameters{}.regularization);
}

TEST(LiveParameters, AThreadCountBelowOneIsRefusedByName) {
  Simulator sim(parametersWithoutGravity(), {hangingYarn()});
  SimulationParameters bad = sim.parameters();
  bad.threads = 0;  // allowed: [1, 1024]
  try {
    sim.setParameters(bad);
    ADD_FAILURE() << "threads 0 was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("threads"), std::string::npos) << e.what();
  }
  EXPECT_EQ(sim.parameters().threads, 1);
}

// A free yarn moving rigidly (no gravity, no holder) under linear air damping c per unit length
// decays as dv/dt = -(c / (rho A)) v: v(t) = v0 exp(-c t / (rho A)). Damping switched on live after
// 0.5 s of undamped motion must give exactly that from the switch on.
TEST(LiveParameters, AirDampingSwitchedOnLiveDecaysTheVelocityExponentially) {
  YarnSpec spec = hangingYarn();
  spec.pinned.clear();
  Simulator sim(parametersWithoutGravity(), {spec});
  const double v0 = 0.2;  // [m/s] along x, across the yarn
  for (std::uint32_t v = 0; v < sim.scene().vertices.size(); ++v) {
    sim.setVelocity(v, Eigen::Vector3d(v0, 0.0, 0.0));
  }
  while (sim.time() < 0.5 - 1e-9) {
    sim.step();
  }
  EXPECT_NEAR(sim.scene().vertices.velocity[0].x(), v0, 1e-12 * v0);

  const double rate = 2.0;  // [1/s] c / (rho A)
  SimulationParameters damped = sim.parameters();
  damped.air_damping = rate * spec.material.density * kPi * spec.radius * spec.radius;
  sim.setParameters(damped);
  const double switched_at = sim.time();
  while (sim.time() < 1.5 - 1e-9) {
    sim.step();
  }
  const double expected = v0 * std::exp(-rate * (sim.time() - switched_at));
  // explicit damping: (1 - k dt)^n differs from exp(-k t) by about k^2 dt t / 2 = 2e-3 relative
  for (std::uint32_t v = 0; v < sim.scene().vertices.size(); ++v) {
    EXPECT_NEAR(sim.scene().vertices.velocity[v].x(), expected, 3e-3 * expected) << "vertex " << v;
  }
}

TEST(LiveParameters, BreakingSwitchedOnLiveTearsAnOverloadedYarn) {
  Simulator sim(parametersWithoutGravity(), {hangingYarn()});
  const auto last = static_cast<std::uint32_t>(sim.scene().vertices.size() - 1);
  const double breaking_force = 4.86e8 * kPi * 1.0e-8;  // [N] sigma_b pi r^2 of cottonLike
  SimulationParameters unbreakable = sim.parameters();
  unbreakable.breaking_enabled = false;
  sim.setParameters(unbreakable);
  sim.setAppliedForce(last, Eigen::Vector3d(0.0, 0.0, -2.0 * breaking_force));
  for (int i = 0; i < 200; ++i) {
    sim.step();
  }
  EXPECT_TRUE(sim.takeTearEvents().empty());
  SimulationParameters breakable = sim.parameters();
  breakable.breaking_enabled = true;
  sim.setParameters(breakable);
  sim.step();
  EXPECT_EQ(sim.takeTearEvents().size(), 1U);
}

}  // namespace
}  // namespace yarn_tearing::test
