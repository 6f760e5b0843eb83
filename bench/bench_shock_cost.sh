#!/usr/bin/env bash
# The cost of a plate impact per particle-step, side by side in one session, alternating runs:
# pair_style mca with the shock equation of state (examples/mca-shock/in.plate), LAMMPS's
# smd/tlsph on the same plate (in.tlsph, EOS_SHOCK + linear plasticity, no failure), and the
# linear elements with yield (examples/mca-spall/in.plate); aluminium at 400 m/s, no records.
# Prints each case's median Pair and Loop microseconds per particle-step (LAMMPS's timing
# breakdown) and the ratios to smd/tlsph.
# With RUNS=N (N rounds, default 0: none), a whole plate run at 400 m/s of pair mca and of
# smd/tlsph (not the linear elements), alternating, at the examples' steps (theta 0.1, cfl 0.1)
# and at the steps that keep every reading within 1 % of each method's finest run at 400 and
# 1000 m/s (theta 0.025; cfl 0.0125 or finer: the tables of examples/mca-shock/time_step_peers.md;
# smd/tlsph with its pairwise failure, as there): the median loop seconds of a run and their
# ratio.
#   [RUNS=N] bash bench/bench_shock_cost.sh [BUILD] [repeats]    (BUILD: a folder with env.sh)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
examples=$(cd "$here/../examples" && pwd)
build=${1:-$here/../build} reps=${2:-3}
work=$(mktemp -d)
cd "$work"
one() {  # input, lmp args... -> "pair_us loop_us" per particle-step
  local input=$1; shift
  (source "$build/env.sh"; OMP_NUM_THREADS=1 lmp -in "$input" -log none -nocite "$@") | awk '
    /^Loop time of/ {loop = $4; steps = $9; atoms = $12}
    $1 == "Pair" && $2 == "|" {pair = $5}
    END {printf "%.4f %.4f %.3f %d\n", 1e6 * pair / (atoms * steps), 1e6 * loop / (atoms * steps), loop, steps}'
}
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : 0.5 * (v[NR / 2] + v[NR / 2 + 1])}'; }
: > mca.txt; : > tlsph.txt; : > linear.txt
for _ in $(seq "$reps"); do
  one "$examples/mca-shock/in.plate" -var metal al -var v 400 -var records 0 -var d 1e-5 \
    -var here "$examples/mca-shock/" >> mca.txt
  one "$examples/mca-shock/in.tlsph" -var metal al -var v 400 -var records 0 -var bodies 1 >> tlsph.txt
  one "$examples/mca-spall/in.plate" -var method mca -var v 400 -var records 0 -var yield 0.29e9 \
    -var K 77.37e9 -var G 26e9 -var rho 2703 >> linear.txt
done
for c in mca tlsph linear; do
  echo "$c $(cut -d' ' -f1 $c.txt | median) $(cut -d' ' -f2 $c.txt | median)"
done | awk '{pair[$1] = $2; loop[$1] = $3; order[NR] = $1}
  END {for (k = 1; k <= 3; k++) {c = order[k]; printf "%-7s Pair %.3f us, loop %.3f us per particle-step; / tlsph: Pair %.2f, loop %.2f\n", c, pair[c], loop[c], pair[c] / pair["tlsph"], loop[c] / loop["tlsph"]}}'

runs=${RUNS:-0}
[ "$runs" -gt 0 ] || exit 0
: > runs.txt
plate() {  # theta -> "loop steps" of the elements' plate run
  one "$examples/mca-shock/in.plate" -var metal al -var v 400 -var records 0 -var d 1e-5 \
    -var here "$examples/mca-shock/" -var theta "$1" | cut -d' ' -f3,4
}
tlsph() {  # cfl -> "loop steps" of smd/tlsph's plate run
  one "$examples/mca-shock/in.tlsph" -var metal al -var v 400 -var records 0 -var bodies 1 \
    -var failure pairwise -var cfl "$1" | cut -d' ' -f3,4
}
for _ in $(seq "$runs"); do
  echo "default mca $(plate 0.1)" >> runs.txt
  echo "default tlsph $(tlsph 0.1)" >> runs.txt
  echo "bound1 mca $(plate 0.025)" >> runs.txt
  echo "bound1 tlsph $(tlsph 0.0125)" >> runs.txt
done
for step in default bound1; do
  m=$(awk -v s=$step '$1 == s && $2 == "mca" {print $3}' runs.txt | median)
  t=$(awk -v s=$step '$1 == s && $2 == "tlsph" {print $3}' runs.txt | median)
  ms=$(awk -v s=$step '$1 == s && $2 == "mca" {print $4; exit}' runs.txt)
  ts=$(awk -v s=$step '$1 == s && $2 == "tlsph" {print $4; exit}' runs.txt)
  label=$([ $step = default ] && echo "at the examples' steps (theta 0.1, cfl 0.1)" ||
    echo "with every reading within 1 % (theta 0.025, cfl 0.0125 or finer)")
  awk -v l="$label" -v m=$m -v t=$t -v ms=$ms -v ts=$ts 'BEGIN {printf "a plate run %s: mca %.2f s (%d steps), tlsph %.2f s (%d steps); mca / tlsph %.2f\n", l, m, ms, t, ts, m / t}'
done
