#!/usr/bin/env bash
# Tests yarn_tearing as users of an installed package meet it:
#   1. `catkin_make install`s it into a temporary prefix from the workspace that tools/build.sh
#      makes (<repo>/ws or $YARN_TEARING_WS: built there first if need be, its objects reused), then
#      sets that workspace's install prefix back to its own install/;
#   2. with nothing but `source <prefix>/setup.bash` in an empty environment: rospack finds the
#      installed share folder, the messages and headers are there, the demo (node, force_ramp,
#      demo_supervisor, launch files, configs) runs to both tears and records a bag, plot_bag
#      (with its yarn_plotting module) draws it, the nodelet (yarn_tearing_nodelet.launch)
#      publishes yarn_states, and tensile_test runs a cotton preset;
#   3. builds the downstream package test/downstream/yarn_tearing_downstream, which links
#      yarn_tearing_core through find_package(catkin COMPONENTS yarn_tearing) and runs a hanging
#      yarn, once against the install space and once against the devel space ws/devel.
# Exits non-zero at the first failure. The temporary folder is removed at the end unless
# $YARN_TEARING_INSTALL_TEST_DIR names one (kept, and reused for a faster second run).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ -n "${YARN_TEARING_INSTALL_TEST_DIR:-}" ]]; then
  work="$(realpath -m "${YARN_TEARING_INSTALL_TEST_DIR}")"
  mkdir -p "${work}"
else
  work="$(mktemp -d /tmp/yarn_tearing_install.XXXXXX)"
  trap 'rm -rf "${work}"' EXIT
fi
prefix="${work}/install"
workspace="${YARN_TEARING_WS:-${repo}/ws}"  # tools/build.sh's
jobs="$(nproc)"

step() { echo "== test_install: $*"; }
fail() {
  echo "test_install: FAILED: $*" >&2
  exit 1
}

# Runs a command in an empty environment in which only `setup` (a setup.bash) is sourced.
in_clean_env() {
  local setup="$1"
  shift
  env -i HOME="${HOME}" PATH=/usr/local/bin:/usr/bin:/bin LANG=C.UTF-8 ROS_HOME="${work}/ros_home" \
    ROS_MASTER_URI="http://localhost:${port}" ROS_LOG_DIR="${work}/ros_home/log" \
    bash -c 'set -eo pipefail; source "$0"; set -u; eval "$1"' "${setup}" "$*"
}

free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1])'
}
port="$(free_port)"

step "build and install into ${prefix}"
rm -rf "${prefix}"
# The install prefix is a configure-time setting of catkin (its installed setup files and CMake
# config name it): configured for the install, and back to the workspace's own afterwards.
"${repo}/tools/build.sh" install -DCMAKE_INSTALL_PREFIX="${prefix}" -j"${jobs}" \
  >"${work}/build.log" 2>&1 ||
  { tail -50 "${work}/build.log"; fail "catkin_make install (log: ${work}/build.log)"; }
"${repo}/tools/build.sh" -DCMAKE_INSTALL_PREFIX="${workspace}/install" >>"${work}/build.log" 2>&1 ||
  { tail -50 "${work}/build.log"; fail "catkin_make with the workspace's install prefix"; }

step "files of the install space"
for file in lib/libyarn_tearing_core.so lib/libyarn_tearing_ros.so \
  lib/yarn_tearing/yarn_tearing_node lib/yarn_tearing/plot_bag \
  lib/yarn_tearing/yarn_plotting/__init__.py lib/yarn_tearing/force_ramp \
  lib/yarn_tearing/tensile_test lib/yarn_tearing/tensile_pull \
  include/yarn_tearing/core/simulation/simulator.hpp include/yarn_tearing/BreakEvent.h \
  share/yarn_tearing/package.xml share/yarn_tearing/launch/demo.launch \
  share/yarn_tearing/config/default.yaml share/yarn_tearing/config/rviz/demo.rviz \
  share/yarn_tearing/cmake/yarn_tearingConfig.cmake; do
  [[ -e "${prefix}/${file}" ]] || fail "${prefix}/${file} is not installed"
done

step "only install/setup.bash sourced: package, messages and libraries resolve there"
found="$(in_clean_env "${prefix}/setup.bash" 'rospack find yarn_tearing')"
[[ "${found}" == "${prefix}/share/yarn_tearing" ]] || fail "rospack find yarn_tearing = ${found}"
in_clean_env "${prefix}/setup.bash" \
  "[[ \"\${CMAKE_PREFIX_PATH}\" != *'${repo}'* ]] || { echo \"CMAKE_PREFIX_PATH names the source tree: \${CMAKE_PREFIX_PATH}\"; exit 1; }"
in_clean_env "${prefix}/setup.bash" 'rosmsg show yarn_tearing/BreakEvent >/dev/null'
in_clean_env "${prefix}/setup.bash" \
  "python3 -c 'import yarn_tearing.msg as m, sys; sys.exit(not m.__file__.startswith(\"${prefix}/\"))'" ||
  fail "yarn_tearing.msg is not imported from the install space"
# grep without -q reads all of ldd's output: -q exits at the match and, under pipefail, ldd's
# next write (SIGPIPE) failed the check now and then.
in_clean_env "${prefix}/setup.bash" \
  "ldd \$(catkin_find --first-only yarn_tearing yarn_tearing_node) | grep '${prefix}/lib/libyarn_tearing_ros.so' >/dev/null" ||
  fail "yarn_tearing_node does not load libyarn_tearing_ros.so from the install space"

step "the demo from the install space (node, force_ramp, demo_supervisor, bag)"
rm -f "${work}/demo_status" "${work}/demo.bag"
in_clean_env "${prefix}/setup.bash" \
  "roslaunch yarn_tearing demo.launch record:=true bag:=${work}/demo.bag status_file:=${work}/demo_status" \
  >"${work}/demo.log" 2>&1 || true
[[ "$(cat "${work}/demo_status" 2>/dev/null)" == 0 ]] ||
  { tail -40 "${work}/demo.log"; fail "the demo did not end with both yarns torn"; }
grep -q "yarn 'weak' tore" "${work}/demo.log" || fail "no break printed by the demo"

step "plot_bag and yarn_plotting from the install space"
rm -rf "${work}/figures"
in_clean_env "${prefix}/setup.bash" "rosrun yarn_tearing plot_bag ${work}/demo.bag ${work}/figures" \
  >"${work}/plot.log" 2>&1 || { cat "${work}/plot.log"; fail "plot_bag"; }
for figure in filmstrip tension_strain stress_strain length; do
  [[ -s "${work}/figures/${figure}.png" ]] || fail "plot_bag wrote no ${figure}.png"
done

step "the nodelet from the install space (standalone)"
in_clean_env "${prefix}/setup.bash" "
  roslaunch yarn_tearing yarn_tearing_nodelet.launch output:=log >${work}/nodelet.log 2>&1 &
  launch=\$!
  trap 'kill -INT \$launch; wait \$launch || true' EXIT
  for i in \$(seq 100); do rostopic list >/dev/null 2>&1 && break; sleep 0.2; done
  timeout 30 rostopic echo -n 1 /yarn_states/sim_time" >"${work}/nodelet_echo.log" 2>&1 ||
  { cat "${work}/nodelet_echo.log" "${work}/nodelet.log"; fail "no yarn_states from the nodelet"; }

step "tensile_test (with tensile_pull and the material presets) from the install space"
in_clean_env "${prefix}/setup.bash" \
  "cd ${work} && rosrun yarn_tearing tensile_test cotton --specimens 2 --vertices 5 --plot ${work}/tensile.png" \
  >"${work}/tensile.log" 2>&1 || { cat "${work}/tensile.log"; fail "tensile_test"; }
grep -q "breaking force \[N\]" "${work}/tensile.log" || fail "tensile_test printed no report"
[[ -s "${work}/tensile.png" ]] || fail "tensile_test wrote no plot"

build_downstream() {
  local name="$1" setup="$2"
  local ws="${work}/downstream_${name}"
  rm -rf "${ws}"
  mkdir -p "${ws}/src"
  ln -s "${repo}/test/downstream/yarn_tearing_downstream" "${ws}/src/yarn_tearing_downstream"
  in_clean_env "${setup}" \
    "cd ${ws} && catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -j${jobs}" \
    >"${ws}/build.log" 2>&1 || { tail -30 "${ws}/build.log"; fail "downstream build against ${name}"; }
  in_clean_env "${ws}/devel/setup.bash" "rosrun yarn_tearing_downstream yarn_tearing_downstream_hanging_yarn" ||
    fail "downstream program built against ${name}"
}

step "downstream package linking yarn_tearing_core: install space"
build_downstream install "${prefix}/setup.bash"
step "downstream package linking yarn_tearing_core: devel space"
build_downstream devel "${workspace}/devel/setup.bash"

echo "test_install: all checks passed"
