// A heavy end swung hard sideways on a very light yarn (1 g on 1 mg vertices, 2000 m/s^2): the
// projection must still converge every step (it stalled before the geometric-stiffness Newton
// step), and once the swing has died down the yarn lies along the force and carries it: T = F.
// The projection conserves a swing's energy, so a dashpot on the weight (b = 0.01 N s/m, decay
// time m / b = 0.1 s) makes the swing die down.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

TEST(Swing, HeavyEndSwungSidewaysOnALightYarn) {
  YarnSpec spec;
  spec.name = "line";
  spec.material = fibre("line", {{0.0, 0.0}, {0.01, 1.0e8}, {0.05, 3.0e8}});
  spec.material.density = 1500.0;
  spec.radius = 1.0e-4;
  spec.length = 0.1;
  spec.num_vertices = 6;
  spec.direction = Eigen::Vector3d(0.0, 1.0, 0.0);
  spec.pinned = {0};
  spec.end_mass = 0.001;
  SimulationParameters p = parametersWithoutGravity();
  p.air_damping = 1.0e-3;
  Simulator sim(p, {spec});
  const double force = 2.0;  // [N] along +x, across the yarn
  const std::uint32_t end = sim.scene().globalVertex(0, -1);
  const double dashpot = 0.01;  // [N s/m]

  std::vector<double> tension;
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector3d velocity = sim.scene().vertices.velocity[end];
    sim.setAppliedForce(end, Eigen::Vector3d(force, 0.0, 0.0) - dashpot * velocity);
    sim.step();
    ASSERT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    if (i >= 2000) tension.push_back(sim.scene().edges.tension[4]);
  }
  const Eigen::Vector3d arm = sim.scene().vertices.position[end];
  EXPECT_LT(std::abs(arm.y()), 1e-3 * spec.length);  // along the force
  std::nth_element(tension.begin(), tension.begin() + tension.size() / 2, tension.end());
  EXPECT_NEAR(tension[tension.size() / 2], force, 0.005 * force);
}

}  // namespace
}  // namespace yarn_tearing::test
