#!/usr/bin/env bash
# The upsetting runs of README section 3: the named runs (their tables upset-*.dat and shapes
# upset-*.dump feed plot_subsystem.py; logs log.upset-*; none of these is tracked) and, for the
# plastic ones, ensembles of 5 seeds (every atom displaced by up to 1e-9 a: the hops are chaotic,
# one run is one sample).  Summary lines: upset_runs.txt (tracked: section 3's table).
#   source ../../build/env.sh; bash run_upset.sh      # about 4 min
set -euo pipefail
cd "$(dirname "$0")"
rm -f upset_runs.txt
slow=(-var speed 1e-5 -var h 1e-4)
fast=(-var speed 1e-3 -var h 1e-2)
inertia=(-var inertia "inertia 10 0.5")
declare -A cases=(
  [upset-slow-6]="-var strain 0.06 slow"
  [upset-fast-6]="-var strain 0.06 fast"
  [upset-fast-6-inertia]="-var strain 0.06 fast inertia"
  [upset-fast]="-var strain 0.3 fast"
  [upset-fast-inertia]="-var strain 0.3 fast inertia"
  [upset-fast-slide]="-var strain 0.3 fast -var stick 0"
  [upset-slow]="-var strain 0.3 slow"
)
args() {  # the lmp arguments of a case
  local a=()
  for w in ${cases[$1]}; do
    case $w in
      slow) a+=("${slow[@]}") ;;
      fast) a+=("${fast[@]}") ;;
      inertia) a+=("${inertia[@]}") ;;
      *) a+=("$w") ;;
    esac
  done
  printf '%s\n' "${a[@]}"
}
for name in upset-slow-6 upset-fast-6 upset-fast-6-inertia upset-fast upset-fast-inertia \
            upset-fast-slide upset-slow; do
  mapfile -t a < <(args "$name")
  lmp -in in.upset -var out "$name" -log "log.$name" -screen none "${a[@]}"
done
for name in upset-fast-6 upset-fast-6-inertia upset-fast upset-fast-inertia upset-fast-slide; do
  mapfile -t a < <(args "$name")
  for seed in 1 2 3 4 5; do
    lmp -in in.upset -var seed "$seed" -log none -screen none "${a[@]}" \
      -var out "ensemble-$name"
  done
done
rm -f ensemble-*.dat ensemble-*.dump
cat upset_runs.txt
