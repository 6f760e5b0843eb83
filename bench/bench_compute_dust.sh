#!/usr/bin/env bash
# Cost of compute dust on the 32,000-cluster fcc block (in.bench_pair, morse/spline cut 1.2):
# loop time without and with c_dust in the thermo output, evaluated every 100 steps and, to
# resolve the cost of one evaluation, every step; best of $reps runs; markdown table.
#   source build/env.sh; bash bench/bench_compute_dust.sh [steps] [reps]
set -euo pipefail
cd "$(dirname "$0")"
steps=${1:-2000}
reps=${2:-3}
loop() {  # steps, thermo interval, dust flag: best loop time
  for _ in $(seq "$reps"); do
    OMP_NUM_THREADS=1 lmp -in in.bench_pair -log none -nocite -var steps "$1" \
      -var pair "morse/spline cut 1.2" -var coeff "2.46e-6 3.76e5 1.0e-5" \
      -var thermoevery "$2" -var dust "$3" | awk '/^Loop time/ {print $4}'
  done | sort -g | head -1
}
echo "| run (32000 clusters, morse/spline cut 1.2) | without (s) | with c_dust (s) | overhead |"
echo "|---|---|---|---|"
for every in 100 1; do
  n=$([ "$every" = 1 ] && echo 200 || echo "$steps")
  without=$(loop "$n" "$every" 0)
  with=$(loop "$n" "$every" 1)
  awk -v a="$without" -v b="$with" -v n="$n" -v e="$every" 'BEGIN {
    printf "| %d steps, evaluated every %d | %.3f | %.3f | %+.1f %% (%.1f ms per evaluation) |\n",
      n, e, a, b, 100*(b-a)/a, 1000*(b-a)/(n/e+1) }'
done
