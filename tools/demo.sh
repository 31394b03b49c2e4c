#!/usr/bin/env bash
# The paper's Figure 4 demo: installs the dependencies (tools/install_deps.sh), builds
# (tools/build.sh) and runs `roslaunch yarn_tearing demo.launch`, which prints each break as it
# happens and ends by itself once the weak and strong yarns have torn (~30 s). The run is recorded
# to <out>/demo.bag and plotted by scripts/plot_bag into <out> (filmstrip, tension_strain,
# stress_strain and length PNGs), named at the end. Arguments go to roslaunch:
#
#   tools/demo.sh                                   # console, bag and figures
#   tools/demo.sh rviz:=true                        # also RViz (installs the rviz package)
#   tools/demo.sh bag:=/tmp/demo.bag                # the bag elsewhere (figures still in <out>)
#   tools/demo.sh record:=false                     # no bag, no figures
#   tools/demo.sh --capstan                         # the capstan demo instead (capstan_demo.launch,
#                                                   # ~10 s): also capstan.png
#   tools/demo.sh --fabric                          # the trouser tear instead (fabric_demo.launch):
#                                                   # fabric filmstrip and tear force-extension
#
# <out> is $YARN_TEARING_DEMO_OUT, default ./yarn_tearing_demo_<UTC time>. Exits non-zero when the
# demo did not end by itself (demo_supervisor timed out or was interrupted) or plotting failed.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${YARN_TEARING_DEMO_OUT:-${PWD}/yarn_tearing_demo_$(date -u +%Y%m%dT%H%M%SZ)}"
out="$(realpath -m "${out}")"
bag="${out}/demo.bag"
record=true
launch_file=demo.launch
plot_args=()

install_args=()
launch_args=()
for arg in "$@"; do
  case "${arg}" in
    --capstan)
      launch_file=capstan_demo.launch
      # plot_bag draws the capstan law with the peg's friction coefficient from the demo's config.
      mu="$(/usr/bin/python3 -c 'import sys, yaml; print(yaml.safe_load(open(sys.argv[1]))["obstacles"][0]["friction"])' "${repo}/config/capstan_demo.yaml")"
      plot_args+=(--capstan-friction "${mu}")
      continue
      ;;
    --fabric)
      launch_file=fabric_demo.launch
      continue
      ;;
    rviz:=true)
      install_args+=(--rviz)
      if [[ -z "${DISPLAY:-}" ]]; then
        echo "demo.sh: rviz:=true needs a display (DISPLAY is not set)" >&2
      fi
      ;;
    record:=false) record=false ;;
    bag:=*) bag="$(realpath -m "${arg#bag:=}")" ;;  # rosbag record runs in ROS_HOME
  esac
  case "${arg}" in
    record:=* | bag:=*) ;;
    *) launch_args+=("${arg}") ;;
  esac
done

"${repo}/tools/install_deps.sh" "${install_args[@]}"
"${repo}/tools/build.sh"

set +u  # setup.bash reads unset variables
# shellcheck disable=SC1091
source "${repo}/ws/devel/setup.bash"
set -u

mkdir -p "${out}" "$(dirname "${bag}")"
status_file="${out}/demo_status"
rm -f "${status_file}"
if [[ "${record}" == true ]]; then
  launch_args+=(record:=true "bag:=${bag}")
fi
roslaunch yarn_tearing "${launch_file}" status_file:="${status_file}" "${launch_args[@]}" || true

demo_ok=false
if [[ "$(cat "${status_file}" 2>/dev/null)" == 0 ]]; then
  demo_ok=true
else
  echo "demo.sh: the demo did not end torn (timeout, interrupted or crashed)" >&2
fi
rm -f "${status_file}"
if [[ "${record}" != true ]]; then
  [[ "${demo_ok}" == true ]]
  exit
fi

# rosbag record closes the bag on roslaunch's SIGINT; a bag cut short is left as .bag.active.
if [[ ! -f "${bag}" && -f "${bag}.active" ]]; then
  echo "demo.sh: ${bag} was not closed; reindexing ${bag}.active" >&2
  rosbag reindex --force --quiet "${bag}.active"  # keeps the original as .bag.orig.active
  mv "${bag}.active" "${bag}"
  rm -f "${bag}.orig.active"
fi
if [[ ! -f "${bag}" ]]; then
  echo "demo.sh: no bag recorded at ${bag}" >&2
  exit 1
fi

plot_ok=true
figures="$(rosrun yarn_tearing plot_bag "${plot_args[@]}" "${bag}" "${out}")" || plot_ok=false
echo "demo bag: ${bag}"
if [[ "${plot_ok}" == true ]]; then
  echo "demo figures: ${out}"
  while IFS= read -r figure; do echo "  ${figure}"; done <<<"${figures}"
else
  echo "demo.sh: plot_bag failed on ${bag}" >&2
fi
[[ "${demo_ok}" == true && "${plot_ok}" == true ]]
