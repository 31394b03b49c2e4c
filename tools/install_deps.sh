#!/usr/bin/env bash
# Installs what building, testing and running yarn_tearing needs on Debian 12 (bookworm), from
# Debian's own ROS 1 packages (no /opt/ros, no rosdep). Idempotent: when everything is installed
# already it only checks (no apt-get update) and returns within a second.
#
#   tools/install_deps.sh          # build + tests + demo
#   tools/install_deps.sh --rviz   # also rviz (large) for `roslaunch yarn_tearing demo.launch rviz:=true`
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake clang-format libeigen3-dev libgtest-dev libbenchmark-dev
  # the benchmark's references: another simulator (Bullet's soft-body patch), a maintained
  # sparse Cholesky (CHOLMOD)
  libbullet-dev pkg-config libsuitesparse-dev
  # catkin + ROS 1 core (roscore, roslaunch, rostopic, rosbag, message generation)
  catkin ros-core ros-core-dev rosbash python3-catkin-pkg python3-genpy python3-rospy
  python3-rosbag librosbag-dev python3-rostest librostest-dev python3-rosunit
  # messages, services, tf2, diagnostics
  libgeometry-msgs-dev python3-geometry-msgs libstd-msgs-dev python3-std-msgs
  libvisualization-msgs-dev python3-visualization-msgs libstd-srvs-dev python3-std-srvs
  libros-rosgraph-msgs-dev python3-rosgraph-msgs libtf2-dev libtf2-msgs-dev libtf2-ros-dev python3-tf2-ros
  libdiagnostic-updater-dev python3-diagnostic-msgs
  # nodelet (the library, its headers, the `nodelet` manager/loader executable)
  libnodelet-dev libnodeletlib-dev libnodeletlib-tools python3-nodelet
  # live tuning (dynamic_reconfigure: server headers, cfg generator, dynparam)
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  # package checks (tools/check_catkin_lint.sh)
  catkin-lint
  # scripts (force_ramp, plot_bag)
  python3-yaml python3-numpy python3-matplotlib
)
if [[ "${1:-}" == "--rviz" ]]; then
  packages+=(rviz)
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "${package}" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("${package}")
  fi
done
if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install_deps: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
if [[ "$(id -u)" -ne 0 ]]; then
  sudo_cmd=(sudo)
fi
echo "install_deps: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y --no-install-recommends \
  "${missing[@]}"
