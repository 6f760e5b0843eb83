#!/usr/bin/env bash
# Growth with N: the fcc block of in.bench_pair from 4,000 to 2,048,000 clusters, stock morse
# and morse/spline cut 1.2 one after the other: Pair ns per atom-step, the loop's ns per
# atom-step and LAMMPS's memory per cluster (bytes, "Per MPI rank memory allocation", max).
#   source build/env.sh; bash bench/bench_growth.sh [reps]
set -euo pipefail
cd "$(dirname "$0")"
reps=${1:-3}
D=2.46e-6 ALPHA=3.76e5 A=1.0e-5
echo "| clusters | style | steps | Pair (ns/atom-step), best | loop (ns/atom-step) | memory (bytes/cluster) |"
echo "|---|---|---|---|---|---|"
for n in 10 20 40 80; do
  natoms=$((4 * n * n * n))
  steps=$((64000000 / natoms))                 # the same atom-steps for every size
  [ "$steps" -lt 20 ] && steps=20
  for pair in "morse $(python3 -c "print(1.2*$A)")" "morse/spline cut 1.2"; do
    best=""
    for _ in $(seq "$reps"); do
      out=$(OMP_NUM_THREADS=1 lmp -in in.bench_pair -log none -nocite -var n "$n" -var steps "$steps" \
              -var pair "$pair" -var coeff "$D $ALPHA $A")
      line=$(awk -v N="$natoms" -v S="$steps" '
        /^Pair *\|/ {p=$3} /^Loop time/ {l=$4}
        /Per MPI rank memory allocation/ {m=$(NF-1)}
        END {printf "%.2f %.2f %.0f", p*1e9/(N*S), l*1e9/(N*S), m*1048576/N}' <<<"$out")
      if [ -z "$best" ] || awk -v a="${line%% *}" -v b="${best%% *}" 'BEGIN {exit !(a < b)}'; then
        best=$line
      fi
    done
    read -r p l m <<<"$best"
    echo "| $natoms | ${pair%% *} | $steps | $p | $l | $m |"
  done
done
