#!/usr/bin/env bash
# The GPU check on a machine with a GPU that has none of this project's set-up: the bundle
# tools/gpu_device_bundle.sh made (.devcarry: lmp, liblammps, the OpenCL ICD loader, the plugin
# files built for x86-64-v3, LAMMPS's Python module), NVIDIA's OpenCL through that loader; the
# tests of the /gpu styles and of stock morse/gpu with host-built and device-built lists, then
# bench/bench_gpu.sh.  Output under $OUT (default /tmp/out).  From the repository's root:
#   bash bench/gpu_device_check.sh ["cells:steps ..."] [reps]     (about 6 min on an H200)
set -uo pipefail
here=$(cd "$(dirname "$0")/../.devcarry" && pwd) || { echo "no .devcarry: run tools/gpu_device_bundle.sh"; exit 1; }
OUT=${OUT:-/tmp/out}; mkdir -p "$OUT"
nv=$(ls /usr/local/nvidia/lib64/libnvidia-opencl.so.1 2>/dev/null || true)
if [ -n "$nv" ]; then echo libnvidia-opencl.so.1 > /tmp/nv.icd; export OCL_ICD_VENDORS=/tmp/nv.icd; fi
export LD_LIBRARY_PATH="$here/lib:$here/lammps:$here/plugin:/usr/local/nvidia/lib64${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PATH="$here/lammps:$PATH" PYTHONPATH="$here/python"
export LAMMPS_PLUGIN_PATH="$here/plugin" CLUSTERDYN_PLUGIN="$here/plugin/clusterdynplugin.so"
export CLUSTERDYN_LMP="$here/lammps/lmp" OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export PYTHONDONTWRITEBYTECODE=1 PYTHONUNBUFFERED=1
sizes=${1:-"20:500 63:100"}
reps=${2:-3}
{ nvidia-smi -L; lscpu | grep -m1 "Model name"; } 2>&1 | tee "$OUT/device.txt"
for nb in no yes; do
  start=$(date +%s)
  CLUSTERDYN_GPU_NEIGH=$nb timeout 100 python3 -m pytest -q -p no:cacheprovider --tb=short \
    unittest/python/test_pair_spline_gpu.py unittest/python/test_gpu_package.py \
    > "$OUT/pytest_neigh_$nb.txt" 2>&1
  echo "neigh $nb: $(tail -1 "$OUT/pytest_neigh_$nb.txt") ($(( $(date +%s) - start )) s)" | tee -a "$OUT/device.txt"
done
grep -E "^(FAILED|E  )" "$OUT/pytest_neigh_yes.txt" | cut -c1-300 | head -40
start=$(date +%s)
timeout 270 bash bench/bench_gpu.sh "$sizes" "no yes" "$reps" 32000 | tee "$OUT/bench_gpu.md"
echo "bench: $(( $(date +%s) - start )) s" | tee -a "$OUT/device.txt"
