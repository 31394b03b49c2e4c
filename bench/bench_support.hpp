// What the benchmark files share: the timing loop of one simulation step.
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
}

}  // namespace yarn_tearing
