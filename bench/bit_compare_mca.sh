#!/usr/bin/env bash
# Compares two builds of the plugin to the last bit on pair_style mca: positions, velocities,
# forces, torques, angular velocities, compute mca/atom and the pair's tallies written with %.17g
# after bench/in.bit_mca (every part of the style at once), serial, on 2 ranks, with newton off
# and without the many-body term, and after the reduced runs of the MCA examples (elastic
# pulse, fracture bar, spall plate with and without yield; the shock law's plate of
# examples/mca-shock with its links' strength).  compute mca/atom's first 10 columns (the 11th,
# the spall kinetics' damage, came later).
# Prints one line per case, "identical", "the same trajectory" (the dump alike, the energy line
# not: pe and the pair's tallies), or DIFFERENT with each quantity's largest difference over its
# largest value (positions across a periodic boundary by their minimum image; torques and spins
# with their largest value, round-off in a plate) and the energy lines.
#   bash bench/bit_compare_mca.sh BUILD_A BUILD_B    (folders with env.sh)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
examples=$(cd "$here/../examples" && pwd)
a=$1 b=$2
work=$(mktemp -d)
finish='compute bitstress all mca/atom
compute bitpair all pair mca
thermo_style custom step pe pxx pxz
run 0 post no
write_dump all custom final.dump id x y z vx vy vz fx fy fz tqx tqy tqz omegax omegay omegaz c_bitstress[1] c_bitstress[2] c_bitstress[3] c_bitstress[4] c_bitstress[5] c_bitstress[6] c_bitstress[7] c_bitstress[8] c_bitstress[9] c_bitstress[10] modify sort id format float %.17g
print "ENERGY $(pe:%.17g) $(pxx:%.17g) $(pxz:%.17g) $(c_bitpair[1]:%.17g) $(c_bitpair[2]:%.17g) $(c_bitpair[3]:%.17g) $(c_bitpair[4]:%.17g) $(c_bitpair[5]:%.17g) $(c_bitpair[6]:%.17g)"'
printf 'include %s/in.bit_mca\n%s\n' "$here" "$finish" > "$work/in.all"
for ex in mca-elastic/in.pulse mca-fracture/in.bar mca-spall/in.plate mca-shock/in.plate; do
  printf 'include %s/%s\n%s\n' "$examples" "$ex" "$finish" > "$work/in.$(basename "$(dirname "$ex")")"
done
one() {  # build, tag, input, ranks, lmp args...
  local build=$1 tag=$2 input=$3 ranks=$4; shift 4
  mkdir -p "$work/$tag" && cd "$work/$tag"
  (source "$build/env.sh"; mpirun -np "$ranks" --oversubscribe lmp -in "$work/$input" -log none \
     -nocite "$@" | grep '^ENERGY' > energy.txt)
  cd "$work"
}
largest_difference() {  # two dumps -> the quantity that differs most, relative to its largest value
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
def read(path):
    lines = open(path).read().splitlines()
    head = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    box = next(k for k, l in enumerate(lines) if l.startswith("ITEM: BOX BOUNDS"))
    lengths = [float(l.split()[1]) - float(l.split()[0]) for l in lines[box + 1:box + 4]]
    return lines[head].split()[2:], [[float(v) for v in l.split()] for l in lines[head + 1:]], lengths
names, a, lengths = read(sys.argv[1])
_, b, _ = read(sys.argv[2])
# a position wrapped to the other side of a periodic box is the same position
for p, q in zip(a, b):
    for k, n in enumerate(("x", "y", "z")):
        if n in names:
            c = names.index(n)
            q[c] -= lengths[k] * round((q[c] - p[c]) / lengths[k])
if len(a) != len(b):
    print(f"{len(a)} against {len(b)} atoms")
    sys.exit()
# a vector's or a tensor's components are read against the largest of them (a column that is
# zero but for round-off, as fy of a plate, would read its round-off against itself)
groups = {"x": ["x", "y", "z"], "v": ["vx", "vy", "vz"], "f": ["fx", "fy", "fz"],
          "torque": ["tqx", "tqy", "tqz"], "omega": ["omegax", "omegay", "omegaz"],
          "stress": [f"c_bitstress[{k}]" for k in range(1, 7)]}
grouped = {n for g in groups.values() for n in g}
groups.update({n: [n] for n in names[1:] if n not in grouped})
worst, scales = [], []
for label, members in groups.items():
    cols = [names.index(n) for n in members if n in names]
    scale = max(abs(p[c]) for p in a for c in cols) or 1.0
    worst.append((max(abs(p[c] - q[c]) for p, q in zip(a, b) for c in cols) / scale, label))
    scales.append(scale)
print("largest difference over the largest value: " +
      ", ".join(f"{label} {d:.0e}" for d, label in worst if label not in ("torque", "omega")) +
      "; " + ", ".join(f"{label} {d:.0e} (largest {scale:.0e})" for d, label, scale in
                        ((d, l, s) for (d, l), s in zip(worst, scales)) if label in ("torque", "omega")))
PY
}
case_() {  # label, input, ranks, lmp args...
  local label=$1 input=$2 ranks=$3; shift 3
  one "$a" A "$input" "$ranks" "$@"
  one "$b" B "$input" "$ranks" "$@"
  if cmp -s A/final.dump B/final.dump && cmp -s A/energy.txt B/energy.txt; then
    echo "$label: identical ($(wc -l < A/final.dump) dump lines, $(cut -c1-60 A/energy.txt))"
  elif cmp -s A/final.dump B/final.dump; then
    echo "$label: the same trajectory (positions, velocities, forces, torques, stresses), other energies"
    diff A/energy.txt B/energy.txt | head -4 || true
  else
    echo "$label: DIFFERENT ($(largest_difference A/final.dump B/final.dump))"
    diff A/energy.txt B/energy.txt | head -4 || true
  fi
  rm -rf A B
}
case_ "every part, serial" in.all 1
case_ "every part, 2 ranks" in.all 2
case_ "every part, newton off, 2 ranks" in.all 2 -var newton off
case_ "every part, manybody no" in.all 1 -var manybody no
case_ "elastic pulse (reduced)" in.mca-elastic 1 -var n 3
case_ "fracture bar (reduced)" in.mca-fracture 1 -var n 3 -var steps 3000 -var every 500
case_ "spall plate (reduced)" in.mca-spall 1 -var flyer 4 -var target 8 -var cells 3 -var records 0
case_ "spall plate with yield (reduced)" in.mca-spall 1 -var flyer 4 -var target 8 -var cells 3 -var records 0 -var yield 0.3e9
case_ "shock plate, links' strength (reduced)" in.mca-shock 1 -var flyer 4 -var target 8 -var cells 3 -var records 0 -var v 1000 -var d 1e-5 -var fracture threshold -var here "$examples/mca-shock/"
rm -rf "$work"
