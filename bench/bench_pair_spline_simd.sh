#!/usr/bin/env bash
# The spline kernel on CPUs with and without AVX-512: LAMMPS's Pair and Loop times of the
# Morse tails (cut, wagner, lagunov, kappa) and lj/spline (applied as read) for each plugin
# build named, against stock morse and morse/opt, interleaved: every round runs every style
# with every build once, so that a slow spell of a shared machine falls on all of them.
# Prints a markdown table: best and median Pair time of $reps rounds (all of them), best Loop.
#   source build/env.sh
#   bash bench/bench_pair_spline_simd.sh [steps] [reps] [label=plugin.so ...]
# Default builds: native=$CLUSTERDYN_PLUGIN and avx2=$CLUSTERDYN_BUILD/unittest/clusterdyn_avx2.so
# (the test suite's -march=x86-64-v3 build: the code a CPU without AVX-512 runs).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
steps=${1:-500}
reps=${2:-5}
shift $(($# < 2 ? $# : 2))
builds=("$@")
[ ${#builds[@]} -gt 0 ] || builds=("native=$CLUSTERDYN_PLUGIN" "avx2=$CLUSTERDYN_BUILD/unittest/clusterdyn_avx2.so")
D=2.46e-6 ALPHA=3.76e5 A=1.0e-5
RC=$(python3 -c "print(1.2*$A)")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset LAMMPS_PLUGIN_PATH    # each run loads the plugin it names
styles=(  # label | pair_style | pair_coeff
  "morse/spline cut 1.2|morse/spline cut 1.2|$D $ALPHA $A"
  "morse/spline wagner|morse/spline wagner|$D $ALPHA $A"
  "morse/spline lagunov 1.2|morse/spline lagunov 1.2|$D $ALPHA $A"
  "morse/spline cut 1.2, kappa 1.1|morse/spline cut 1.2|$D $ALPHA $A kappa 1.1"
  "lj/spline cut 1.2|lj/spline cut 1.2|$D $A"
  "lj/spline lagunov 1.2|lj/spline lagunov 1.2|$D $A"
  "lj/spline wagner|lj/spline wagner|$D $A")
stock=("morse 1.2a (stock)|morse $RC|$D $ALPHA $A" "morse/opt 1.2a (stock OPT)|morse/opt $RC|$D $ALPHA $A")
record() { echo "$work/${1//[^A-Za-z0-9]/_}"; }
one() {  # key, plugin, pair, coeff: appends "pair loop" to the key's file
  printf 'plugin load %s\ninclude %s/in.bench_pair\n' "$2" "$here" > "$work/in"
  OMP_NUM_THREADS=1 lmp -in "$work/in" -log none -nocite -var steps "$steps" -var pair "$3" \
    -var coeff "$4" | awk '/^Pair *\|/ {p = $3} /^Loop time/ {l = $4} END {print p, l}' >> "$(record "$1")"
}
keys=()
for r in $(seq "$reps"); do
  for s in "${stock[@]}"; do
    IFS='|' read -r label pair coeff <<< "$s"
    one "$label" "${builds[0]#*=}" "$pair" "$coeff"
    [ "$r" -gt 1 ] || keys+=("$label")
  done
  for b in "${builds[@]}"; do
    for s in "${styles[@]}"; do
      IFS='|' read -r label pair coeff <<< "$s"
      one "$label [${b%%=*}]" "${b#*=}" "$pair" "$coeff"
      [ "$r" -gt 1 ] || keys+=("$label [${b%%=*}]")
    done
  done
done
echo "| run ($steps steps, 32000 clusters, $reps rounds) | Pair (s), best | median | all rounds | Loop (s), best |"
echo "|---|---|---|---|---|"
for k in "${keys[@]}"; do
  python3 - "$k" "$(record "$k")" <<'EOF'
import statistics, sys
rows = [line.split() for line in open(sys.argv[2])]
pair = [float(r[0]) for r in rows]
loop = [float(r[1]) for r in rows]
print(f"| {sys.argv[1]} | {min(pair):.3f} | {statistics.median(pair):.3f} | "
      f"{' '.join(f'{p:.3f}' for p in pair)} | {min(loop):.3f} |")
EOF
done
