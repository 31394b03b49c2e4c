// A break event reports the rate of its edge's geometric strain: the rate the specimen is pulled
// at on a constant-speed pull, and the curve's tangent compliance times the stress rate on a
// constant-rate force ramp; for yarns and fabrics, at every time step.
#include <gtest/gtest.h>

#include <vector>

#include "fabric_support.hpp"

namespace yarn_tearing::test {
namespace {

const std::vector<double> kTimeSteps = {1.0e-4, 1.0e-3, 5.0e-3, 1.0e-2};

/// The first break event of `sim`, stepping to `max_time` [s] with `drive` called before each
/// step with the step's end time [s].
template <typename Drive>
TearEvent firstTear(Simulator& sim, double max_time, Drive drive) {
  while (sim.time() < max_time) {
    drive(sim.time() + sim.parameters().time_step);
    sim.step();
    const std::vector<TearEvent> events = sim.takeTearEvents();
    if (!events.empty()) return events.front();
  }
  ADD_FAILURE() << "no tear at dt = " << sim.parameters().time_step;
  return TearEvent{};
}

TEST(BreakStrainRate, TwoGraspsDrawingAYarnApartReportTheirStrainRate) {
  // Each end drawn outwards at 5 cm/s: the 0.3 m yarn is strained at 0.1 / 0.3 = 0.33 /s.
  const double speed = 0.05;  // [m/s] each
  YarnSpec spec = hangingYarn(cottonLike());
  spec.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  spec.pinned.clear();
  const double expected = 2.0 * speed / spec.length;
  for (double dt : kTimeSteps) {
    Simulator sim(parametersWithoutGravity(dt), {spec});
    const std::uint32_t first = sim.scene().globalVertex(0, 0);
    const std::uint32_t last = sim.scene().globalVertex(0, -1);
    const Eigen::Vector3d a = sim.scene().vertices.position[first];
    const Eigen::Vector3d b = sim.scene().vertices.position[last];
    const TearEvent event = firstTear(sim, 1.0, [&](double t) {
      sim.setKinematicTarget(first, a - Eigen::Vector3d(speed * t, 0.0, 0.0));
      sim.setKinematicTarget(last, b + Eigen::Vector3d(speed * t, 0.0, 0.0));
    });
    EXPECT_NEAR(event.strain_rate, expected, 0.02 * expected) << "dt = " << dt;
  }
}

TEST(BreakStrainRate, ConstantRateForceRampReportsTheTangentStrainRate) {
  // Force rising at F_b / 2 per second on the free end of a pinned yarn: past yield the strain
  // rises at the stress rate over the curve's tangent modulus H.
  const Material material = cottonLike();
  const auto& p = material.curve.points();
  const double tangent = (p[2].stress - p[1].stress) / (p[2].strain - p[1].strain);
  const double area = kPi * 1.0e-8;
  const double force_rate = material.curve.breakingStress() * area / 2.0;  // [N/s]
  const double expected = force_rate / area / tangent;
  YarnSpec spec = hangingYarn(material);
  spec.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  for (double dt : kTimeSteps) {
    Simulator sim(parametersWithoutGravity(dt), {spec});
    const std::uint32_t end = sim.scene().globalVertex(0, -1);
    const TearEvent event = firstTear(sim, 4.0, [&](double t) {
      sim.setAppliedForce(end, Eigen::Vector3d(force_rate * t, 0.0, 0.0));
    });
    EXPECT_NEAR(event.strain_rate, expected, 0.02 * expected) << "dt = " << dt;
  }
}

TEST(BreakStrainRate, FabricDrawnAtConstantSpeedReportsItsWarpStrainRate) {
  // A 4 x 5 cotton strip, first row pinned, last row grasped and drawn along the warp at 2 cm/s:
  // once its crimp is drawn out every warp segment (rest length s (1 + crimp), s the spacing)
  // is strained at v / (span (1 + crimp)).
  const double speed = 0.02;  // [m/s]
  const double crimp = 0.02;
  FabricSpec spec = cottonPatch(4, 5, 0.03, 0.04);
  spec.warp_crimp = crimp;
  spec.weft_crimp = crimp;
  const double expected = speed / (spec.warp_length * (1.0 + crimp));
  for (double dt : kTimeSteps) {
    Simulator sim(parametersWithoutGravity(dt), {}, {spec});
    const std::vector<std::uint32_t> grips = lastRow(sim.scene());
    const std::vector<Eigen::Vector3d> start = positionsOf(sim.scene(), grips);
    const TearEvent event = firstTear(sim, 1.0, [&](double t) {
      for (std::size_t i = 0; i < grips.size(); ++i) {
        sim.setKinematicTarget(grips[i], start[i] + Eigen::Vector3d(0.0, 0.0, -speed * t));
      }
    });
    EXPECT_EQ(event.segment.family, FabricFamily::kWarp) << "dt = " << dt;
    EXPECT_NEAR(event.strain_rate, expected, 0.02 * expected) << "dt = " << dt;
  }
}

}  // namespace
}  // namespace yarn_tearing::test
