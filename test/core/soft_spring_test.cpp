// The soft springs and the compliant constraints together are exactly as stiff as the material:
// a yarn stretches by Hooke's law F L / (E A) at any time step and any vertex count. The soft
// spring alone, ratio m / dt^2, grows past E A / L0 at small steps (0.40 of the Hooke elongation
// at dt = 1e-6, N = 25, before it was counted as part of the edge's stiffness).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

struct HookeCase {
  double time_step;  ///< [s]
  int vertices;
  bool pinned;  ///< vertex 0 pinned and the last pulled; otherwise pulled at both ends
};

/// Mean elongation [m] of a yarn loaded by `force` [N] along +x, the load raised smoothly over
/// many periods of its slowest longitudinal vibration and then held; averaged over the hold.
double meanElongation(const HookeCase& c, double force) {
  YarnSpec spec = hangingYarn();
  spec.num_vertices = c.vertices;
  spec.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  if (!c.pinned) spec.pinned.clear();
  Simulator sim(parametersWithoutGravity(c.time_step), {spec});
  const auto last = static_cast<std::uint32_t>(sim.scene().vertices.size() - 1);
  // Slowest period 4 L / sqrt(E / rho) = 0.54 ms: ramp and hold over ten of them at least.
  const double ramp = std::max(5.0e-3, 100.0 * c.time_step);
  const int ramp_steps = static_cast<int>(std::lround(ramp / c.time_step));
  double sum = 0.0;
  for (int i = 0; i < 2 * ramp_steps; ++i) {
    const double s = std::min(1.0, static_cast<double>(i + 1) / ramp_steps);
    const double f = force * s * s * (3.0 - 2.0 * s);  // smoothstep
    if (!c.pinned) sim.setAppliedForce(0, Eigen::Vector3d(-f, 0.0, 0.0));
    sim.setAppliedForce(last, Eigen::Vector3d(f, 0.0, 0.0));
    sim.step();
    if (i >= ramp_steps) sum += yarnLength(sim) - spec.length;
  }
  return sum / ramp_steps;
}

TEST(SoftSpring, YarnStretchesByHookesLawAtEveryTimeStep) {
  const Material material = cottonLike();
  const double area = kPi * 1.0e-4 * 1.0e-4;
  const double force = 0.5 * material.curve.yieldStress() * area;  // elastic range
  const double expected = force * 0.3 / (material.curve.youngsModulus() * area);
  for (double dt : {1.0e-6, 1.0e-5, 1.0e-4, 1.0e-3, 1.0e-2}) {
    for (int n : {2, 5, 25}) {
      for (bool pinned : {true, false}) {
        const double elongation = meanElongation({dt, n, pinned}, force);
        EXPECT_NEAR(elongation / expected, 1.0, 0.01)
            << "dt " << dt << ", " << n << " vertices, " << (pinned ? "pinned" : "free");
      }
    }
  }
}

TEST(SoftSpring, TakesAtMostHalfOfTheEdgeStiffness) {
  SimulationParameters p = parametersWithoutGravity(1.0e-6);
  const YarnSpec spec = hangingYarn();
  const Simulator sim(p, {spec});
  EdgeStretchLimits limits;
  computeStretchLimits(sim.scene(), p, limits);
  for (std::size_t e = 0; e < limits.compliance.size(); ++e) {
    EXPECT_LE(limits.soft_spring[e] * limits.compliance[e], 0.5 + 1e-15) << "edge " << e;
    // In parallel the spring and the constraint give the edge's own stiffness E A / L0.
    EXPECT_NEAR(limits.soft_spring[e] + 1.0 / limits.constraintCompliance(e),
                1.0 / limits.compliance[e], 1e-9 / limits.compliance[e]);
  }
}

}  // namespace
}  // namespace yarn_tearing::test
