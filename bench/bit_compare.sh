#!/usr/bin/env bash
# Compares two builds of the plugin to the last bit: forces, energies, virials, positions and
# velocities written with %.17g after the benchmark block (in.bench_pair, 200 steps, cut and
# link) and a shortened shock-3d default scene (to 0.3 us, plain and link 1.05), serial and
# -sf omp with 2 threads, and the block with the other tails, kappa and laws and with fix
# viscous/relative (serial).
# Prints one line per case, "identical" or the energies that differ.
#   bash bench/bit_compare.sh BUILD_A BUILD_B    (folders with env.sh)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
shock=$(cd "$here/../examples/shock-3d" && pwd)
a=$1 b=$2
work=$(mktemp -d)
finish='thermo_style custom step pe pxx pyy pzz pxy pxz pyz
run 0 post no
write_dump all custom final.dump id x y z vx vy vz fx fy fz modify sort id format float %.17g
print "ENERGY $(pe:%.17g) $(pxx:%.17g) $(pyy:%.17g) $(pzz:%.17g) $(pxy:%.17g) $(pxz:%.17g) $(pyz:%.17g)"'
printf 'include %s/in.bench_pair\n%s\n' "$here" "$finish" > "$work/in.block"
printf 'include %s/in.shock3d\n%s\n' "$shock" "$finish" > "$work/in.shock"
one() {  # build, tag, input, lmp args...
  local build=$1 tag=$2 input=$3; shift 3
  mkdir -p "$work/$tag" && cd "$work/$tag"
  (source "$build/env.sh"; OMP_NUM_THREADS=2 lmp -in "$work/$input" -log none -nocite "$@" \
     | grep '^ENERGY' > energy.txt)
  cd "$work"
}
case_() {  # label, input, lmp args...
  local label=$1 input=$2; shift 2
  one "$a" A "$input" "$@"
  one "$b" B "$input" "$@"
  if cmp -s A/final.dump B/final.dump && cmp -s A/energy.txt B/energy.txt; then
    echo "$label: identical ($(wc -l < A/final.dump) dump lines, $(cut -c1-40 A/energy.txt))"
  else
    echo "$label: DIFFERENT"; diff A/energy.txt B/energy.txt | head -4 || true
  fi
  rm -rf A B
}
D=2.46e-6 ALPHA=3.76e5 A_=1.0e-5
for sf in "" "-sf omp -pk omp 2"; do
  # shellcheck disable=SC2086
  case_ "block cut 1.2 $sf" in.block -var steps 200 -var temp 1e16 -var pair "morse/spline cut 1.2" -var coeff "$D $ALPHA $A_" $sf
  # shellcheck disable=SC2086
  case_ "block cut 1.2 link 1.05 $sf" in.block -var steps 200 -var temp 1e16 -var pair "morse/spline cut 1.2 link 1.05" -var coeff "$D $ALPHA $A_" $sf
  # shellcheck disable=SC2086
  case_ "shock-3d default to 0.3 us $sf" in.shock -var time 3e-7 -var records 0 $sf
  # shellcheck disable=SC2086
  case_ "shock-3d link 1.05 to 0.3 us $sf" in.shock -var time 3e-7 -var records 0 -var link 1.05 $sf
done
LJ="2.46e-6 1.0e-5"
case_ "block wagner" in.block -var steps 200 -var temp 1e16 -var pair "morse/spline wagner" -var coeff "$D $ALPHA $A_"
case_ "block lagunov 1.3 start 1.1, kappa 1.1" in.block -var steps 200 -var temp 1e16 -var pair "morse/spline lagunov 1.3 start 1.1" -var coeff "$D $ALPHA $A_ kappa 1.1"
case_ "block lj/spline cut 1.2 kappa 1.1 link 1.05" in.block -var steps 200 -var temp 1e16 -var pair "lj/spline cut 1.2 link 1.05" -var coeff "$LJ kappa 1.1"
case_ "block mie/spline lagunov 1.3" in.block -var steps 200 -var temp 1e16 -var pair "mie/spline lagunov 1.3" -var coeff "$LJ 9 6"
case_ "block cut 1.2 with fix viscous/relative J 50" in.block -var steps 200 -var temp 1e16 -var pair "morse/spline cut 1.2" -var coeff "$D $ALPHA $A_" -var dampon 1
case_ "block harmonic/spline cut 1.1" in.block -var steps 200 -var temp 1e16 -var pair "harmonic/spline cut 1.1" -var coeff "$D $ALPHA $A_"
rm -rf "$work"
