#!/usr/bin/env bash
# The paper's Figure 4 demo: installs the dependencies (tools/install_deps.sh), builds
# (tools/build.sh) and runs `roslaunch yarn_tearing demo.launch`, which prints each break as it
# happens and ends by itself once both yarns have torn (~25 s). Arguments go to roslaunch:
#
#   tools/demo.sh                                   # console only
#   tools/demo.sh rviz:=true                        # also RViz (installs the rviz package)
#   tools/demo.sh record:=true bag:=/tmp/demo.bag   # rosbag of the demo's topics
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

install_args=()
for arg in "$@"; do
  if [[ "${arg}" == "rviz:=true" ]]; then
    install_args+=(--rviz)
    if [[ -z "${DISPLAY:-}" ]]; then
      echo "demo.sh: rviz:=true needs a display (DISPLAY is not set)" >&2
    fi
  fi
done

"${repo}/tools/install_deps.sh" "${install_args[@]}"
"${repo}/tools/build.sh"

set +u  # setup.bash reads unset variables
# shellcheck disable=SC1091
source "${repo}/ws/devel/setup.bash"
set -u
exec roslaunch yarn_tearing demo.launch "$@"
