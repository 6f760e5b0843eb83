#!/usr/bin/env bash
# The cost and the memory of pair_style mca with the shock law against the plate's width: the
# plate of examples/mca-shock/in.plate (aluminium at 400 m/s, 10 um elements, no records) with
# CELLS x CELLS fcc cells across (5: 3,050 elements ... 50: 305,000), a short run of STEPS steps
# from the impact on one rank (and on 2 ranks for the widest).  Prints per width: the elements,
# the neighbours per element (LAMMPS's count, half list), LAMMPS's Pair and Neigh time per
# element-step (timing breakdown), its memory report per element (the ranks' sum: their mean
# times their number) at the run's setup and at a run 0 after it (a list build from the saved
# pairs: the pages at their high water), and the
# energy (ke + pe + rotation) and the links broken at the last step (the widest plate on 1 and
# 2 ranks: the same result).
#   bash bench/bench_mca_scale.sh [BUILD] [STEPS] [CELLS...]    (BUILD: a folder with env.sh)
# ROUNDS=N (default 1): the widths in turn N times on one rank, then each width's median Pair
# time and the widest's median against the narrowest's (short runs of a small plate scatter by
# 1.5x on a machine whose speed wanders: one round does not read the rise).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
examples=$(cd "$here/../examples" && pwd)
build=$(cd "${1:-$here/../build}" && pwd) steps=${2:-200}
shift $(( $# > 2 ? 2 : $# ))
widths=("$@")
[ ${#widths[@]} -gt 0 ] || widths=(5 10 20 32 50)
work=$(mktemp -d)
cd "$work"
# in.plate with a run of $steps steps, then a run 0
sed -e "s/^variable     steps equal .*/variable     steps equal $steps/" \
  -e 's/^run          ${steps}$/&\nrun 0/' "$examples/mca-shock/in.plate" > in.plate
grep -q "^run 0" in.plate || { echo "bench_mca_scale.sh: in.plate has no 'run \${steps}' line" >&2; exit 1; }
one() {  # ranks cells
  local ranks=$1 cells=$2
  (source "$build/env.sh"; OMP_NUM_THREADS=1 mpirun -np "$ranks" --oversubscribe lmp \
    -in in.plate -log none -nocite -var metal al -var v 400 -var d 1e-5 -var records 0 \
    -var cells "$cells" -var here "$examples/mca-shock/") | awk -v ranks="$ranks" -v cells="$cells" '
    /Per MPI rank memory allocation/ {if (mem0 == "") mem0 = $(NF - 3); mem = $(NF - 3)}
    /^Loop time of/ && !done {steps = $9; atoms = $12}
    $1 == "Pair" && $2 == "|" && !done {pair = $5}
    $1 == "Neigh" && $2 == "|" && !done {neigh = $5; done = 1}
    /^Ave neighs\/atom/ {nb = $4}
    /^ *Step / {thermo = 1; next}
    thermo && /^Loop time/ {thermo = 0}
    thermo && !done && $1 ~ /^[0-9]+$/ {energy = $6; broken = $7}
    END {
      printf "%2d ranks %3d cells: %7d elements, %5.1f neighbours each; Pair %.3f us, Neigh %.3f us per element-step; memory %.2f kB per element (%.2f after the run); energy %s J, %s links broken\n",
        ranks, cells, atoms, nb, 1e6 * pair / (atoms * steps), 1e6 * neigh / (atoms * steps),
        mem0 * ranks * 1048.576 / atoms, mem * ranks * 1048.576 / atoms, energy, broken}'
}
rounds=${ROUNDS:-1}
for _ in $(seq "$rounds"); do
  for c in "${widths[@]}"; do one 1 "$c"; done
done | tee runs.txt
one 2 "${widths[-1]}"
if [ "$rounds" -gt 1 ]; then
  for c in "${widths[@]}"; do
    awk -v c="$c" '$3 == c"" && $4 == "cells:" {print $11}' runs.txt | sort -g |
      awk -v c="$c" '{v[NR] = $1} END {m = (NR % 2) ? v[(NR + 1) / 2] : 0.5 * (v[NR / 2] + v[NR / 2 + 1]);
        printf "median of %d rounds, %3d cells: Pair %.3f us per element-step (%.3f-%.3f)\n", NR, c, m, v[1], v[NR]}'
  done | tee medians.txt
  awk 'NR == 1 {first = $8} {last = $8} END {printf "widest / narrowest: %.2fx\n", last / first}' medians.txt
fi
