// An undamped pendulum keeps its energy: 10 g on a 0.3 m yarn released from 45 degrees swings
// for 10 s (about 9 periods) with no air damping. A projection along the edges' final directions
// damps a swing at first order in dt (doc/method.md, "Start directions for held vertices"); the
// swing energy must stay within 2 %.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

/// Kinetic plus gravitational energy of every vertex [J] (g along -z).
double mechanicalEnergy(const Simulator& sim) {
  const VertexSet& v = sim.scene().vertices;
  double potential = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) potential += v.mass[i] * kGravity * v.position[i].z();
  return kineticEnergy(sim) + potential;
}

class EnergyDrift : public ::testing::TestWithParam<std::tuple<double, int>> {};

TEST_P(EnergyDrift, PendulumKeepsItsSwingEnergyForTenSeconds) {
  const auto [dt, vertices] = GetParam();
  YarnSpec spec = hangingYarn();
  spec.num_vertices = vertices;
  spec.direction = Eigen::Vector3d(std::sqrt(0.5), 0.0, -std::sqrt(0.5));
  spec.end_mass = 0.01;  // [kg]
  SimulationParameters p;
  p.time_step = dt;
  Simulator sim(p, {spec});
  const std::size_t end = sim.scene().vertices.size() - 1;
  const double swing_energy =
      sim.scene().vertices.mass[end] * kGravity * spec.length * (1.0 - std::sqrt(0.5));  // [J]
  const double start = mechanicalEnergy(sim);
  const int steps = static_cast<int>(std::lround(10.0 / dt));
  for (int i = 0; i < steps; ++i) {
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
  }
  EXPECT_NEAR(mechanicalEnergy(sim), start, 0.02 * swing_energy);
}

INSTANTIATE_TEST_SUITE_P(StepsAndMeshes, EnergyDrift,
                         ::testing::Values(std::make_tuple(1e-2, 2), std::make_tuple(1e-2, 25),
                                           std::make_tuple(1e-3, 2), std::make_tuple(1e-3, 25),
                                           std::make_tuple(1e-3, 100), std::make_tuple(1e-4, 2),
                                           std::make_tuple(1e-4, 25)),
                         [](const ::testing::TestParamInfo<std::tuple<double, int>>& info) {
                           return std::to_string(std::get<1>(info.param)) + "vertices_" +
                                  stepName(std::get<0>(info.param));
                         });

}  // namespace
}  // namespace yarn_tearing::test
