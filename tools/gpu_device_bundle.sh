#!/usr/bin/env bash
# Makes .devcarry/ (git ignores it through .git/info/exclude): what bench/gpu_device_check.sh
# needs on a GPU machine that has none of this project's set-up, about 25 MB: this LAMMPS
# build's lmp and liblammps (stripped), the OpenCL ICD loader (ocl-icd), LAMMPS's Python
# module, and the plugin files built for x86-64-v3 (AVX2; the other machine's CPU is not this
# one's) in build-device/.  The GPU machine must have the NVIDIA driver's OpenCL library and an
# Open MPI 4 (libmpi.so.40).  Then, in one call there, with .devcarry carried:
#   bash bench/gpu_device_check.sh
#   source build/env.sh; bash tools/gpu_device_bundle.sh
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cache=$top/build/CMakeCache.txt
[ -f "$cache" ] || { echo "build/ first (tools/bootstrap.sh)" >&2; exit 1; }
lammps_root=$(sed -n 's/^LAMMPS_ROOT:PATH=//p' "$cache")
lammps_build=$(sed -n 's/^LAMMPS_BUILD_DIR:PATH=//p' "$cache")
cmake -S "$top" -B "$top/build-device" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DLAMMPS_ROOT="$lammps_root" -DLAMMPS_BUILD_DIR="$lammps_build" \
  -DCLUSTERDYN_SIMD_ARCH=x86-64-v3 -DBUILD_TESTING=off >/dev/null
cmake --build "$top/build-device" --target clusterdynplugin >/dev/null
grep -qx "/.devcarry/" "$top/.git/info/exclude" 2>/dev/null || echo "/.devcarry/" >>"$top/.git/info/exclude"
d=$top/.devcarry
rm -rf "$d"
mkdir -p "$d"/{lammps,lib,plugin,python}
cp "$lammps_build"/lmp "$lammps_build"/liblammps.so.0 "$d/lammps/"
strip --strip-unneeded "$d/lammps/lmp" "$d/lammps/liblammps.so.0"
ln -s liblammps.so.0 "$d/lammps/liblammps.so"
cp -L "$(ldd "$lammps_build/liblammps.so.0" | awk '/libOpenCL.so.1/ {print $3}')" "$d/lib/"
cp "$top"/build-device/clusterdynplugin.so "$top"/build-device/clusterdyn_omp.so \
  "$top"/build-device/clusterdyn_gpu.so "$d/plugin/"
cp -r "$lammps_root/python/lammps" "$d/python/"
find "$d/python" -name __pycache__ -prune -exec rm -rf {} +
du -sh "$d"
