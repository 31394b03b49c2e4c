// What the benchmark files share: the cotton weaves, the timing loops of one simulation step and
// of a window of steps from a given state (a scene's first tear, a time).
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>

#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing {

/// The benchmarks' cotton: E = 7.6 GPa up to 1.5 % strain, breaking at 7.1 % (486 MPa).
inline StressStrainCurve cotton() {
  return StressStrainCurve({{0.0, 0.0}, {0.015, 1.14e8}, {0.071, 4.86e8}});
}

/// A cotton plain weave of `ends` x `picks` vertices (0.1 mm yarns, `spacing` [m] between yarns,
/// no crimp) in the xz plane hanging along -z, nothing pinned.
inline FabricSpec plainWeave(int ends, int picks, double spacing) {
  FabricSpec spec;
  spec.name = "patch";
  spec.ends = ends;
  spec.picks = picks;
  spec.warp_length = spacing * (picks - 1);
  spec.weft_length = spacing * (ends - 1);
  spec.warp.material.curve = cotton();
  spec.weft = spec.warp;
  return spec;
}

/// plainWeave() of side x side vertices hanging from its pinned first row.
inline FabricSpec benchFabric(int side, double spacing) {
  FabricSpec spec = plainWeave(side, side, spacing);
  spec.pinned_sides = {FabricSide::kFirstRow};
  return spec;
}

/// BM_FabricTearing's trouser tear: benchFabric() of side x side with 2 mm between yarns, a slit
/// a quarter of the picks long up its middle, the two halves of its last row drawn apart along
/// the weft at 0.1 m/s each.
class TrouserTear {
 public:
  explicit TrouserTear(int side) : side_(side), start_(SimulationParameters{}, {}, {spec(side)}) {
    const Scene& scene = start_.scene();
    for (int c = 0; c < side; ++c) {
      origin_.push_back(scene.vertices.position[scene.fabricVertex(0, -1, c)]);
    }
  }

  /// The fabric of a tear of size `side` [-].
  static FabricSpec spec(int side) {
    FabricSpec spec = benchFabric(side, 0.002);
    spec.slits = {{FabricFamily::kWeft, side - side / 4, side - 1, side / 2 - 1}};
    return spec;
  }
  /// The scene at its start, to be stepped with drive().
  Simulator& start() { return start_; }
  /// Sets the last row's targets for the end of `sim`'s next step and takes the step.
  void drive(Simulator& sim) const {
    const double travel = 0.1 * (sim.time() + sim.parameters().time_step);  // [m]
    for (int c = 0; c < side_; ++c) {
      const double sign = c <= middle() ? -1.0 : 1.0;
      sim.setKinematicTarget(sim.scene().fabricVertex(0, -1, c),
                             origin_[c] + Eigen::Vector3d(sign * travel, 0.0, 0.0));
    }
    sim.step();
  }

 private:
  /// The last column of the first tongue [-].
  int middle() const { return side_ / 2 - 1; }

  int side_;
  Simulator start_;
  std::vector<Eigen::Vector3d> origin_;  ///< the last row's start positions [m]
};

/// The largest stretch of an intact edge over its original rest length, |x_b - x_a| / L0 - 1 [-].
inline double maxStrain(const Scene& scene) {
  const EdgeSet& edges = scene.edges;
  const std::vector<Eigen::Vector3d>& x = scene.vertices.position;
  double strain = 0.0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!edges.intact(e)) continue;
    const double length = (x[edges.vertex_b[e]] - x[edges.vertex_a[e]]).norm();
    strain = std::max(strain, length / edges.original_rest_length[e] - 1.0);
  }
  return strain;
}

/// Times single steps of `sim`; reports the last step's projection iterations
/// ("iterations/step").
inline void timeSteps(benchmark::State& state, Simulator& sim) {
  for (auto _ : state) {
    sim.step();
    benchmark::ClobberMemory();
  }
  state.counters["iterations/step"] = sim.lastHealth().projection_iterations;
  state.counters["factorizations/step"] = sim.lastHealth().factorizations;
  state.counters["analyses/step"] = sim.lastHealth().analyses;
}

/// Steps `start` with `drive(sim)` (which sets the scene's targets and steps it) until
/// `ready(start)`; then each iteration steps that state `window` times with `drive` (copying it
/// is not timed). `per_step` is the mean step [s] over the window, substeps included,
/// `factorizations/step` the mean Newton systems factorized a step [-], `analyses/step` the mean
/// symbolic analyses of their patterns a step [-], and `tears` the tears in the window.
template <typename Ready, typename Drive>
void timeWindowFrom(benchmark::State& state, Simulator& start, const Ready& ready, int window,
                    const Drive& drive) {
  while (!ready(start)) drive(start);
  Simulator sim = start;
  std::size_t tears = 0;
  long factorizations = 0;
  long analyses = 0;
  for (auto _ : state) {
    state.PauseTiming();
    sim = start;
    state.ResumeTiming();
    for (int i = 0; i < window; ++i) {
      drive(sim);
      factorizations += sim.lastHealth().factorizations;
      analyses += sim.lastHealth().analyses;
    }
    state.PauseTiming();
    tears = sim.takeTearEvents().size();
    state.ResumeTiming();
  }
  const double steps = static_cast<double>(state.iterations()) * window;
  state.counters["per_step"] =
      benchmark::Counter(steps, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["factorizations/step"] = static_cast<double>(factorizations) / steps;
  state.counters["analyses/step"] = static_cast<double>(analyses) / steps;
  state.counters["tears"] = static_cast<double>(tears);
}

/// Whether `sim` has torn (its recoil is pending) or reached `limit` [s] of simulated time.
inline bool tornOrPast(const Simulator& sim, double limit) {
  return sim.recoilPending() || sim.time() >= limit;
}

/// timeWindowFrom() from the first tear of `start`, or from `limit` [s] of simulated time.
template <typename Drive>
void timeWindowFromFirstTear(benchmark::State& state, Simulator& start, double limit, int window,
                             const Drive& drive) {
  const auto torn = [limit](const Simulator& sim) { return tornOrPast(sim, limit); };
  timeWindowFrom(state, start, torn, window, drive);
}

}  // namespace yarn_tearing
