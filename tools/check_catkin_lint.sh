#!/usr/bin/env bash
# Fails when catkin_lint (Debian package catkin-lint) reports an error or warning on the package,
# except the one explained in doc/architecture.md ("catkin_lint"): the developer scripts tools/*.sh are
# executable but, by design, not installed. Lints the files git knows (as a clean clone has them),
# not the build folders.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
copy="$(mktemp -d /tmp/yarn_tearing_lint.XXXXXX)"
trap 'rm -rf "${copy}"' EXIT
mkdir -p "${copy}/yarn_tearing"
(cd "${repo}" && git ls-files -co --exclude-standard | grep -v -e '^ws/' -e '^build' |
  tar -cf - -T - | tar -xf - -C "${copy}/yarn_tearing")
report="$(catkin_lint -W1 "${copy}/yarn_tearing" 2>&1 | grep -e ': error: ' -e ': warning: ' || true)"
unexplained="$(grep -v -E "warning: file 'tools/[a-z_]+\.sh' is executable but not installed" \
  <<<"${report}" || true)"
if [[ -n "${unexplained}" ]]; then
  echo "${unexplained}" >&2
  echo "check_catkin_lint: catkin_lint reports the problems above" >&2
  exit 1
fi
echo "check_catkin_lint: no errors, no warnings (besides the tools/*.sh scripts, see doc/architecture.md)"
