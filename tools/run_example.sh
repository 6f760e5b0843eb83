#!/usr/bin/env bash
# The README's main command: set up everything (tools/bootstrap.sh) and run the
# default example, printing its result.
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$top/tools/bootstrap.sh"
source "$top/build/env.sh"
cd "$top/examples/chain-1d"
lmp -in in.chain -log none -nocite "$@" | grep -A30 '^Result'
