// One full step, and each stage on its own, for hanging yarns of 25 to 10,000 vertices.
// Run (doc/performance.md):
//   build/core/yarn_tearing_bench --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "bench_support.hpp"
#include "yarn_tearing/core/forces/explicit_forces.hpp"
#include "yarn_tearing/core/material/material_response.hpp"
#include "yarn_tearing/core/projection/length_constraint_projection.hpp"
#include "yarn_tearing/core/projection/tension_estimator.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/core/tearing/tearing.hpp"

namespace yarn_tearing {
namespace {

/// A cotton yarn of `vertices` vertices, 12.5 mm segments, a 10 g weight on its end, hanging
/// straight down from its pinned first vertex.
YarnSpec benchYarn(int vertices) {
  YarnSpec spec;
  spec.name = "bench";
  spec.material.curve = cotton();
  spec.num_vertices = vertices;
  spec.length = 0.0125 * (vertices - 1);
  spec.pinned = {0};
  spec.end_mass = 0.01;
  return spec;
}

/// The bench yarn, hanging for 0.2 s. With `damping` the
/// air damping is 0.05 N s/m^2 and the yarn has settled; without, the weight still bounces on the
/// elastic yarn and slack stretches come and go (the projection's hardest steady case).
Simulator hangingYarn(int vertices, bool damping) {
  const YarnSpec spec = benchYarn(vertices);
  SimulationParameters parameters;
  parameters.air_damping = damping ? 0.05 : 0.0;
  Simulator sim(parameters, {spec});
  for (int i = 0; i < 200; ++i) sim.step();
  return sim;
}

Simulator settledYarn(int vertices) { return hangingYarn(vertices, true); }

void BM_Step(benchmark::State& state) {
  Simulator sim = settledYarn(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    sim.step();
    benchmark::ClobberMemory();
  }
  state.SetComplexityN(state.range(0));
  state.counters["iterations/step"] = sim.lastHealth().projection_iterations;
}

void BM_StepBouncing(benchmark::State& state) {
  Simulator sim = hangingYarn(static_cast<int>(state.range(0)), false);
  for (auto _ : state) {
    sim.step();
    benchmark::ClobberMemory();
  }
  state.SetComplexityN(state.range(0));
}

/// The first simulated second after a yarn with a 10 g weight is released straight from rest,
/// without damping: the first step (every edge pulled taut from the top down), the tension wave
/// running down and the weight bouncing back. Reports the mean cost of a step over that second
/// (`per_step`, seconds); building the yarn is not timed.
void BM_FirstSecondAfterRelease(benchmark::State& state) {
  constexpr int kSteps = 1000;
  const int vertices = static_cast<int>(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    YarnSpec spec = benchYarn(vertices);
    SimulationParameters parameters;
    Simulator sim(parameters, {spec});
    state.ResumeTiming();
    for (int i = 0; i < kSteps; ++i) sim.step();
    benchmark::DoNotOptimize(sim.scene().vertices.position.data());
  }
  state.counters["per_step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kSteps,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetComplexityN(state.range(0));
}

/// A span pinned at both ends with a 2 N pretension, under gravity, after 0.05 s: the robot's
/// case (a yarn between two holders). Arguments: vertices, and the step as 10^-k s. At
/// dt = 1e-4 s its light vertices' sideways stiffness is past what the fast iterations treat
/// stably (omega dt > 1), and Newton steps finish each projection (doc/method.md, "Implicit strain
/// limit").
void BM_HeldSpan(benchmark::State& state) {
  const int vertices = static_cast<int>(state.range(0));
  YarnSpec spec = benchYarn(vertices);
  spec.direction = Eigen::Vector3d::UnitX();
  spec.pinned = {0, -1};
  spec.end_mass = 0.0;
  Scene scene = buildScene({spec});
  const double strain = 2.0 / (spec.material.curve.youngsModulus() * spec.area());
  for (Eigen::Vector3d& x : scene.vertices.position) x *= 1.0 + strain;
  SimulationParameters parameters;
  parameters.time_step = std::pow(10.0, -static_cast<double>(state.range(1)));
  Simulator sim(parameters, scene);
  while (sim.time() < 0.05) sim.step();
  timeSteps(state, sim);
}

/// A woven-like grid of side x side vertices joined along rows and columns (warp and weft, 12.5 mm
/// segments of the bench yarn, no diagonals), hanging from its pinned top row, settled with air
/// damping for 0.2 s: the general sparse path of the solvers.
void BM_GridAtRest(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const double spacing = 0.0125;
  const YarnSpec yarn_spec = benchYarn(2);
  Scene scene;
  Yarn yarn;
  yarn.name = "grid";
  yarn.material = yarn_spec.material;
  yarn.radius = yarn_spec.radius;
  yarn.num_vertices = static_cast<std::uint32_t>(side * side);
  scene.yarns.push_back(yarn);
  const double vertex_mass = 2.0 * yarn_spec.linearDensity() * spacing;
  auto id = [side](int row, int col) { return static_cast<std::uint32_t>(row * side + col); };
  for (int row = 0; row < side; ++row) {
    for (int col = 0; col < side; ++col) {
      scene.vertices.add(Eigen::Vector3d(col * spacing, 0.0, -row * spacing), vertex_mass,
                         2.0 * spacing, 0);
      if (row == 0) scene.vertices.motion.back() = VertexMotion::kPinned;
    }
  }
  for (int row = 0; row < side; ++row) {
    for (int col = 0; col < side; ++col) {
      if (col + 1 < side) {
        scene.edges.add(id(row, col), id(row, col + 1), 0, spacing, yarn_spec.area(), 1.0);
      }
      if (row + 1 < side) {
        scene.edges.add(id(row, col), id(row + 1, col), 0, spacing, yarn_spec.area(), 1.0);
      }
    }
  }
  scene.yarns[0].num_edges = static_cast<std::uint32_t>(scene.edges.size());
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  Simulator sim(parameters, scene);
  while (sim.time() < 0.2) sim.step();
  timeSteps(state, sim);
}

/// Stages 1 and 2 (forces with the soft springs, then symplectic Euler) on the settled state. The
/// vertices go on moving under them alone, which changes nothing in their cost.
void BM_StageForcesAndPrediction(benchmark::State& state) {
  Simulator sim = settledYarn(static_cast<int>(state.range(0)));
  Scene scene = sim.scene();
  std::vector<Eigen::Vector3d> force(scene.vertices.size());
  const double dt = sim.parameters().time_step;
  EdgeStretchLimits limits;
  for (auto _ : state) {
    computeStretchLimits(scene, sim.parameters(), limits);
    accumulateExplicitForces(sim.parameters(), scene.vertices, limits.soft_spring, scene.edges,
                             force);
    predictPositions(force, dt, scene.vertices);
    benchmark::ClobberMemory();
  }
  state.SetComplexityN(state.range(0));
}

/// Stage 3 from the same predicted positions each time (includes copying them, O(N)).
void BM_StageProjection(benchmark::State& state) {
  Simulator sim = settledYarn(static_cast<int>(state.range(0)));
  const Scene& scene = sim.scene();
  std::vector<Eigen::Vector3d> predicted = scene.vertices.position;
  for (std::size_t v = 1; v < predicted.size(); ++v) predicted[v].z() -= 9.81e-6;  // g dt^2
  EdgeStretchLimits limits;
  computeStretchLimits(scene, sim.parameters(), limits);
  LengthConstraintProjection projection;
  EdgeGramSolver gram;
  gram.setTopology(scene.edges, scene.vertices.size());
  std::vector<Eigen::Vector3d> position;
  for (auto _ : state) {
    position = predicted;
    benchmark::DoNotOptimize(
        projection.project(position, scene.vertices, scene.edges, limits, sim.parameters(), gram));
  }
  state.SetComplexityN(state.range(0));
}

/// Stage 4 on the settled state.
void BM_StageTensionEstimate(benchmark::State& state) {
  Simulator sim = settledYarn(static_cast<int>(state.range(0)));
  const Scene& scene = sim.scene();
  std::vector<Eigen::Vector3d> force(scene.vertices.size());
  for (std::size_t v = 0; v < force.size(); ++v) {
    force[v] = scene.vertices.mass[v] * sim.parameters().gravity;
  }
  const std::vector<Eigen::Vector3d> start_velocity = scene.vertices.velocity;
  TensionEstimateInput input;
  input.vertices = &scene.vertices;
  input.start_velocity = &start_velocity;
  input.force = &force;
  input.time_step = sim.parameters().time_step;
  input.regularization = sim.parameters().regularization;
  TensionEstimator estimator;
  EdgeGramSolver gram;
  gram.setTopology(scene.edges, scene.vertices.size());
  std::vector<double> tension = scene.edges.tension;
  for (auto _ : state) {
    benchmark::DoNotOptimize(estimator.estimate(input, scene.edges, gram, tension));
  }
  state.SetComplexityN(state.range(0));
}

/// Stages 5 and 6 (material update, then the search for edges to tear) on the settled state.
void BM_StageMaterialAndTearing(benchmark::State& state) {
  Simulator sim = settledYarn(static_cast<int>(state.range(0)));
  Scene scene = sim.scene();
  Tearing tearing;
  for (auto _ : state) {
    updateMaterialResponse(scene.yarns, sim.parameters().time_step, scene.edges);
    benchmark::DoNotOptimize(tearing.collect(scene, 0.0).size());
  }
  state.SetComplexityN(state.range(0));
}

/// The step right after a tear, which resolves the recoil: the settled yarn's end pulled at twice
/// the breaking force until it tears, then that state stepped once (copying it back is not
/// timed). Its cost over a plain step's is the recoil's price per tear. With `local`, the yarn
/// the release wave reaches is taken through it (SimulationParameters::local_recoil,
/// integrateRecoilWave()); without, the whole yarn in recoil_substeps substeps.
void stepAfterTear(benchmark::State& state, bool local) {
  Simulator torn = settledYarn(static_cast<int>(state.range(0)));
  SimulationParameters parameters = torn.parameters();
  parameters.local_recoil = local;
  torn.setParameters(parameters);
  const std::uint32_t end = torn.scene().globalVertex(0, -1);
  torn.setAppliedForce(end, Eigen::Vector3d(0.0, 0.0, -2.0 * 4.86e8 * torn.scene().edges.area[0]));
  while (!torn.recoilPending()) torn.step();
  Simulator sim = torn;
  for (auto _ : state) {
    state.PauseTiming();
    sim = torn;
    state.ResumeTiming();
    sim.step();
    benchmark::ClobberMemory();
  }
  state.SetComplexityN(state.range(0));
  state.counters["substeps"] = sim.lastHealth().substeps;
  state.counters["substepped_vertices"] = static_cast<double>(sim.lastHealth().substepped_vertices);
}

void BM_StepAfterTear(benchmark::State& state) { stepAfterTear(state, true); }

void BM_StepAfterTearWholeScene(benchmark::State& state) { stepAfterTear(state, false); }

#define YARN_SIZES Arg(25)->Arg(100)->Arg(1000)->Arg(10000)->Complexity(benchmark::oN)

BENCHMARK(BM_Step)->YARN_SIZES->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StepBouncing)->YARN_SIZES->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FirstSecondAfterRelease)->YARN_SIZES->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepAfterTear)->Arg(25)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StepAfterTearWholeScene)->Arg(25)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_HeldSpan)
    ->Args({25, 3})
    ->Args({25, 4})
    ->Args({1000, 3})
    ->Args({1000, 4})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GridAtRest)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StageForcesAndPrediction)->YARN_SIZES->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StageProjection)->YARN_SIZES->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StageTensionEstimate)->YARN_SIZES->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StageMaterialAndTearing)->YARN_SIZES->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace yarn_tearing
