// Yield (paper §3.4): past the yield point the rest length grows for good; below it, it does not.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

/// Vertex 0 pinned, no gravity, force along +x on the last vertex.
struct LoadedYarn {
  explicit LoadedYarn(const Material& material)
      : spec(makeSpec(material)), sim(parametersWithoutGravity(), {spec}) {}
  static YarnSpec makeSpec(const Material& material) {
    YarnSpec s = hangingYarn(material);
    s.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
    return s;
  }
  std::uint32_t end() const { return static_cast<std::uint32_t>(sim.scene().vertices.size() - 1); }
  /// Ramps the end force linearly from its current value to `force` [N] over `duration` [s].
  void rampTo(double force, double duration) {
    const double from = sim.scene().vertices.applied_force[end()].x();
    const double start = sim.time();
    while (sim.time() < start + duration) {
      const double s = std::min(1.0, (sim.time() - start + sim.parameters().time_step) / duration);
      sim.setAppliedForce(end(), Eigen::Vector3d(from + s * (force - from), 0.0, 0.0));
      sim.step();
      breaks += sim.takeTearEvents().size();
    }
  }
  void hold(double duration) { rampTo(sim.scene().vertices.applied_force[end()].x(), duration); }
  YarnSpec spec;
  Simulator sim;
  std::size_t breaks = 0;
};

TEST(Plasticity, LoadedPastYieldAndUnloadedKeepsThePermanentElongation) {
  const Material material = cottonLike();
  const double area = kPi * 1.0e-8;
  const double peak_stress = 0.5 * (material.curve.yieldStress() + material.curve.breakingStress());
  // Closed form: eps_p = eps(sigma) - sigma / E on the piecewise-linear curve.
  const double expected_plastic =
      material.curve.strainAtStress(peak_stress) - peak_stress / material.curve.youngsModulus();
  ASSERT_GT(expected_plastic, 0.003);
  const double residual_force = 0.001 * material.curve.yieldStress() * area;  // keeps it straight
  LoadedYarn yarn(material);
  yarn.rampTo(peak_stress * area, 1.0);
  yarn.rampTo(residual_force, 0.5);
  yarn.hold(0.5);
  const double residual_elastic = residual_force / (material.curve.youngsModulus() * area);
  const double expected_length = yarn.spec.length * (1.0 + expected_plastic + residual_elastic);
  const double elongation = yarnLength(yarn.sim) - yarn.spec.length;
  EXPECT_NEAR(elongation, expected_length - yarn.spec.length,
              0.02 * (expected_length - yarn.spec.length));
  EXPECT_NEAR(yarn.sim.scene().edges.plastic_strain[7], expected_plastic, 0.02 * expected_plastic);
  EXPECT_EQ(yarn.breaks, 0u);
}

TEST(Plasticity, LoadedBelowYieldReturnsToItsLength) {
  const Material material = cottonLike();
  const double area = kPi * 1.0e-8;
  const double residual_force = 0.001 * material.curve.yieldStress() * area;  // keeps it straight
  LoadedYarn yarn(material);
  yarn.rampTo(0.9 * material.curve.yieldStress() * area, 1.0);
  const double loaded = yarnLength(yarn.sim);
  yarn.rampTo(residual_force, 0.5);
  yarn.hold(0.5);
  const double expected = 0.9 * material.curve.yieldStrain() * yarn.spec.length;
  EXPECT_NEAR(loaded - yarn.spec.length, expected, 0.02 * expected);
  const double residual_elastic = residual_force / (material.curve.youngsModulus() * area);
  EXPECT_NEAR(yarnLength(yarn.sim), yarn.spec.length * (1.0 + residual_elastic), 0.02 * expected);
  EXPECT_EQ(yarn.sim.scene().edges.plastic_strain[7], 0.0);
}

/// Plastic strain at break [-] when the end force rises at `rate` [N/s].
double plasticStrainAtBreak(const Material& material, double rate) {
  LoadedYarn yarn(material);
  const double breaking_force = material.curve.breakingStress() * kPi * 1.0e-8;
  while (yarn.sim.time() < 100.0 * breaking_force / rate) {
    yarn.sim.setAppliedForce(
        yarn.end(),
        Eigen::Vector3d(rate * (yarn.sim.time() + yarn.sim.parameters().time_step), 0.0, 0.0));
    yarn.sim.step();
    const std::vector<TearEvent> events = yarn.sim.takeTearEvents();
    if (!events.empty()) return events[0].plastic_strain;
  }
  ADD_FAILURE() << "no break";
  return 0.0;
}

TEST(Plasticity, WithoutRateSensitivityPlasticStrainAtBreakIsRateIndependent) {
  const Material material = cottonLike();
  const double breaking_force = material.curve.breakingStress() * kPi * 1.0e-8;
  const double fast_rate = breaking_force / 0.5;
  const double fast = plasticStrainAtBreak(material, fast_rate);
  const double slow = plasticStrainAtBreak(material, fast_rate / 10.0);
  // The break is detected on the first step at or past the breaking stress, so each run may
  // overshoot by one step's force increment; bound the difference by the fast run's increment
  // times the plastic compliance 1/H - 1/E of the last segment (H its slope).
  const auto& p = material.curve.points();
  const double hardening = (p[2].stress - p[1].stress) / (p[2].strain - p[1].strain);
  const double plastic_compliance = 1.0 / hardening - 1.0 / material.curve.youngsModulus();
  const double step_increment = fast_rate * 1.0e-3 / (kPi * 1.0e-8);  // [Pa]
  EXPECT_NEAR(fast, slow, step_increment * plastic_compliance);
  const double closed_form = material.curve.breakingStrain() -
                             material.curve.breakingStress() / material.curve.youngsModulus();
  EXPECT_NEAR(slow, closed_form, step_increment * plastic_compliance);
}

}  // namespace
}  // namespace yarn_tearing::test
