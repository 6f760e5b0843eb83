#!/usr/bin/env bash
# Pair time of two builds of the plugin side by side, alternating runs in one session:
# pair_style mca on the elastic block of bench_mca.md (examples/mca-elastic/in.bpm_timing,
# 4 n^3 elements) and on bench/in.bit_mca (every part of the style: breaking, damage, yield,
# friction, welding), on the shock law's plate (examples/mca-shock/in.plate, aluminium at
# 400 m/s, 10 um elements), and morse/spline on in.bench_pair.  Prints each case's median
# Pair seconds (LAMMPS's timing breakdown, avg column) for A and B and their ratio B/A.
# With "together", A and B run at the same time, one on each of two cores (taskset; the cores
# swapped each round), so that both meet the same machine state: on a machine whose speed
# wanders between runs this reads the ratio where alternating runs scatter (both run slower
# than alone; print the median of the rounds' ratios B/A as well).
#   bash bench/bench_pair_ab.sh BUILD_A BUILD_B [repeats] [together]    (folders with env.sh)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
examples=$(cd "$here/../examples" && pwd)
a=$1 b=$2 reps=${3:-5} together=${4:-}
work=$(mktemp -d)
cd "$work"
pair_time() {  # build, input, lmp args...
  local build=$1 input=$2; shift 2
  (source "$build/env.sh"; OMP_NUM_THREADS=1 ${core:+taskset -c "$core"} lmp -in "$input" \
     -log none -nocite "$@" | awk '$1 == "Pair" && $2 == "|" {print $5}')
}
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : 0.5 * (v[NR / 2] + v[NR / 2 + 1])}'; }
case_() {  # label, input, lmp args...
  local label=$1 input=$2; shift 2
  : > A.txt; : > B.txt
  for r in $(seq "$reps"); do
    if [ "$together" = together ]; then
      core=$((r % 2)) pair_time "$a" "$input" "$@" >> A.txt &
      core=$(((r + 1) % 2)) pair_time "$b" "$input" "$@" >> B.txt
      wait
    else
      pair_time "$a" "$input" "$@" >> A.txt
      pair_time "$b" "$input" "$@" >> B.txt
    fi
  done
  local ma mb ratios=""; ma=$(median < A.txt); mb=$(median < B.txt)
  [ "$together" = together ] && ratios="  median of the rounds' B/A $(paste A.txt B.txt | awk '{printf "%.4f\n", $2 / $1}' | median)"
  echo "$label: Pair s A $ma B $mb  B/A $(awk -v a="$ma" -v b="$mb" 'BEGIN {printf "%.3f", b / a}')$ratios"
}
case_ "mca elastic block n 8, 500 steps" "$examples/mca-elastic/in.bpm_timing" -var n 8 -var steps 500
case_ "mca every part, 8 cells, 2 x 300 steps" "$here/in.bit_mca" -var cells 8
case_ "mca shock plate, aluminium at 400 m/s, 10 um" "$examples/mca-shock/in.plate" -var metal al \
  -var v 400 -var d 1e-5 -var records 0 -var here "$examples/mca-shock/"
case_ "morse/spline cut 1.2, block, 200 steps" "$here/in.bench_pair" -var steps 200 -var temp 1e16 \
  -var pair "morse/spline cut 1.2" -var coeff "2.46e-6 3.76e5 1.0e-5"
rm -rf "$work"
