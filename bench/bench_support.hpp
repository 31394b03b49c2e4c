// What the benchmark files share: the timing loops of one simulation step and of a window of
// steps from a scene's first tear.
#pragma once

#include <benchmark/benchmark.h>

#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing {

/// Times single steps of `sim`; reports the last step's projection iterations
/// ("iterations/step").
inline void timeSteps(benchmark::State& state, Simulator& sim) {
  for (auto _ : state) {
    sim.step();
    benchmark::ClobberMemory();
  }
  state.counters["iterations/step"] = sim.lastHealth().projection_iterations;
  state.counters["factorizations/step"] = sim.lastHealth().factorizations;
}

/// Steps `start` with `drive(sim)` (which sets the scene's targets and steps it) until its first
/// tear or `limit` [s] of simulated time; then each iteration steps that state `window` times
/// with `drive` (copying it is not timed). `per_step` is the mean step [s] over the window,
/// recoil substeps included, and `tears` the tears in it.
template <typename Drive>
void timeWindowFromFirstTear(benchmark::State& state, Simulator& start, double limit, int window,
                             const Drive& drive) {
  while (!start.recoilPending() && start.time() < limit) drive(start);
  Simulator sim = start;
  std::size_t tears = 0;
  for (auto _ : state) {
    state.PauseTiming();
    sim = start;
    state.ResumeTiming();
    for (int i = 0; i < window; ++i) drive(sim);
    state.PauseTiming();
    tears = sim.takeTearEvents().size();
    state.ResumeTiming();
  }
  state.counters["per_step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * window,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["tears"] = static_cast<double>(tears);
}

}  // namespace yarn_tearing
