// Conjugate gradients on a woven fabric's edge systems: the yarn chains they are preconditioned
// by, the solution against the sparse LDL^T, and a hanging fabric stepped either way.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "fabric_support.hpp"
#include "yarn_tearing/core/model/edge_chains.hpp"
#include "yarn_tearing/core/projection/edge_gram_solver.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing::test {
namespace {

/// A side x side cotton plain weave, 12.5 mm between yarns, hanging from its first row.
Simulator hangingFabric(int side, const SimulationParameters& parameters) {
  const double length = 0.0125 * (side - 1);
  return Simulator(parameters, {}, {cottonPatch(side, side, length, length)});
}

TEST(EdgeChains, EachYarnOfAWeaveIsOneChainAlongIt) {
  const int ends = 7;
  const int picks = 5;
  const Simulator sim(SimulationParameters{}, {}, {cottonPatch(ends, picks, 0.06, 0.04)});
  const EdgeSet& edges = sim.scene().edges;
  EdgeIncidence incidence;
  incidence.build(edges, sim.scene().vertices.size());
  EdgeChains chains;
  chains.build(edges, incidence);

  ASSERT_EQ(chains.order().size(), edges.size());
  std::vector<std::uint32_t> sorted = chains.order();
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) EXPECT_EQ(sorted[i], i);  // each edge once
  int chain_ends = 0;
  for (std::size_t i = 0; i < chains.order().size(); ++i) {
    const std::uint32_t v = chains.joint()[i];
    if (v == EdgeChains::kNoVertex) {
      ++chain_ends;
      continue;
    }
    const std::uint32_t e = chains.order()[i];
    const std::uint32_t f = chains.order()[i + 1];
    EXPECT_EQ(edges.yarn[e], edges.yarn[f]);
    EXPECT_TRUE(edges.vertex_a[e] == v || edges.vertex_b[e] == v);
    EXPECT_TRUE(edges.vertex_a[f] == v || edges.vertex_b[f] == v);
  }
  EXPECT_EQ(chain_ends, ends + picks);  // one chain per warp and per weft yarn
}

TEST(EdgeGramSolver, ConjugateGradientsMatchTheSparseLdlt) {
  // A 64 x 64 weave (8,064 edges, past the iterative threshold), crumpled: its edge directions
  // turned at random by up to 0.5 rad, so that warp and weft no longer cross at right angles.
  const Simulator sim = hangingFabric(64, SimulationParameters{});
  const EdgeSet& edges = sim.scene().edges;
  const std::size_t q = edges.size();
  const std::size_t n = sim.scene().vertices.size();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> turn(-0.5, 0.5);
  std::uniform_real_distribution<double> uniform(0.5, 2.0);
  std::vector<Eigen::Vector3d> direction(q);
  for (std::size_t e = 0; e < q; ++e) {
    const Eigen::Vector3d d = sim.scene().vertices.position[edges.vertex_b[e]] -
                              sim.scene().vertices.position[edges.vertex_a[e]];
    direction[e] = (Eigen::AngleAxisd(turn(rng), Eigen::Vector3d::UnitY()) *
                    Eigen::AngleAxisd(turn(rng), Eigen::Vector3d::UnitZ()) * d.normalized());
  }
  std::vector<double> weight(n);
  for (std::size_t v = 0; v < n; ++v) weight[v] = sim.scene().vertices.inverseMass(v);
  std::vector<std::uint8_t> active(q, 1);
  for (std::size_t e = 0; e < q; e += 7) active[e] = 0;  // slack edges
  std::vector<double> shift(q);
  for (double& c : shift) c = 1e-3 * uniform(rng) * weight[n - 1];
  std::vector<double> rhs(q);
  for (double& r : rhs) r = uniform(rng);

  GramSystem system;
  system.direction = &direction;
  system.vertex_weight = &weight;
  system.active = &active;
  system.diagonal_shift = &shift;
  EdgeGramSolver iterative;
  iterative.setTopology(edges, n);
  EdgeGramSolver direct;
  direct.setTopology(edges, n);
  direct.forceDirectSolves(true);
  std::vector<double> x_iterative = rhs;
  std::vector<double> x_direct = rhs;
  iterative.solve(edges, system, x_iterative);
  direct.solve(edges, system, x_direct);
  EXPECT_TRUE(iterative.lastSolveIterative());
  EXPECT_FALSE(direct.lastSolveIterative());

  double largest = 0.0;
  double difference = 0.0;
  for (std::size_t e = 0; e < q; ++e) {
    largest = std::max(largest, std::abs(x_direct[e]));
    difference = std::max(difference, std::abs(x_iterative[e] - x_direct[e]));
    if (!active[e]) {
      EXPECT_EQ(x_iterative[e], 0.0);
    }
  }
  ASSERT_GT(largest, 0.0);
  EXPECT_LT(difference, 1e-8 * largest);

  // A second right-hand side of the same system (resolve: the fast contact rows' columns).
  std::vector<double> again_iterative = rhs;
  std::vector<double> again_direct = rhs;
  std::reverse(again_iterative.begin(), again_iterative.end());
  std::reverse(again_direct.begin(), again_direct.end());
  iterative.resolve(edges, system, again_iterative);
  direct.resolve(edges, system, again_direct);
  EXPECT_TRUE(iterative.lastSolveIterative());
  for (std::size_t e = 0; e < q; ++e) {
    EXPECT_NEAR(again_iterative[e], again_direct[e], 1e-8 * largest) << "edge " << e;
  }
}

TEST(EdgeGramSolver, AHangingFabricStepsAsWithTheSparseLdlt) {
  // The same 64 x 64 fabric released from flat, 50 steps of 1 ms: it falls and swings into its
  // hanging shape, its slack weft coming and going; positions and tensions either way.
  SimulationParameters parameters;
  Simulator iterative = hangingFabric(64, parameters);
  parameters.force_direct_solves = true;
  Simulator direct = hangingFabric(64, parameters);
  // Within the projection's tolerance (1e-6 of a 12.5 mm edge) and 1e-6 of the largest tension.
  expectSameSteps(iterative, direct, 50, 1e-6 * 0.0125, 1e-6);
}

}  // namespace
}  // namespace yarn_tearing::test
