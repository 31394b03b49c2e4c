// A grasp's target jumping far within one step (a teleported tf frame): the held vertex goes
// towards it at its yarn's snap-back speed c * eps_b, the yarn tears at the grasp as it would at
// that speed, every step converges and no free vertex moves faster than the loads can throw it.
// A target within reach is met exactly.
#include "yarn_tearing/core/simulation/held_target_limit.hpp"

#include <gtest/gtest.h>

#include "fabric_support.hpp"

namespace yarn_tearing::test {
namespace {

/// The fastest free vertex [m/s].
double fastestFree(const Simulator& sim) {
  const VertexSet& v = sim.scene().vertices;
  double fastest = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v.motion[i] == VertexMotion::kFree) fastest = std::max(fastest, v.velocity[i].norm());
  }
  return fastest;
}

/// Grasps `vertex` of `sim` and sends its target `jump` [m] along +x from where it is, then
/// steps `steps` times: each converges, no free vertex passes 2 c eps_b, the held vertex moves
/// c eps_b dt a step towards the target. Returns the tears.
std::size_t jumpAndStep(Simulator& sim, std::uint32_t vertex, double jump, int steps) {
  const double dt = sim.parameters().time_step;
  const double snap = sim.scene().yarns[sim.scene().vertices.yarn[vertex]].material.snapBackSpeed();
  const Eigen::Vector3d start = sim.scene().vertices.position[vertex];
  const Eigen::Vector3d target = start + Eigen::Vector3d(jump, 0.0, 0.0);
  sim.setKinematicTarget(vertex, target);
  std::size_t tears = 0;
  for (int i = 1; i <= steps; ++i) {
    sim.step();
    tears += sim.takeTearEvents().size();
    EXPECT_TRUE(sim.lastHealth().projection_converged) << "step " << i;
    EXPECT_LE(fastestFree(sim), 2.0 * snap) << "step " << i;
    const Eigen::Vector3d at = sim.scene().vertices.position[vertex];
    EXPECT_NEAR((at - start).x(), std::min(jump, i * snap * dt), 1e-9 * (1.0 + jump));
    EXPECT_NEAR((at - start).tail<2>().norm(), 0.0, 1e-12);
  }
  EXPECT_TRUE(sim.scene().vertices.kinematic_target[vertex].isApprox(target));
  return tears;
}

TEST(HeldTargetLimit, AYarnsGraspJumpingAKilometreTearsItAtTheGrasp) {
  Simulator sim(SimulationParameters{}, {hangingYarn()});
  for (int i = 0; i < 50; ++i) sim.step();
  const std::uint32_t end = sim.scene().globalVertex(0, -1);
  EXPECT_GE(jumpAndStep(sim, end, 1.0e3, 5), 1u);
}

TEST(HeldTargetLimit, AFabricCornerJumpingAKilometreStaysBounded) {
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  Simulator sim(parameters, {}, {cottonPatch(16, 12, 0.06, 0.05)});
  while (sim.time() < 0.1) sim.step();
  EXPECT_GE(jumpAndStep(sim, sim.scene().fabricVertex(0, -1, 0), 1.0e3, 5), 1u);
}

TEST(HeldTargetLimit, ATargetWithinReachIsMetExactly) {
  Simulator sim(SimulationParameters{}, {hangingYarn()});
  const std::uint32_t end = sim.scene().globalVertex(0, -1);
  EXPECT_EQ(jumpAndStep(sim, end, 1.0e-3, 3), 0u);  // 1 mm in a 1 ms step: 1 m/s
}

}  // namespace
}  // namespace yarn_tearing::test
