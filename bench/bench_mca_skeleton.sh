#!/usr/bin/env bash
# What pair_style mca's data flow costs per element-step without its arithmetic, on plates that
# fit in the cache and plates that do not, and which other data flow would rise less with the
# width: bench/mca_memory_skeleton.cpp (the same plate, order, half list, rows and per-element
# arrays as pair mca's on examples/mca-shock's plate; each flow in its head) built with -O3 for
# the build's instruction set, each FLOW run on each width in turn, ROUNDS rounds; about
# 6 million element-steps a run.  Prints each run, then per flow and width the median of each
# part (us per element-step) and the widest plate's over the narrowest one's.
#   bash bench/bench_mca_skeleton.sh [BUILD] [ROUNDS] [WIDTHS...]
#   (BUILD: a configured CMake build folder of the plugin, build/ by default, whose
#   CLUSTERDYN_SIMD_ARCH the program takes; defaults 3 rounds, widths 5 and 50 fcc cells across,
#   3,000 and 300,000 elements; FLOWS="as-is no-rows ...": the flows to run, all by default)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/.." && pwd)
build=$(cd "${1:-$top/build}" && pwd)
rounds=${2:-3}
shift $(($# > 2 ? 2 : $#))
widths=("$@")
[ ${#widths[@]} -gt 0 ] || widths=(5 50)
flows=${FLOWS:-as-is no-rows volume-own volume-gather force-packed fused one-record}
simd=$(sed -n 's/^CLUSTERDYN_SIMD_ARCH:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null || true)
[ -n "$simd" ] || { echo "bench_mca_skeleton.sh: $build is not a configured build" >&2; exit 1; }
arch=()
[ "$simd" = off ] || arch=(-march="$simd")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"${CXX:-g++}" -O3 "${arch[@]}" -o "$work/skeleton" "$here/mca_memory_skeleton.cpp"
echo "# mca_memory_skeleton, -O3 ${arch[*]:-(no -march)}, $(date -u +%F), $rounds rounds, widths ${widths[*]}"
for r in $(seq "$rounds"); do
  for flow in $flows; do
    for w in "${widths[@]}"; do
      steps=$(( 6000000 / (120 * w * w) ))
      [ "$steps" -ge 2 ] || steps=2
      echo "round $r $("$work/skeleton" "$w" "$steps" "$flow")"
    done
  done
done | tee "$work/runs"
/usr/bin/python3 - "$work/runs" "${widths[0]}" "${widths[-1]}" <<'EOF'
import re, statistics, sys
runs, narrow, wide = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
parts = ["volume", "update", "plastic", "force", "all"]
got = {}
for line in open(runs):
    m = re.match(r"round \d+ (\S+) W (\d+) elements (\d+)", line)
    if not m:
        continue
    vals = {p: float(re.search(p + r" ([0-9.]+)", line).group(1)) for p in parts}
    got.setdefault((m.group(1), int(m.group(2))), []).append(vals)
print("\n# medians, us per element-step; last column: widest / narrowest (all)")
print("| flow | width | " + " | ".join(parts) + " | wide / narrow |")
print("|---" * (len(parts) + 3) + "|")
flows = list(dict.fromkeys(f for f, _ in got))
for f in flows:
    med = {w: {p: statistics.median(v[p] for v in got[(f, w)]) for p in parts} for (g, w) in got if g == f}
    for w in sorted(med):
        ratio = f"{med[wide]['all'] / med[narrow]['all']:.2f}" if w == wide and narrow in med else ""
        print(f"| {f} | {w} | " + " | ".join(f"{med[w][p]:.4f}" for p in parts) + f" | {ratio} |")
EOF
