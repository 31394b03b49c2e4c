// Yielding materials tear at their breaking force whatever the time step: a 0.3 m, 25-vertex
// yarn pinned at one end is pulled to its break in about 2 s, by a force ramp on its free end
// and by a grasp drawing that end away at constant speed. The closed forms: the event's tension
// is sigma_b * pi r^2, its strain the curve's breaking strain, and the drawn end has moved
// eps_b * L0 when it tears. And a 4 x 5 strip of the material's plain weave, first row pinned,
// last row grasped and drawn along the warp: a warp segment tears at sigma_b * pi r^2 once the
// strip is (1 + crimp)(1 + eps_b) times its length. Each preset of config/materials.yaml.
#include <gtest/gtest.h>

#include <tuple>

#include "fabric_support.hpp"
#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

/// The presets' curves (config/materials.yaml).
Material preset(const std::string& name) {
  if (name == "cotton") {
    return fibre("cotton", {{0.0, 0.0}, {0.015, 1.14e8}, {0.04, 2.85e8}, {0.071, 4.86e8}});
  }
  if (name == "polyester") {
    return fibre("polyester", {{0.0, 0.0}, {0.015, 2.21e8}, {0.06, 3.30e8}, {0.15, 6.53e8}});
  }
  if (name == "nylon66") {
    return fibre("nylon66", {{0.0, 0.0}, {0.025, 8.55e7}, {0.10, 2.60e8}, {0.20, 5.47e8}});
  }
  return fibre("wool", {{0.0, 0.0}, {0.0248, 7.47e7}, {0.30, 1.00e8}, {0.425, 1.44e8}});
}

enum class Pull { kForceRamp, kDrawnEnd };

using Case = std::tuple<std::string, Pull, double>;

class YieldingStrength : public ::testing::TestWithParam<Case> {};

TEST_P(YieldingStrength, TearsAtTheBreakingForceAtAnyStep) {
  const auto& [name, pull, dt] = GetParam();
  const Material material = preset(name);
  const StressStrainCurve& curve = material.curve;
  const double area = kPi * 1.0e-8;
  const double breaking_force = curve.breakingStress() * area;
  YarnSpec spec = hangingYarn(material);
  spec.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  Simulator sim(parametersWithoutGravity(dt), {spec});
  const std::uint32_t end = sim.scene().globalVertex(0, -1);
  const Eigen::Vector3d start = sim.scene().vertices.position[end];
  const double duration = 2.0;                                           // [s] to the break
  const double speed = curve.breakingStrain() * spec.length / duration;  // [m/s]
  std::vector<TearEvent> events;
  while (events.empty() && sim.time() < 2.0 * duration) {
    const double t = sim.time() + dt;
    if (pull == Pull::kForceRamp) {
      sim.setAppliedForce(end, Eigen::Vector3d(breaking_force * t / duration, 0.0, 0.0));
    } else {
      sim.setKinematicTarget(end, start + Eigen::Vector3d(speed * t, 0.0, 0.0));
    }
    sim.step();
    events = sim.takeTearEvents();
  }
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NEAR(events[0].tension, breaking_force, 0.005 * breaking_force);
  EXPECT_NEAR(events[0].strain, curve.breakingStrain(), 0.005 * curve.breakingStrain());
  if (pull == Pull::kDrawnEnd) {
    // The end reaches eps_b L0 within one step's travel.
    EXPECT_NEAR(speed * events[0].time, curve.breakingStrain() * spec.length,
                speed * dt + 0.005 * curve.breakingStrain() * spec.length);
  }
}

/// stepName, and "dt1over60" for 1/60 s.
std::string stepOrFrameName(double dt) {
  return dt > 0.015 ? std::string("dt1over60") : stepName(dt);
}

std::string pullCaseName(const ::testing::TestParamInfo<Case>& info) {
  const auto& [name, pull, dt] = info.param;
  return name + (pull == Pull::kForceRamp ? "_force_" : "_drawn_") + stepOrFrameName(dt);
}

using FabricCase = std::tuple<std::string, double>;

class YieldingFabricStrength : public ::testing::TestWithParam<FabricCase> {};

TEST_P(YieldingFabricStrength, StripTearsAtTheBreakingForceAtAnyStep) {
  const auto& [name, dt] = GetParam();
  const double crimp = 0.02;
  FabricSpec spec = cottonPatch(4, 5, 0.03, 0.04);
  spec.warp.material = preset(name);
  spec.weft.material = preset(name);
  spec.warp_crimp = crimp;
  spec.weft_crimp = crimp;
  const StressStrainCurve& curve = spec.warp.material.curve;
  const double breaking_force = breakingForce(spec.warp);
  const double drawn = spec.warp_length * ((1.0 + crimp) * (1.0 + curve.breakingStrain()) - 1.0);
  const double speed = drawn / 2.0;  // [m/s]: torn after about 2 s
  Simulator sim(parametersWithoutGravity(dt), {}, {spec});
  const std::vector<std::uint32_t> grips = lastRow(sim.scene());
  const std::vector<Eigen::Vector3d> start = positionsOf(sim.scene(), grips);
  std::vector<TearEvent> events;
  while (events.empty() && sim.time() < 4.0) {
    const double t = sim.time() + dt;
    for (std::size_t i = 0; i < grips.size(); ++i) {
      sim.setKinematicTarget(grips[i], start[i] + Eigen::Vector3d(0.0, 0.0, -speed * t));
    }
    sim.step();
    events = sim.takeTearEvents();
  }
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events[0].segment.family, FabricFamily::kWarp);
  EXPECT_NEAR(events[0].tension, breaking_force, 0.005 * breaking_force);
  EXPECT_NEAR(events[0].strain, curve.breakingStrain(), 0.005 * curve.breakingStrain());
  EXPECT_NEAR(speed * events[0].time, drawn, speed * dt + 0.005 * drawn);
}

std::string fabricCaseName(const ::testing::TestParamInfo<FabricCase>& info) {
  const auto& [name, dt] = info.param;
  return name + "_" + stepOrFrameName(dt);
}

INSTANTIATE_TEST_SUITE_P(
    Presets, YieldingFabricStrength,
    ::testing::Combine(::testing::Values("cotton", "polyester", "nylon66", "wool"),
                       ::testing::Values(1.0e-4, 1.0e-3, 5.0e-3, 1.0e-2, 1.0 / 60.0)),
    fabricCaseName);

INSTANTIATE_TEST_SUITE_P(
    Presets, YieldingStrength,
    ::testing::Combine(::testing::Values("cotton", "polyester", "nylon66", "wool"),
                       ::testing::Values(Pull::kForceRamp, Pull::kDrawnEnd),
                       ::testing::Values(1.0e-4, 1.0e-3, 5.0e-3, 1.0e-2, 1.0 / 60.0)),
    pullCaseName);

}  // namespace
}  // namespace yarn_tearing::test
