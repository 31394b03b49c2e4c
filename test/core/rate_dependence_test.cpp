// Rate dependence: the material's curve is the one at the tensile test's rate (100 % of the gauge
// length per minute); at other rates its stresses scale by 1 + k log10(rate / reference), bounded
// at the ends of the measured range. A yarn drawn at constant speed over four decades of rate
// breaks at that factor times sigma_b pi r^2.
#include "yarn_tearing/core/material/rate_dependence.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

struct BreakAtRate {
  double tension = 0.0;     ///< [N]
  double elongation = 0.0;  ///< imposed when it tore [m]
};

/// One end pinned, the other drawn at strain rate `rate` [1/s]; time step so that the break
/// comes after about 500 steps (within [1e-4, 1e-2] s).
BreakAtRate drawUntilBreak(const Material& material, double rate) {
  YarnSpec spec = hangingYarn(material);
  spec.num_vertices = 5;
  spec.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  const double dt = std::clamp(material.curve.breakingStrain() / rate / 500.0, 1.0e-4, 1.0e-2);
  Simulator sim(parametersWithoutGravity(dt), {spec});
  const std::uint32_t grasped = sim.scene().globalVertex(0, -1);
  const Eigen::Vector3d start = sim.scene().vertices.position[grasped];
  const double speed = rate * spec.length;  // [m/s]
  const double end_time = 2.0 * material.curve.breakingStrain() / rate;
  while (sim.time() < end_time) {
    const double t = sim.time() + dt;
    sim.setKinematicTarget(grasped, start + Eigen::Vector3d(speed * t, 0.0, 0.0));
    sim.step();
    const std::vector<TearEvent> events = sim.takeTearEvents();
    if (!events.empty()) return {events[0].tension, speed * t};
  }
  ADD_FAILURE() << "no break at rate " << rate;
  return {};
}

TEST(RateDependence, BreakingForceRisesLinearlyWithLogRateOverFourDecades) {
  Material material = cottonLike();
  material.rate_sensitivity = 0.06;
  const double reference = material.curve.breakingStress() * kPi * 1.0e-8;  // [N]
  for (double decades : {-2.0, -1.0, 0.0, 1.0, 2.0}) {
    const double rate = RateDependence::kReferenceStrainRate * std::pow(10.0, decades);
    const double expected = reference * (1.0 + material.rate_sensitivity * decades);
    const BreakAtRate result = drawUntilBreak(material, rate);
    EXPECT_NEAR(result.tension, expected, 0.02 * expected) << decades << " decades";
    // The strains are those of the reference curve: it breaks at eps_b L0 at every rate.
    const double elongation = material.curve.breakingStrain() * 0.3;
    EXPECT_NEAR(result.elongation, elongation, 0.02 * elongation) << decades << " decades";
  }
}

TEST(RateDependence, ZeroSensitivityIsRateIndependent) {
  const Material material = cottonLike();
  const double reference = material.curve.breakingStress() * kPi * 1.0e-8;  // [N]
  for (double decades : {-2.0, 0.0, 2.0}) {
    const double rate = RateDependence::kReferenceStrainRate * std::pow(10.0, decades);
    EXPECT_NEAR(drawUntilBreak(material, rate).tension, reference, 0.01 * reference)
        << decades << " decades";
  }
  EXPECT_EQ(RateDependence::stressFactor(0.0, 1.0e6), 1.0);
}

TEST(RateDependence, LawIsBoundedAtTheEndsOfTheMeasuredRange) {
  const double k = 0.1;
  const double fastest = RateDependence::stressFactor(k, RateDependence::kMaxStrainRate);
  EXPECT_EQ(RateDependence::stressFactor(k, 1.0e6), fastest);
  EXPECT_NEAR(fastest, 1.0 + k * std::log10(10.0 * 60.0), 1e-12);
  const double slowest = RateDependence::stressFactor(k, RateDependence::kMinStrainRate);
  EXPECT_EQ(RateDependence::stressFactor(k, 0.0), slowest);
  EXPECT_EQ(RateDependence::stressFactor(k, -1.0), slowest);
  EXPECT_GT(RateDependence::stressFactor(RateDependence::kMaxSensitivity, 0.0), 0.19);
  Material material = cottonLike();
  material.rate_sensitivity = RateDependence::kMaxSensitivity * 1.01;
  EXPECT_THROW(material.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace yarn_tearing::test
