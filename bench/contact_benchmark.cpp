// Speed targets of contact: a step with contacts against the same yarn's step without them.
//   BM_DrapedOverPeg/25/1 vs BM_DrapedOverPeg/25/0: a 25-vertex cotton yarn pinned at one end,
//     lying across a 2 mm peg (a capsule) with the rest hanging down beyond it, settled; /0 is the
//     same yarn without the peg (hanging from its pin). Target: with the peg <= 2x without.
//   BM_LyingOnPlane/1000/1 vs BM_LyingOnPlane/1000/0: 1,000 vertices lying straight on a table
//     (a plane, friction mu = 0.3), settled; /0 is the same yarn without the table (falling
//     freely from the same start); /2 the table without friction. Target: on the table (either)
//     <= 2x free.
// Run (doc/performance.md; interleaved so that a ratio's two cases see the same load):
//   build/core/yarn_tearing_bench --benchmark_filter='Peg|Plane' --benchmark_repetitions=9
//     --benchmark_min_time=0.2 --benchmark_enable_random_interleaving=true
//     --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "bench_support.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing {
namespace {

constexpr double kSegment = 0.0125;    ///< [m] segment length, as the other benchmarks
constexpr double kPegRadius = 1.0e-3;  ///< [m] a 2 mm peg

/// A cotton yarn of `vertices` vertices and 12.5 mm segments (r = 0.1 mm) starting at `start`
/// along +x.
YarnSpec cottonYarn(int vertices, const Eigen::Vector3d& start) {
  YarnSpec spec;
  spec.name = "bench";
  spec.material.curve = cotton();
  spec.num_vertices = vertices;
  spec.length = kSegment * (vertices - 1);
  spec.start = start;
  spec.direction = Eigen::Vector3d::UnitX();
  return spec;
}

/// A capsule peg of radius kPegRadius along y through the origin.
Obstacle peg() {
  Obstacle o;
  o.name = "peg";
  o.shape = ObstacleShape::kCapsule;
  o.radius = kPegRadius;
  o.half_length = 0.05;
  o.pose.linear() = Eigen::AngleAxisd(-M_PI / 2.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
  return o;
}

/// Steps `sim` for `seconds` of simulated time.
void advance(Simulator& sim, double seconds) {
  const auto steps = static_cast<int>(std::lround(seconds / sim.parameters().time_step));
  for (int i = 0; i < steps; ++i) sim.step();
}

/// range(0) vertices pinned at vertex 0, 11.5 segments before a 2 mm peg (the peg under the middle
/// of segment 11, as test/core/peg_test.cpp), air damping so that it settles in 1 s; range(1) = 1
/// with the peg, 0 without.
void BM_DrapedOverPeg(benchmark::State& state) {
  const int vertices = static_cast<int>(state.range(0));
  const bool with_peg = state.range(1) != 0;
  YarnSpec spec = cottonYarn(vertices, Eigen::Vector3d(-11.5 * kSegment, 0.0, 0.0));
  spec.start.z() = kPegRadius + spec.radius + 1.0e-6;
  spec.pinned = {0};
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  Simulator sim(parameters, {spec});
  if (with_peg) sim.setObstacles({peg()});
  advance(sim, 1.0);
  timeSteps(state, sim);
}

/// range(0) vertices lying straight on a table (a plane at z = 0) at rest, settled for 0.2 s;
/// range(1) = 1 with the table (mu = 0.3), 2 with a frictionless table, 0 without (the same yarn
/// falling freely for 0.2 s).
void BM_LyingOnPlane(benchmark::State& state) {
  const int vertices = static_cast<int>(state.range(0));
  const int table_case = static_cast<int>(state.range(1));
  YarnSpec spec = cottonYarn(vertices, Eigen::Vector3d::Zero());
  spec.start.z() = spec.radius;
  Simulator sim(SimulationParameters{}, {spec});
  if (table_case != 0) {
    Obstacle table;
    table.name = "table";
    table.shape = ObstacleShape::kPlane;
    table.friction = table_case == 1 ? 0.3 : 0.0;
    sim.setObstacles({table});
  }
  advance(sim, 0.2);
  timeSteps(state, sim);
}

BENCHMARK(BM_DrapedOverPeg)->Args({25, 0})->Args({25, 1})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LyingOnPlane)
    ->Args({1000, 0})
    ->Args({1000, 1})
    ->Args({1000, 2})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace yarn_tearing
