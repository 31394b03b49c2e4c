// A yarn pulled by F at both ends (no gravity) carries F everywhere and stretches by F L / (E A).
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

struct PulledYarn {
  explicit PulledYarn(double force, const Material& material = cottonLike(),
                      const SimulationParameters& p = parametersWithoutGravity())
      : spec(makeSpec(material)), sim(p, {spec}) {
    const auto last = static_cast<std::uint32_t>(sim.scene().vertices.size() - 1);
    sim.setAppliedForce(0, Eigen::Vector3d(-force, 0.0, 0.0));
    sim.setAppliedForce(last, Eigen::Vector3d(force, 0.0, 0.0));
  }
  static YarnSpec makeSpec(const Material& material) {
    YarnSpec s = hangingYarn(material);
    s.pinned.clear();
    s.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
    return s;
  }
  YarnSpec spec;
  Simulator sim;
};

TEST(PulledYarn, CarriesTheForceUniformlyAndStretchesByHookesLaw) {
  const Material material = cottonLike();
  const double area = kPi * 1.0e-4 * 1.0e-4;
  const double force = 0.5 * material.curve.yieldStress() * area;  // elastic range
  PulledYarn pulled(force);
  for (int i = 0; i < 2000; ++i) pulled.sim.step();

  const EdgeSet& edges = pulled.sim.scene().edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    EXPECT_NEAR(edges.tension[e], force, 0.005 * force) << "edge " << e;
  }
  const double stretch = yarnLength(pulled.sim) - pulled.spec.length;
  const double expected = force * pulled.spec.length / (material.curve.youngsModulus() * area);
  EXPECT_NEAR(stretch, expected, 0.01 * expected);
  EXPECT_NEAR(edges.strain_limit[5], force / (material.curve.youngsModulus() * area),
              0.005 * expected / pulled.spec.length);
}

TEST(PulledYarn, NoLoadMeansNoStretch) {
  PulledYarn pulled(0.0);
  for (int i = 0; i < 100; ++i) pulled.sim.step();
  EXPECT_NEAR(yarnLength(pulled.sim), pulled.spec.length, 1e-12);
  EXPECT_NEAR(pulled.sim.scene().edges.strain_limit[3], 0.0, 1e-15);  // round-off only
}

TEST(PulledYarn, MomentumIsConservedAcrossABreak) {
  const Material material = cottonLike();
  const double area = kPi * 1.0e-4 * 1.0e-4;
  const double force = 1.5 * material.curve.breakingStress() * area;
  PulledYarn pulled(force);
  const double scale = force * 0.01;  // impulse of the end force over 10 ms [N s]
  bool broke = false;
  for (int i = 0; i < 10; ++i) {
    pulled.sim.step();
    broke = broke || !pulled.sim.takeTearEvents().empty();
    EXPECT_LT(momentum(pulled.sim).norm(), 1e-12 * scale) << "step " << i;
  }
  EXPECT_TRUE(broke);
}

TEST(PulledYarn, FreeMotionConservesMomentum) {
  PulledYarn pulled(0.0);
  Simulator& sim = pulled.sim;
  for (std::uint32_t v = 0; v < sim.scene().vertices.size(); ++v) {
    sim.setVelocity(v, Eigen::Vector3d(std::sin(v), std::cos(3.0 * v), 0.1 * v));
  }
  const Eigen::Vector3d before = momentum(sim);
  for (int i = 0; i < 1000; ++i) sim.step();
  EXPECT_LT((momentum(sim) - before).norm(), 1e-12 * before.norm());
  EXPECT_LE(sim.lastHealth().max_constraint_violation, sim.parameters().constraint_tolerance);
}

}  // namespace
}  // namespace yarn_tearing::test
