#!/usr/bin/env bash
# Installs what is needed (Debian 12, as root or with sudo), builds, and runs every test of
# yarn_tearing; exits non-zero when any fails. Logs: build/test_logs/.
#   1. clang-format check of every C++ file
#   2. core GoogleTest suite, Release and AddressSanitizer + UndefinedBehaviorSanitizer
#   3. catkin build, ROS-layer unit tests and rostests
#   4. plot_bag tests (python unittest)
#   5. the manual: links, anchors, length, no history (python unittest, test/docs)
#   6. tensile_test: a quick virtual tensile test of a few specimens (python unittest)
#   7. catkin_lint of the package (tools/check_catkin_lint.sh)
#   8. install space and downstream C++ use (tools/test_install.sh)
#   9. report only (never fails the run): the node's achieved real-time factor and dropped steps
#      in the table drag and in fabrics held by their corners and torn (tools/measure_live.sh,
#      at most 2 and 4 minutes; a figure it could not reach within
#      its wait is reported as such)
# Ends with each stage's wall time and the ten slowest tests (tools/slowest_tests.py).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
logs="${repo}/build/test_logs"
mkdir -p "${logs}"

"${repo}/tools/install_deps.sh"

stage_times=()
run_logged() {
  local name="$1"
  shift
  echo "== ${name}"
  local start="${SECONDS}"
  "$@" 2>&1 | tee "${logs}/${name}.log"
  stage_times+=("${name} $((SECONDS - start)) s")
}

run_logged format "${repo}/tools/check_format.sh"
run_logged core "${repo}/tools/test_core.sh"
run_logged ros "${repo}/tools/run_ros_tests.sh"
run_logged plot /usr/bin/python3 -m unittest discover -s "${repo}/test/plot" -t "${repo}/test/plot"
run_logged docs /usr/bin/python3 -m unittest discover -s "${repo}/test/docs" -t "${repo}/test/docs"
run_logged tensile /usr/bin/python3 -m unittest discover -s "${repo}/test/tensile" \
  -t "${repo}/test/tensile"
run_logged lint bash "${repo}/tools/check_catkin_lint.sh"
run_logged install bash "${repo}/tools/test_install.sh"
YARN_TEARING_MEASURE_LIMIT=110 run_logged measure_table_drag bash "${repo}/tools/measure_live.sh" \
  table_drag || echo "measure_table_drag: no figures (see ${logs}/measure_table_drag.log)"
YARN_TEARING_MEASURE_LIMIT=360 run_logged measure_fabric_draw bash "${repo}/tools/measure_live.sh" \
  fabric_draw || echo "measure_fabric_draw: no figures (see ${logs}/measure_fabric_draw.log)"

# One closing line over all suites (each suite above already failed the run if it failed).
core_total=$(grep -ho "tests failed out of [0-9]*" "${logs}/core.log" | awk '{s += $5} END {print s + 0}')
ros_total=$(grep -o "Summary: [0-9]* tests" "${logs}/ros.log" | tail -1 | awk '{print $2 + 0}')
plot_total=$(grep -o "^Ran [0-9]* test" "${logs}/plot.log" | awk '{print $2 + 0}')
docs_total=$(grep -o "^Ran [0-9]* test" "${logs}/docs.log" | awk '{print $2 + 0}')
tensile_total=$(grep -o "^Ran [0-9]* test" "${logs}/tensile.log" | awk '{print $2 + 0}')
echo "stage times: ${stage_times[*]/%/,} total ${SECONDS} s"
/usr/bin/python3 "${repo}/tools/slowest_tests.py" "${logs}" "${repo}/ws/build/test_results/yarn_tearing"
echo "test: $((core_total + ros_total + plot_total + docs_total + tensile_total)) passed, 0 failed"
