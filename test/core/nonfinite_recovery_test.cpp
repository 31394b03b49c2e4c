// A step that overflows (a force of 1e300 N: finite, but past anything the simulation can
// represent) restores that yarn to its initial state; the other yarn goes on untouched. A
// non-finite value in any of the quantities nonFiniteYarns() checks names its yarn.
#include "yarn_tearing/core/simulation/nonfinite_recovery.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

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

TEST(NonFiniteRecovery, ANonFiniteValueInAnyCheckedQuantityNamesItsYarn) {
  YarnSpec second = hangingYarn();
  second.name = "second";
  second.start = Eigen::Vector3d(0.1, 0.0, 0.0);
  const Scene healthy = Simulator(SimulationParameters{}, {hangingYarn(), second}).scene();
  const std::vector<Eigen::Vector3d> no_force(healthy.vertices.size(), Eigen::Vector3d::Zero());
  EXPECT_TRUE(nonFiniteYarns(healthy, no_force).empty());
  const std::uint32_t v = healthy.globalVertex(1, 3);
  const std::uint32_t e = healthy.yarns[1].first_edge + 2;
  using Spoil = std::function<void(Scene&, std::vector<Eigen::Vector3d>&, double)>;
  const std::vector<std::pair<const char*, Spoil>> spoils = {
      {"position", [&](Scene& s, auto&, double x) { s.vertices.position[v].y() = x; }},
      {"velocity", [&](Scene& s, auto&, double x) { s.vertices.velocity[v].z() = x; }},
      {"support force", [&](Scene&, auto& f, double x) { f[v].x() = x; }},
      {"rest length", [&](Scene& s, auto&, double x) { s.edges.rest_length[e] = x; }},
      {"strain limit", [&](Scene& s, auto&, double x) { s.edges.strain_limit[e] = x; }},
      {"tension", [&](Scene& s, auto&, double x) { s.edges.tension[e] = x; }},
      {"spring tension", [&](Scene& s, auto&, double x) { s.edges.spring_tension[e] = x; }},
      {"stress", [&](Scene& s, auto&, double x) { s.edges.stress[e] = x; }},
      {"strain", [&](Scene& s, auto&, double x) { s.edges.strain[e] = x; }},
      {"plastic strain", [&](Scene& s, auto&, double x) { s.edges.plastic_strain[e] = x; }},
      {"strain rate", [&](Scene& s, auto&, double x) { s.edges.strain_rate[e] = x; }},
  };
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()}) {
    for (const auto& [name, spoil] : spoils) {
      Scene scene = healthy;
      std::vector<Eigen::Vector3d> force = no_force;
      spoil(scene, force, bad);
      EXPECT_EQ(nonFiniteYarns(scene, force), std::vector<std::uint32_t>{1}) << name << " " << bad;
    }
  }
}

}  // namespace
}  // namespace yarn_tearing::test
