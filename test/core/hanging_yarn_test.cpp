// A settled hanging yarn: each edge carries the weight of everything below it.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace yarn_tearing::test {
namespace {

void expectTensionEqualsWeightBelow(double end_mass_in_vertex_masses) {
  YarnSpec spec = hangingYarn();
  const double vertex_mass = spec.linearDensity() * spec.length / (spec.num_vertices - 1);
  spec.end_mass = end_mass_in_vertex_masses * vertex_mass;
  SimulationParameters p;
  p.air_damping = 0.05;  // settles the vertical bounce of the weight
  Simulator sim(p, {spec});
  for (int i = 0; i < 3000; ++i) sim.step();

  const Scene& s = sim.scene();
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    double mass_below = 0.0;
    for (std::size_t v = s.edges.vertex_b[e]; v < s.vertices.size(); ++v) {
      mass_below += s.vertices.mass[v];
    }
    const double weight_below = mass_below * kGravity;
    EXPECT_NEAR(s.edges.tension[e], weight_below, 0.005 * weight_below) << "edge " << e;
  }
  EXPECT_TRUE(sim.lastHealth().projection_converged);
  EXPECT_LE(sim.lastHealth().max_constraint_violation, p.constraint_tolerance);
}

TEST(HangingYarn, TensionEqualsWeightBelow) { expectTensionEqualsWeightBelow(0.0); }

TEST(HangingYarn, TensionEqualsWeightBelowWithEndWeight10000TimesAVertex) {
  expectTensionEqualsWeightBelow(1.0e4);
}

TEST(HangingYarn, PinnedSupportFeelsTheWholeWeight) {
  YarnSpec spec = hangingYarn();
  spec.end_mass = 0.01;
  SimulationParameters p;
  p.air_damping = 0.05;
  Simulator sim(p, {spec});
  for (int i = 0; i < 3000; ++i) sim.step();
  double total_mass = 0.0;
  for (double m : sim.scene().vertices.mass) total_mass += m;
  const Eigen::Vector3d f = sim.supportForce(0);
  EXPECT_NEAR(f.z(), -total_mass * kGravity, 0.005 * total_mass * kGravity);
  EXPECT_NEAR(f.x(), 0.0, 1e-9);
}

TEST(HangingYarn, GeneralSparsePathAgreesWithBandedPath) {
  // Both paths solve the same system; they may differ only by round-off.
  YarnSpec spec = hangingYarn();
  spec.end_mass = 0.001;
  SimulationParameters banded;
  SimulationParameters general;
  general.force_general_solver = true;
  Simulator a(banded, {spec});
  Simulator b(general, {spec});
  for (int i = 0; i < 500; ++i) {
    a.step();
    b.step();
  }
  for (std::size_t e = 0; e < a.scene().edges.size(); ++e) {
    EXPECT_NEAR(a.scene().edges.tension[e], b.scene().edges.tension[e],
                1e-8 * a.scene().edges.tension[0]);
  }
}

}  // namespace
}  // namespace yarn_tearing::test
