// A step that overflows (a force of 1e300 N: finite, but past anything the simulation can
// represent) restores that yarn to its initial state; the other yarn goes on untouched.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

TEST(NonFiniteRecovery, OverflowingYarnIsRestoredOthersGoOn) {
  YarnSpec hit = hangingYarn();
  hit.name = "hit";
  YarnSpec other = hangingYarn();
  other.name = "other";
  other.start = Eigen::Vector3d(0.1, 0.0, 0.0);
  SimulationParameters parameters;
  Simulator sim(parameters, {hit, other});
  for (int i = 0; i < 100; ++i) sim.step();
  const Scene initial = Simulator(parameters, {hit, other}).scene();
  const std::uint32_t end = sim.scene().globalVertex(0, -1);
  sim.setAppliedForce(end, Eigen::Vector3d(1.0e300, 0.0, 0.0));
  sim.step();
  ASSERT_TRUE(allFinite(sim));
  ASSERT_FALSE(sim.lastHealth().restored_yarns.empty());
  EXPECT_EQ(sim.lastHealth().restored_yarns.front(), 0u);
  const Yarn& yarn = sim.scene().yarns[0];
  for (std::uint32_t i = 0; i < yarn.num_vertices; ++i) {
    const std::uint32_t v = yarn.first_vertex + i;
    EXPECT_EQ(sim.scene().vertices.position[v], initial.vertices.position[v]);
    EXPECT_TRUE(sim.scene().vertices.applied_force[v].isZero(0.0));
  }
  for (std::uint32_t j = 0; j < yarn.num_edges; ++j) {
    EXPECT_TRUE(sim.scene().edges.intact(yarn.first_edge + j));
  }
  for (const TearEvent& e : sim.takeTearEvents()) EXPECT_NE(e.yarn, 0u);
  // The next steps are healthy again, and the restored yarn hangs under gravity as before.
  for (int i = 0; i < 100; ++i) {
    sim.step();
    ASSERT_TRUE(sim.lastHealth().restored_yarns.empty()) << "step " << i;
  }
  EXPECT_TRUE(allFinite(sim));
  EXPECT_TRUE(sim.scene().edges.intact(0));
  EXPECT_NEAR(sim.scene().vertices.position[sim.scene().globalVertex(1, -1)].z(), -0.3, 1.0e-3);
}

TEST(NonFiniteRecovery, HealthyStepsRestoreNothing) {
  Simulator sim(SimulationParameters{}, {hangingYarn()});
  for (int i = 0; i < 10; ++i) {
    sim.step();
    EXPECT_TRUE(sim.lastHealth().restored_yarns.empty());
  }
}

}  // namespace
}  // namespace yarn_tearing::test
