#!/usr/bin/env bash
# Cost of one fix descent/normalized iteration (plain, and with inertia 20 0.99) against one
# velocity-Verlet step (fix nve) on the same 2D lattice (in.bench_descent, 40,000 particles):
# LAMMPS's Pair, Modify and loop times, best of $reps runs each; markdown table.
#   source build/env.sh; bash bench/bench_fix_descent_normalized.sh [steps] [reps]
set -euo pipefail
cd "$(dirname "$0")"
steps=${1:-1000}
reps=${2:-3}
times() {  # integrator: prints "pair modify loop" of the run with the smallest loop time
  for _ in $(seq "$reps"); do
    OMP_NUM_THREADS=1 lmp -in in.bench_descent -log none -nocite -var steps "$steps" \
      -var integrator "$1" |
      awk '/^Pair *\|/ {p=$3} /^Modify *\|/ {m=$3} /^Loop time/ {l=$4} END {print l, p, m}'
  done | sort -g | head -1 | awk '{print $2, $3, $1}'
}
echo "| run ($steps steps, 40,000 particles, mie/spline cut 1.1 link 1.05) | Pair (s) | Modify (s) | Loop (s) |"
echo "|---|---|---|---|"
for integrator in nve descent inertia; do
  read -r pair modify loop <<<"$(times "$integrator")"
  echo "| $integrator | $pair | $modify | $loop |"
done
