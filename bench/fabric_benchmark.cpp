// Steps of a woven fabric: hanging at rest, and while a trouser tear runs.
// Run: build/core/yarn_tearing_bench --benchmark_filter=Fabric --benchmark_repetitions=5
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "bench_support.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"

namespace yarn_tearing {
namespace {

/// Hanging from its first row, 12.5 mm between yarns, air damping 0.05 N s/m^2, after 0.2 s.
void BM_FabricAtRest(benchmark::State& state) {
  SimulationParameters parameters;
  parameters.air_damping = 0.05;
  Simulator sim(parameters, {}, {benchFabric(static_cast<int>(state.range(0)), 0.0125)});
  while (sim.time() < 0.2) sim.step();
  timeSteps(state, sim);
  state.counters["max_strain"] = maxStrain(sim.scene());
}

/// A trouser tear (TrouserTear) of range(0) x range(0), its factorizations on up to `threads`
/// threads (SimulationParameters::threads), run until the first tear, then each iteration steps
/// that state 50 times (copying it is not timed); `per_step` is the mean step [s] over the window,
/// recoil substeps included, and `tears` the tears in it.
void timeTrouserTear(benchmark::State& state, int threads) {
  constexpr int kWindow = 50;
  TrouserTear tear(static_cast<int>(state.range(0)));
  SimulationParameters parameters = tear.start().parameters();
  parameters.threads = threads;
  tear.start().setParameters(parameters);
  timeWindowFromFirstTear(state, tear.start(), 2.0, kWindow,
                          [&tear](Simulator& sim) { tear.drive(sim); });
}

/// timeTrouserTear() on one thread.
void BM_FabricTearing(benchmark::State& state) { timeTrouserTear(state, 1); }

/// timeTrouserTear() on up to range(1) threads, in wall time for both counts.
void BM_FabricTearingThreads(benchmark::State& state) {
  timeTrouserTear(state, static_cast<int>(state.range(1)));
}

BENCHMARK(BM_FabricAtRest)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FabricTearing)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FabricTearingThreads)
    ->Args({64, 1})
    ->Args({64, 2})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace yarn_tearing
