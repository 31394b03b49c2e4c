#!/usr/bin/env bash
# Builds the ROS-free simulation core twice and runs its GoogleTest suite with each build:
#   build/core      Release
#   build/sanitize  AddressSanitizer + UndefinedBehaviorSanitizer (any report fails the run)
# Also builds the benchmarks (build/core/yarn_tearing_bench) without running them.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
jobs="$(nproc)"

build_and_test() {
  local dir="$1"
  shift
  cmake -S "${repo}" -B "${dir}" -DYARN_TEARING_CORE_ONLY=ON "$@" > /dev/null
  cmake --build "${dir}" -j"${jobs}"
  (cd "${dir}" && ctest --output-on-failure -j"${jobs}")
}

echo "== core tests (Release)"
build_and_test "${repo}/build/core" -DCMAKE_BUILD_TYPE=Release

echo "== core tests (AddressSanitizer + UndefinedBehaviorSanitizer)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
build_and_test "${repo}/build/sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DYARN_TEARING_SANITIZE=ON
