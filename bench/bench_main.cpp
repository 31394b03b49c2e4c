// The benchmarks' entry point. With --fresh_heap, glibc's allocation thresholds (M_MMAP_THRESHOLD
// and M_TRIM_THRESHOLD) are pinned at their start values, 128 KiB: every case then steps on the
// heap of a process that has not yet freed a large mapped block, as a program stepping one scene
// may (there glibc gives back a freed top of the heap above 128 KiB and faults it in again on the
// next allocation), rather than on one that the earlier cases' freed simulators have tuned.
// Run: build/core/yarn_tearing_bench --fresh_heap --benchmark_filter=...
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cstring>

namespace {

/// Removes --fresh_heap from the arguments; true when it was there.
bool takeFreshHeapFlag(int& argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--fresh_heap") != 0) continue;
    for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
    --argc;
    return true;
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (takeFreshHeapFlag(argc, argv)) {
    constexpr int kStartThreshold = 128 * 1024;  // glibc's start value of both [bytes]
    mallopt(M_MMAP_THRESHOLD, kStartThreshold);
    mallopt(M_TRIM_THRESHOLD, kStartThreshold);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
