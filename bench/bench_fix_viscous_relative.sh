#!/usr/bin/env bash
# Cost of fix viscous/relative on the 32,000-cluster fcc block (in.bench_pair): LAMMPS's
# loop, Pair, Modify and Comm times with and without the fix, the run with the smallest loop
# time of $reps, the configurations interleaved (this machine's speed drifts); markdown table.
#   source build/env.sh; bash bench/bench_fix_viscous_relative.sh [steps] [reps] [threads]
# threads > 1: the /omp styles (-sf omp -pk omp threads)
set -euo pipefail
cd "$(dirname "$0")"
steps=${1:-1000}
reps=${2:-5}
threads=${3:-1}
suffix=$([ "$threads" -gt 1 ] && echo omp || true)
configs=(none "J 50" "J 50 mode normal" "J 50 mode normal weight dpd")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for r in $(seq "$reps"); do
  for k in "${!configs[@]}"; do
    damp=${configs[$k]}
    OMP_NUM_THREADS=$threads lmp -in in.bench_pair -log none -nocite ${suffix:+-sf omp -pk omp $threads} \
      -var steps "$steps" -var pair "morse/spline cut 1.2" -var coeff "2.46e-6 3.76e5 1.0e-5" \
      -var dampon "$([ "$damp" = none ] && echo 0 || echo 1)" -var damp "$damp" |
      awk '/^Loop time/ {l=$4} /^Pair *\|/ {p=$3} /^Modify *\|/ {m=$3} /^Comm *\|/ {c=$3}
           END {print l, p, m, c}' >>"$out/$k"
  done
done
echo "| run ($steps steps, 32000 clusters, morse/spline cut 1.2${suffix:+, -sf omp, $threads threads}) | loop (s) | Pair (s) | Modify (s) | Comm (s) | loop / no fix |"
echo "|---|---|---|---|---|---|"
base=$(sort -g "$out/0" | head -1 | cut -d' ' -f1)
for k in "${!configs[@]}"; do
  read -r loop pair modify comm <<<"$(sort -g "$out/$k" | head -1)"
  echo "| fix viscous/relative: ${configs[$k]} | $loop | $pair | $modify | $comm | $(awk -v a="$loop" -v b="$base" 'BEGIN {printf "%.2f", a / b}') |"
done
