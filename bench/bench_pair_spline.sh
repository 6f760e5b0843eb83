#!/usr/bin/env bash
# Measures LAMMPS's Pair time of the spline styles against the stock styles doing the
# same work, on the same machine in one session; prints a markdown table with the best
# of $reps runs of each (the spread on a shared machine is 10-20 %).
#   source build/env.sh; bash bench/bench_pair_spline.sh [steps] [reps]
set -euo pipefail
cd "$(dirname "$0")"
steps=${1:-1000}
reps=${2:-3}
D=2.46e-6 ALPHA=3.76e5 A=1.0e-5
SIGMA=$(python3 -c "print($A*2**(-1/6))")
run() {  # label, launcher args, lmp args...: prints "| label | best pair seconds | all |"
  local label=$1; shift
  local times=()
  for _ in $(seq "$reps"); do
    times+=("$("$@" -in in.bench_pair -log none -nocite -var steps "$steps" | awk '/^Pair *\|/ {print $3}')")
  done
  printf '| %s | %s | %s |\n' "$label" "$(printf '%s\n' "${times[@]}" | sort -g | head -1)" "${times[*]}"
}
lmp_serial=(env OMP_NUM_THREADS=1 lmp)
echo "| run ($steps steps, 32000 clusters) | Pair time (s), best | all runs |"
echo "|---|---|---|"
run "morse 1.2a (stock)" "${lmp_serial[@]}" -var pair "morse $(python3 -c "print(1.2*$A)")" -var coeff "$D $ALPHA $A"
run "morse/opt 1.2a (stock OPT)" "${lmp_serial[@]}" -var pair "morse/opt $(python3 -c "print(1.2*$A)")" -var coeff "$D $ALPHA $A"
run "morse/spline cut 1.2" "${lmp_serial[@]}" -var pair "morse/spline cut 1.2" -var coeff "$D $ALPHA $A"
run "morse/spline cut 1.2 link 1.05" "${lmp_serial[@]}" -var pair "morse/spline cut 1.2 link 1.05" -var coeff "$D $ALPHA $A"
run "morse/spline cut 1.2 link 1.05 relink yes" "${lmp_serial[@]}" -var pair "morse/spline cut 1.2 link 1.05 relink yes" -var coeff "$D $ALPHA $A"
run "morse/spline wagner" "${lmp_serial[@]}" -var pair "morse/spline wagner" -var coeff "$D $ALPHA $A"
run "morse/spline lagunov 1.2" "${lmp_serial[@]}" -var pair "morse/spline lagunov 1.2" -var coeff "$D $ALPHA $A"
run "morse/spline cut 1.2, kappa 1.1" "${lmp_serial[@]}" -var pair "morse/spline cut 1.2" -var coeff "$D $ALPHA $A kappa 1.1"
run "lj/cut 1.2a (stock)" "${lmp_serial[@]}" -var pair "lj/cut $(python3 -c "print(1.2*$A)")" -var coeff "$D $SIGMA"
run "lj/cut/opt 1.2a (stock OPT)" "${lmp_serial[@]}" -var pair "lj/cut/opt $(python3 -c "print(1.2*$A)")" -var coeff "$D $SIGMA"
run "lj/spline cut 1.2" "${lmp_serial[@]}" -var pair "lj/spline cut 1.2" -var coeff "$D $A"
run "lj/spline cut 1.2, kappa 1.1" "${lmp_serial[@]}" -var pair "lj/spline cut 1.2" -var coeff "$D $A kappa 1.1"
run "morse 1.2a (stock) -sf omp, 2 threads" env OMP_NUM_THREADS=2 lmp -sf omp -pk omp 2 -var pair "morse $(python3 -c "print(1.2*$A)")" -var coeff "$D $ALPHA $A"
run "morse/spline cut 1.2 -sf omp, 2 threads" env OMP_NUM_THREADS=2 lmp -sf omp -pk omp 2 -var pair "morse/spline cut 1.2" -var coeff "$D $ALPHA $A"
run "morse/spline lagunov 1.2 -sf omp, 2 threads" env OMP_NUM_THREADS=2 lmp -sf omp -pk omp 2 -var pair "morse/spline lagunov 1.2" -var coeff "$D $ALPHA $A"
run "morse/spline cut 1.2 link 1.05 -sf omp, 2 threads" env OMP_NUM_THREADS=2 lmp -sf omp -pk omp 2 -var pair "morse/spline cut 1.2 link 1.05" -var coeff "$D $ALPHA $A"
run "morse 1.2a (stock), 2 MPI ranks" mpirun -np 2 -x OMP_NUM_THREADS=1 lmp -var pair "morse $(python3 -c "print(1.2*$A)")" -var coeff "$D $ALPHA $A"
run "morse/spline cut 1.2, 2 MPI ranks" mpirun -np 2 -x OMP_NUM_THREADS=1 lmp -var pair "morse/spline cut 1.2" -var coeff "$D $ALPHA $A"
run "morse/spline cut 1.2 link 1.05, 2 MPI ranks" mpirun -np 2 -x OMP_NUM_THREADS=1 lmp -var pair "morse/spline cut 1.2 link 1.05" -var coeff "$D $ALPHA $A"
