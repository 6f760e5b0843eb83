#!/usr/bin/env bash
# Cost of fix viscous/relative on the 32,000-cluster fcc block (in.bench_pair): LAMMPS's
# Pair and Modify times with and without the fix, best of $reps runs; markdown table.
#   source build/env.sh; bash doc/benchmarks/bench_fix_viscous_relative.sh [steps] [reps]
set -euo pipefail
cd "$(dirname "$0")"
steps=${1:-1000}
reps=${2:-3}
times() {  # damp args: prints "pair modify" of the run with the smallest total
  for _ in $(seq "$reps"); do
    OMP_NUM_THREADS=1 lmp -in in.bench_pair -log none -nocite -var steps "$steps" \
      -var pair "morse/spline cut 1.2" -var coeff "2.46e-6 3.76e5 1.0e-5" \
      -var dampon "$([ "$1" = none ] && echo 0 || echo 1)" -var damp "$1" |
      awk '/^Pair *\|/ {p=$3} /^Modify *\|/ {m=$3} END {print p+m, p, m}'
  done | sort -g | head -1 | cut -d' ' -f2-
}
echo "| run ($steps steps, 32000 clusters, morse/spline cut 1.2) | Pair (s) | Modify (s) |"
echo "|---|---|---|"
for damp in none "J 50" "J 50 mode normal" "J 50 mode normal weight dpd"; do
  read -r pair modify <<<"$(times "$damp")"
  echo "| fix viscous/relative: $damp | $pair | $modify |"
done
