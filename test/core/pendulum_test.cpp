// A yarn with a heavy end weight released from horizontal swings as a pendulum: at the bottom of
// the swing the weight's segment carries 3 m g (energy: v^2 = 2 g L; T = m g + m v^2 / L).
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

TEST(Pendulum, TensionAtBottomOfSwingIsThreeTimesWeight) {
  YarnSpec spec = hangingYarn();
  spec.direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  spec.end_mass = 0.01;  // 10 g, ~700 times the whole yarn
  SimulationParameters p;
  p.time_step = 1.0e-4;
  Simulator sim(p, {spec});
  const std::size_t last = sim.scene().vertices.size() - 1;
  const std::size_t last_edge = sim.scene().edges.size() - 1;
  const double end_vertex_mass = sim.scene().vertices.mass[last];

  double lowest_z = 0.0;
  double tension_at_lowest = 0.0;
  for (int i = 0; i < 6000; ++i) {  // 0.6 s: past the bottom (quarter period ~0.32 s)
    sim.step();
    const double z = sim.scene().vertices.position[last].z();
    if (z < lowest_z) {
      lowest_z = z;
      tension_at_lowest = sim.scene().edges.tension[last_edge];
    }
  }
  const double expected = 3.0 * end_vertex_mass * kGravity;
  EXPECT_NEAR(tension_at_lowest, expected, 0.02 * expected);
  EXPECT_NEAR(lowest_z, -spec.length, 0.01 * spec.length);
}

}  // namespace
}  // namespace yarn_tearing::test
