#!/usr/bin/env bash
# Where pair_style mca's cost per element-step rises with the plate's width, pass by pass: a
# copy of the plugin's sources with a clock around each pass of compute() (bench/mca_pass_timer.py;
# the repository is not touched), built against the build's LAMMPS, runs the plate of
# examples/mca-shock/in.plate (aluminium at 400 m/s, 10 um elements, no records, one rank, STEPS
# steps from the impact) NARROW and WIDE fcc cells across, alternating, ROUNDS rounds.  PAD > 0:
# a second copy whose pair rows carry PAD unused doubles more (the bytes each pass streams per
# pair grow, and the saved copies with them; no arithmetic in the passes changes), run in the same
# rounds.  Beside them, in the same rounds, LAMMPS's own pair_style granular on the same plate
# with 3 and with 10 doubles of pair history (in.granular_plate; GRANULAR=0: not), and
# LAMMPS's smd/tlsph, two passes over each particle's partners with a stress between them, on
# the plate of examples/mca-shock/in.tlsph (one body, the same number of steps, free sides; 8
# particles across for 5 fcc cells, 'across' = 1.6 x cells rounded; TLSPH=0: not), with its
# Pair time per partner-step and its mean partners per particle (fewer near free sides, so
# more of them on a wider plate).  Each timed
# part includes its per-element work: the volume pass the elements' update
# and the exchange with the ghosts, the plastic pass the elements' returns.  Prints each run,
# then per build and width the median of each part (us per element-step) and the wide plate's
# over the narrow one's.  Needs git, cmake and ninja.
#   bash bench/bench_mca_passes.sh [BUILD] [STEPS] [ROUNDS] [NARROW] [WIDE]
#   (BUILD: a configured CMake build folder of the plugin, build/ by default, whose LAMMPS and
#   SIMD setting the copies take; defaults 100 steps, 3 rounds, 5 and 50 cells; PAD=8 by
#   default, PAD=0: the unpadded copy only; GRANULAR=0: no granular runs, which need LAMMPS's
#   GRANULAR package; TLSPH=0: no smd/tlsph runs, which need its MACHDYN package; a LAMMPS
#   without either package skips its runs)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
steps=${2:-100} rounds=${3:-3} narrow=${4:-5} wide=${5:-50} pad=${PAD:-8}
cache=$build/CMakeCache.txt
value() { sed -n "s/^$1:[A-Z]*=//p" "$cache"; }
lammps_root=$(value LAMMPS_ROOT) lammps_build=$(value LAMMPS_BUILD_DIR) simd=$(value CLUSTERDYN_SIMD_ARCH)
[ -n "$lammps_root" ] && [ -n "$lammps_build" ] || { echo "bench_mca_passes.sh: $build is not a configured build" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
variant() {  # name pad: a patched copy of the sources, its plugin built
  local name=$1 rows=$2
  mkdir -p "$work/$name"
  (cd "$top" && git ls-files -z --cached --others --exclude-standard | xargs -0 cp --parents -t "$work/$name")
  /usr/bin/python3 "$here/mca_pass_timer.py" "$work/$name/src" "$rows"
  cmake -S "$work/$name" -B "$work/$name/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=off \
    -DLAMMPS_ROOT="$lammps_root" -DLAMMPS_BUILD_DIR="$lammps_build" -DCLUSTERDYN_SIMD_ARCH="${simd:-native}" \
    > "$work/$name.configure.log" 2>&1 || { tail -20 "$work/$name.configure.log" >&2; exit 1; }
  cmake --build "$work/$name/build" --target clusterdynplugin > "$work/$name.build.log" 2>&1 ||
    { tail -20 "$work/$name.build.log" >&2; exit 1; }
}
builds=(as-is)
variant as-is 0
if [ "$pad" -gt 0 ]; then variant "padded+$pad" "$pad"; builds+=("padded+$pad"); fi
sed -e "s/^variable     steps equal .*/variable     steps equal $steps/" \
  "$top/examples/mca-shock/in.plate" > "$work/in.plate"
grep -q "^variable     steps equal $steps\$" "$work/in.plate" ||
  { echo "bench_mca_passes.sh: in.plate has no 'variable     steps equal' line" >&2; exit 1; }
one() {  # build cells
  (cd "$work" && LD_LIBRARY_PATH="$work/$1/build:$lammps_build" LAMMPS_PLUGIN_PATH="$work/$1/build" \
    OMP_NUM_THREADS=1 "$lammps_build/lmp" -in in.plate -log none -nocite -var metal al -var v 400 \
    -var d 1e-5 -var records 0 -var cells "$2" -var here "$top/examples/mca-shock/" 2>&1) |
    awk -v b="$1" -v c="$2" '/^Loop time of/ {n = $12; s = $9} $1 == "Pair" && $2 == "|" {p = $3}
      /PASSTIMER/ {sub(/.*PASSTIMER us\/elem-step: /, ""); t = $0}
      # the clock prints on stderr at the end, maybe before the timing breakdown: read all first
      END {
        if (t == "" || n == 0 || p == "") {printf "%s %d cells: the run failed\n", b, c; exit 1}
        split(t, f, " ")
        printf "%s %d cells: Pair %.4f volume %s plastic %s forces %s prep+after %.4f\n",
          b, c, 1e6 * p / (n * s), f[4], f[6], f[8], f[2] + f[10]
      }'
}
granular() {  # history cells: the stock style's Pair time
  (cd "$work" && LD_LIBRARY_PATH="$lammps_build" OMP_NUM_THREADS=1 "$lammps_build/lmp" \
    -in "$here/in.granular_plate" -log none -nocite -var cells "$2" -var history "$1" 2>&1) |
    awk -v b="granular-$1" -v c="$2" '/^Loop time of/ {n = $12; s = $9} $1 == "Pair" && $2 == "|" {p = $3}
      END {
        if (n == 0 || p == "") {printf "%s %d cells: the run failed\n", b, c; exit 1}
        printf "%s %d cells: Pair %.4f\n", b, c, 1e6 * p / (n * s)
      }'
}
# the plate of in.tlsph, STEPS steps; then its mean partners per particle (compute
# smd/tlsph/num/neighs: partners not broken; none break here)
{ sed -e "s/^variable     steps equal .*/variable     steps equal $steps/" "$top/examples/mca-shock/in.tlsph"
  printf '%s\n' 'compute      partners all reduce ave c_nn' 'thermo_style custom step c_partners' 'run          0 post no'
} > "$work/in.tlsph"
grep -q "^variable     steps equal $steps\$" "$work/in.tlsph" ||
  { echo "bench_mca_passes.sh: in.tlsph has no 'variable     steps equal' line" >&2; exit 1; }
tlsph() {  # cells: smd/tlsph's Pair time on a plate as wide, per particle- and partner-step
  (cd "$work" && LD_LIBRARY_PATH="$lammps_build" OMP_NUM_THREADS=1 "$lammps_build/lmp" \
    -in in.tlsph -log none -nocite -var metal al -var v 400 -var records 0 -var bodies 1 \
    -var across "$(((16 * $1 + 5) / 10))" 2>&1) |
    awk -v c="$1" '/^Loop time of/ && $9 > 0 {n = $12; s = $9} $1 == "Pair" && $2 == "|" {p = $3}
      $1 == "Step" && $2 == "c_partners" {getline; k = $2}
      END {
        if (n == 0 || p == "" || k == "") {printf "smd/tlsph %d cells: the run failed\n", c; exit 1}
        printf "smd/tlsph %d cells: Pair %.4f per-partner %.5f partners=%.2f,particles=%d\n", c,
          1e6 * p / (n * s), 1e6 * p / (n * s * k), k, n
      }'
}
packages=$("$lammps_build/lmp" -h)    # read whole: a grep -q would cut lmp's output short
has_package() { grep -qw "$1" <<< "$packages"; }
if [ "${GRANULAR:-1}" != 0 ] && ! has_package GRANULAR; then
  echo "bench_mca_passes.sh: this LAMMPS has no GRANULAR package: no pair_style granular runs" >&2; GRANULAR=0
fi
if [ "${TLSPH:-1}" != 0 ] && ! has_package MACHDYN; then
  echo "bench_mca_passes.sh: this LAMMPS has no MACHDYN package: no smd/tlsph runs" >&2; TLSPH=0
fi
[ "${GRANULAR:-1}" = 0 ] || builds_granular=(granular-3 granular-10)
[ "${TLSPH:-1}" = 0 ] || builds_granular+=(smd/tlsph)
for _ in $(seq "$rounds"); do
  for b in "${builds[@]}"; do for c in "$narrow" "$wide"; do one "$b" "$c"; done; done
  if [ "${GRANULAR:-1}" != 0 ]; then
    for h in 3 10; do for c in "$narrow" "$wide"; do granular "$h" "$c"; done; done
  fi
  if [ "${TLSPH:-1}" != 0 ]; then for c in "$narrow" "$wide"; do tlsph "$c"; done; fi
done | tee "$work/runs.txt"
echo "medians, us per element-step (granular, smd/tlsph: per atom-step, smd/tlsph also per partner-step; Pair, then the passes), and the wide plate's over the narrow one's:"
for b in "${builds[@]}" ${builds_granular[@]+"${builds_granular[@]}"}; do
  awk -v b="$b" -v nc="$narrow" -v wc="$wide" '
    function median(list,   a, n, i, j, t) {
      n = split(list, a, " ")
      for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] + 0 > a[j] + 0; j--) {t = a[j]; a[j] = a[j - 1]; a[j - 1] = t}
      return n % 2 ? a[(n + 1) / 2] : 0.5 * (a[n / 2] + a[n / 2 + 1])
    }
    $1 == b {for (k = 5; k <= 13; k += 2) if ($k != "") v[$2, k] = v[$2, k] " " $k}
    END {
      split(b == "smd/tlsph" ? "Pair per-partner" : "Pair volume plastic forces prep+after", name, " ")
      for (k = 5; k <= 13; k += 2) {
        if (v[nc, k] == "") continue
        m1 = median(v[nc, k]); m2 = median(v[wc, k])
        printf "%-11s %-11s %3d cells %.4f  %3d cells %.4f  wide/narrow %.2f\n", b, name[(k - 3) / 2], nc, m1, wc, m2, m2 / m1
      }
    }' "$work/runs.txt"
done
