#!/usr/bin/env bash
# Runs the whole test suite against another LAMMPS source tree:
#   bash tools/check_lammps_version.sh /path/to/lammps
# builds that tree with the pinned configuration in its own cache entry
# (~/.cache/clusterdyn/lammps-<its version>-<key>), the plugin against it in its own folder
# (build-lammps-<version>/ of this tree, or CLUSTERDYN_BUILD_DIR), and runs every test there,
# ending with "N passed, N failed".  The default build/ and the pinned LAMMPS are left alone.
set -uo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
src=${1:?usage: check_lammps_version.sh LAMMPS_SOURCE_TREE}
src=$(cd "$src" && pwd) || exit 1
version=$(sed -n 's/^#define LAMMPS_VERSION "\(.*\)"/\1/p' "$src/src/version.h" 2>/dev/null)
[ -n "$version" ] || { echo "check_lammps_version: no src/version.h in $src"; exit 1; }
echo "check_lammps_version: LAMMPS $version from $src"
export CLUSTERDYN_LAMMPS_SOURCE=$src
export CLUSTERDYN_BUILD_DIR=${CLUSTERDYN_BUILD_DIR:-$top/build-lammps-$(date -d "$version" +%Y%m%d)}
exec bash "$top/tools/run_tests.sh"
