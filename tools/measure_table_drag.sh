#!/usr/bin/env bash
# Reports the node's achieved real-time factor and dropped steps in the table drag
# (tools/measure_table_drag.py; default real_time_factor 1 and 0), from the catkin workspace
# that tools/build.sh made. Reporting only: the figures never fail it; it ends within 2 minutes.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ws="${YARN_TEARING_WS:-${repo}/ws}"
set +u
# shellcheck disable=SC1091
source "${ws}/devel/setup.bash"
set -u
export ROS_HOME="${ROS_HOME:-${ws}/ros_home}"
exec timeout --kill-after=10 110 /usr/bin/python3 "${repo}/tools/measure_table_drag.py" "$@"
