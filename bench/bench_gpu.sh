#!/usr/bin/env bash
# The spline pair styles on the GPU package against stock morse/gpu doing the same work (the
# fcc block of aluminium clusters of in.bench_pair, Morse D alpha a cut at 1.2 a), and the CPU
# styles beside them: LAMMPS's loop time and the device's own force-kernel time ("Force calc"
# of the GPU package's Device Time Info), the best of $reps runs, interleaved; a markdown table
# with the ratios to stock morse/gpu on the same lists.  One command, on pocl and on a lent GPU:
#   source build/env.sh; bash bench/bench_gpu.sh [sizes] [neigh] [reps] [cpu]
#   sizes  "cells:steps ..." (4 cells^3 clusters; default "20:200 63:10": 32,000 and 1,000,188)
#   neigh  "no" (host-built lists, the default: pocl crashes on device-built ones) or "no yes"
#   cpu    the largest block the CPU styles (one core) also run (default 32000)
# The fix viscous/relative row is morse/spline/gpu with the fix's host pass beside it.
set -euo pipefail
cd "$(dirname "$0")"
sizes=${1:-"20:200 63:10"}
neighs=${2:-"no"}
reps=${3:-2}
cpu_max=${4:-32000}
MORSE="2.46e-6 3.76e5 1.0e-5"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# the runs: label | lists (neigh no/yes, or host) | pair style | extra lmp arguments
runs() {
  for nb in $neighs; do
    local pk="-pk gpu 1 neigh $nb"
    echo "morse/gpu (stock)|$nb|morse/gpu 1.2e-5|$pk"
    echo "morse/spline/gpu cut 1.2|$nb|morse/spline/gpu cut 1.2|$pk"
    echo "morse/spline/gpu wagner|$nb|morse/spline/gpu wagner|$pk"
    echo "morse/spline/gpu lagunov 1.2|$nb|morse/spline/gpu lagunov 1.2|$pk"
    echo "morse/spline/gpu cut 1.2 + fix viscous/relative J 50|$nb|morse/spline/gpu cut 1.2|$pk -var dampon 1"
  done
  if [ "$atoms" -le "$cpu_max" ]; then
    echo "morse (stock, CPU, 1 core)|host|morse 1.2e-5|"
    echo "morse/spline cut 1.2 (CPU, 1 core)|host|morse/spline cut 1.2|"
  fi
}

echo "| clusters | steps | style | lists | loop (s) | device force kernel (s) | loop / stock | kernel / stock |"
echo "|---|---|---|---|---|---|---|---|"
for size in $sizes; do
  n=${size%%:*} steps=${size##*:}
  atoms=$((4 * n * n * n))
  mapfile -t table < <(runs)
  rm -f "$out"/*
  for _ in $(seq "$reps"); do
    for k in "${!table[@]}"; do
      IFS='|' read -r _ _ pair extra <<<"${table[$k]}"
      # shellcheck disable=SC2086  # extra: words of lmp arguments
      OMP_NUM_THREADS=1 lmp -in in.bench_pair -log none -nocite -var n "$n" -var steps "$steps" \
        -var pair "$pair" -var coeff "$MORSE" $extra |
        awk '/^Loop time/ {l=$4} /^Force calc:/ {f=$3} END {print l, (f == "" ? "-" : f)}' \
        >>"$out/$k"
    done
  done
  for k in "${!table[@]}"; do
    IFS='|' read -r label lists _ _ <<<"${table[$k]}"
    read -r loop force <<<"$(sort -g "$out/$k" | head -1)"
    # the stock GPU row on the same lists (the first list mode for the CPU rows)
    ref=$lists
    [ "$lists" = host ] && ref=${neighs%% *}
    for s in "${!table[@]}"; do
      IFS='|' read -r slabel slists _ _ <<<"${table[$s]}"
      [ "$slabel" = "morse/gpu (stock)" ] && [ "$slists" = "$ref" ] && stock=$s
    done
    read -r sloop sforce <<<"$(sort -g "$out/$stock" | head -1)"
    kr=-
    [ "$force" != - ] && kr=$(awk -v a="$force" -v b="$sforce" 'BEGIN {printf "%.2f", a / b}')
    printf '| %d | %d | %s | %s | %s | %s | %.2f | %s |\n' "$atoms" "$steps" "$label" \
      "$([ "$lists" = host ] && echo "host (CPU style)" || echo "neigh $lists")" "$loop" "$force" \
      "$(awk -v a="$loop" -v b="$sloop" 'BEGIN {print a / b}')" "$kr"
  done
done
