#!/usr/bin/env bash
# Reports the node's achieved real-time factor in a user's scene, through its topics, from the
# catkin workspace that tools/build.sh made. Reporting only: the figures never fail it.
#   tools/measure_live.sh table_drag [real_time_factor ...]   (tools/measure_table_drag.py; 1 and 0)
#   tools/measure_live.sh fabric_draw [SIZE[@AIR_DAMPING] ...] (tools/measure_fabric_draw.py; 16, 32, both in air)
# Each ends within the time limit given by YARN_TEARING_MEASURE_LIMIT [s] (default 240).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ws="${YARN_TEARING_WS:-${repo}/ws}"
measurement="${1:?usage: tools/measure_live.sh table_drag|fabric_draw [arguments]}"
shift
case "${measurement}" in
  table_drag | fabric_draw) ;;
  *) echo "measure_live: unknown measurement '${measurement}' (table_drag, fabric_draw)" >&2; exit 2 ;;
esac
set +u
# shellcheck disable=SC1091
source "${ws}/devel/setup.bash"
set -u
export ROS_HOME="${ROS_HOME:-${ws}/ros_home}"
exec timeout --kill-after=10 "${YARN_TEARING_MEASURE_LIMIT:-240}" /usr/bin/python3 \
  "${repo}/tools/measure_${measurement}.py" "$@"
