#!/usr/bin/env bash
# Why pair_style mca's cost per element-step grows with the plate's width: two hypotheses, each
# run side by side with the plain plate, alternating, on the plate of
# examples/mca-shock/in.plate (aluminium at 400 m/s, 10 um elements, no records, one rank):
#   default   the plate as the example makes it (LAMMPS's atom sort: bins, x fastest)
#   blocked   the same elements created block by block, BLOCK x BLOCK fcc cells across each
#             (the narrow plate's width), and atom_modify sort 0 0: an element's neighbours lie
#             within its block's few thousand elements in memory, not a plane of the whole width
#   thp       the default plate with transparent huge pages for malloc's memory
#             (GLIBC_TUNABLES=glibc.malloc.hugetlb=1): fewer TLB misses
# The machine's speed wanders, so each run prints the time of every 5 steps (thermo's cpu; pe
# because the input's last line prints the pair's tallies, which need an energy): the fastest
# 5 steps and the median, in us per element-step (the loop: Pair is 97 % of it).
#   bash bench/bench_mca_locality.sh [BUILD] [STEPS] [ROUNDS] [BLOCK] [CELLS]
#   (BUILD: a folder with env.sh; defaults 100 steps, 3 rounds, blocks of 5, 50 cells across)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
examples=$(cd "$here/../examples" && pwd)
build=$(cd "${1:-$here/../build}" && pwd)
steps=${2:-100} rounds=${3:-3} block=${4:-5} cells=${5:-50}
work=$(mktemp -d)
cd "$work"
plain() {  # the example with STEPS steps and a thermo line of the elapsed time every 5 steps
  sed -e "s/^variable     steps equal .*/variable     steps equal $steps/" \
      -e 's/^thermo_style custom.*/thermo_style custom step cpu pe/' -e 's/^thermo       .*/thermo 5/' \
      -e '/^thermo_modify/d' "$examples/mca-shock/in.plate"
}
plain > in.default
# blocks of BLOCK x BLOCK cells, each the plate's whole length; the regions end just short of a
# lattice plane so that no point is made twice
{
  n=$((cells / block))
  for ((bz = 0; bz < n; bz++)); do
    for ((by = 0; by < n; by++)); do
      awk -v by="$by" -v bz="$bz" -v b="$block" 'BEGIN {
        printf "region b%d_%d block INF INF %g %g %g %g\ncreate_atoms 1 region b%d_%d\n",
          by, bz, by * b - 0.01, (by + 1) * b - 0.01, bz * b - 0.01, (bz + 1) * b - 0.01, by, bz}'
    done
  done
} > blocks
plain | sed 's/^atom_modify  map array$/atom_modify  map array sort 0 0/' |
  awk '/^create_atoms 1 box/ {while ((getline line < "blocks") > 0) print line; next} {print}' \
  > in.blocked
one() {  # label, input, cells, environment...
  local label=$1 input=$2 width=$3; shift 3
  (source "$build/env.sh"; env "$@" OMP_NUM_THREADS=1 lmp -in "$input" -log log.txt -nocite \
    -var metal al -var v 400 -var d 1e-5 -var records 0 -var cells "$width" \
    -var here "$examples/mca-shock/" > /dev/null)
  awk -v label="$label" '
    /^Loop time of/ {atoms = $12}
    /^ *Step / {t = 1; next}
    t && /^Loop/ {t = 0}
    t && $1 ~ /^[0-9]+$/ {if (n++) d[n - 1] = $2 - last; last = $2}
    END {
      k = n - 1
      for (a = 1; a <= k; a++) for (b = a + 1; b <= k; b++) if (d[b] < d[a]) {x = d[a]; d[a] = d[b]; d[b] = x}
      printf "%-34s %7d elements: fastest 5 steps %.3f, median %.3f us per element-step\n",
        label, atoms, 1e6 * d[1] / (5 * atoms), 1e6 * d[int((k + 1) / 2)] / (5 * atoms)}' log.txt
}
for r in $(seq "$rounds"); do
  echo "round $r"
  one "narrow plate ($block cells across)" in.default "$block" GLIBC_TUNABLES=
  one "wide plate ($cells cells), bin sort" in.default "$cells" GLIBC_TUNABLES=
  one "wide plate, blocks of $block cells" in.blocked "$cells" GLIBC_TUNABLES=
  one "narrow plate, huge pages" in.default "$block" GLIBC_TUNABLES=glibc.malloc.hugetlb=1
  one "wide plate, huge pages" in.default "$cells" GLIBC_TUNABLES=glibc.malloc.hugetlb=1
done
rm -rf "$work"
