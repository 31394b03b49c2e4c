// The estimated tensions against the tensions that truly act in the same yarn simulated with
// stiff springs (k = E A / L) at a tiny time step, on a swinging yarn.
#include <gtest/gtest.h>

#include <iostream>

#include "test_support.hpp"
#include "yarn_tearing/core/lab/stiff_reference_yarn.hpp"

namespace yarn_tearing::test {
namespace {

/// Smoothstep 0 -> 1 over [0, duration] [s].
double smoothRamp(double t, double duration) {
  const double s = std::min(1.0, t / duration);
  return s * s * (3.0 - 2.0 * s);
}

TEST(StiffReference, EstimatedTensionsMatchTheStiffSpringsOnASwingingYarn) {
  YarnSpec spec = hangingYarn();
  spec.direction = Eigen::Vector3d(1.0, 0.0, -1.0);  // released from 45 degrees
  spec.end_mass = 0.002;
  SimulationParameters p = parametersWithoutGravity(2.0e-4);
  Simulator sim(p, {spec});
  StiffReferenceYarn reference(spec, Eigen::Vector3d::Zero());
  ASSERT_LT(reference.internalTimeStep(), 1e-5);
  // An unstretched stiff yarn released at once rings at its elastic frequency (here ~100 Hz)
  // forever, since nothing damps it. Gravity is therefore switched on smoothly over 0.1 s, ten
  // ringing periods, in both simulations: the swing still goes from 45 degrees down through the
  // bottom and up the other side.
  const Eigen::Vector3d g(0.0, 0.0, -kGravity);
  const std::size_t edges = sim.scene().edges.size();
  double squared_error = 0.0;
  double peak = 0.0;
  std::size_t samples = 0;
  while (sim.time() < 0.6) {
    const Eigen::Vector3d gravity = smoothRamp(sim.time() + 0.5 * p.time_step, 0.1) * g;
    for (std::uint32_t v = 0; v < sim.scene().vertices.size(); ++v) {
      sim.setAppliedForce(v, sim.scene().vertices.mass[v] * gravity);
    }
    reference.setGravity(gravity);
    sim.step();
    reference.advance(p.time_step);
    for (std::size_t e = 0; e < edges; ++e) {
      const double truth = reference.tension(e);
      squared_error += std::pow(sim.scene().edges.tension[e] - truth, 2);
      peak = std::max(peak, truth);
      ++samples;
    }
  }
  const double rms = std::sqrt(squared_error / samples);
  EXPECT_LE(rms, 0.05 * peak) << "rms " << rms << " N, peak " << peak << " N";
  std::cout << "rms error " << rms << " N of peak " << peak << " N (" << 100.0 * rms / peak
            << " %)\n";
  const std::size_t last = sim.scene().vertices.size() - 1;
  EXPECT_LT((sim.scene().vertices.position[last] - reference.positions()[last]).norm(),
            0.01 * spec.length);
}

}  // namespace
}  // namespace yarn_tearing::test
