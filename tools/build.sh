#!/usr/bin/env bash
# Builds yarn_tearing in the catkin workspace <repo>/ws with Debian's catkin_make, against
# /usr/bin/python3 (a pyenv python3 earlier on PATH lacks catkin_pkg). Extra arguments go to
# catkin_make, e.g. `tools/build.sh run_tests`. Afterwards: source ws/devel/setup.bash
#
# ws/src/yarn_tearing is a directory of symlinks to the repo's top-level entries (all but ws/ and
# build*/), not one symlink to the repo: roslaunch and rostest look files up by walking the
# package directory following symlinks, and a link back to the repo (which contains ws/) would be
# an endless loop (ws/src/yarn_tearing/ws/src/yarn_tearing/...).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ws="${YARN_TEARING_WS:-${repo}/ws}"
package="${ws}/src/yarn_tearing"

mkdir -p "${ws}/src"
if [[ -L "${package}" ]]; then
  rm "${package}"
fi
mkdir -p "${package}"
find "${package}" -mindepth 1 -maxdepth 1 -type l -delete
for entry in "${repo}"/*; do
  name="$(basename "${entry}")"
  case "${name}" in
    ws | build*) continue ;;
  esac
  ln -s "${entry}" "${package}/${name}"
done

# catkin snapshots the environment for `make run_tests` when it configures
# (build/catkin_generated/setup_cached.sh), and only lists directories that exist then: create
# devel's Python and library folders first, or the test scripts cannot import yarn_tearing.msg.
mkdir -p "${ws}/devel/lib/python3/dist-packages"
cmake_args=()
cached_setup="${ws}/build/catkin_generated/setup_cached.sh"
if [[ -f "${cached_setup}" ]] && ! grep -q "dist-packages" "${cached_setup}"; then
  cmake_args+=(--force-cmake)
fi

cd "${ws}"
catkin_make "${cmake_args[@]}" -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release \
  -j"$(nproc)" "$@"
