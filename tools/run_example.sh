#!/usr/bin/env bash
# The README's main command: set up everything (tools/bootstrap.sh) and run the
# default example, the 3D shock-dusting scene of examples/shock-3d (about 30 s), printing
# its dust count and the paper's threshold.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$top/tools/bootstrap.sh"
source "$top/build/env.sh"
cd "$top/examples/shock-3d"
lmp -in in.shock3d -log none -nocite "$@" | grep -A30 '^Result'
