#!/usr/bin/env bash
# Builds yarn_tearing (tools/build.sh) and runs its ROS tests through catkin: the ROS-layer unit
# tests (test/ros/unit, gtest) and all rostests (test/ros/*.test);
# exits non-zero when any test fails or errs. Results: ws/build/test_results/yarn_tearing/.
# Takes about 1 minute on 2 cores once built (each .test starts its own master on a free port,
# so a running roscore is not disturbed).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ws="${repo}/ws"
export ROS_HOME="${ROS_HOME:-${ws}/ros_home}"  # rostest logs

results="${ws}/build/test_results/yarn_tearing"
rm -rf "${results}"
# A unity build (CMAKE_UNITY_BUILD, kept in the workspace's cache): a target's files compiled in
# batches, 133 s instead of 227 s for a fresh workspace here; see tools/test_core.sh.
"${repo}/tools/build.sh" -DCMAKE_UNITY_BUILD=ON
"${repo}/tools/build.sh" tests  # the test programs, on every core
# One test at a time (-j1): the rate and tracking tests need the CPU they measure.
"${repo}/tools/build.sh" run_tests_yarn_tearing -j1
catkin_test_results --verbose "${results}"
