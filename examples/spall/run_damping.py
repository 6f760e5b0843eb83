#!/usr/bin/python3
"""Whether to damp a spall run: the aluminium clusters' plate impact of in.spall (fcc [100],
2 x 2 cells, cut at 1.3 a) without damping and with fix viscous/relative J = 100, 50, 20, 10:
the spall threshold (3 seeds, 1 m/s thermal start, impact speeds 1.1 ... 3.0 vd), and at
each setting's lowest speed where all seeds spall the pull-back strength, the share of the
impact's kinetic energy the damping removed and the dust.  Writes damping.md; runs in
runs-damping/ are not kept.  About 6 minutes on one core.

    source ../../build/env.sh; /usr/bin/python3 run_damping.py
"""
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import mean_sd, script  # noqa: E402
from shock_records import spall_strength  # noqa: E402

JS = [0, 100, 50, 20, 10]
RATIOS = [round(1.1 + 0.1 * k, 1) for k in range(20)]
SEEDS = [1, 2, 3]


def impact(ratio, seed, J):
    """One impact: spall, the pull-back strength sigma_sp = 1/2 rho0 c_l dU (tools/pull_back.py
    with one speed, a lattice of clusters: c_b = c_l, delta = 0; rho0 of the clusters' fcc
    lattice, c_l = c0 = v0 along [100]), the removed share of the impact energy, the dust
    share."""
    with tempfile.TemporaryDirectory() as workdir:
        with script(os.path.join(HERE, "in.spall"), {"ratio": ratio, "seed": seed, "J": J,
                                                     "records": 100}, workdir, "log.lammps") as lmp:
            r = {k: float(lmp.extract_variable(k)) for k in
                 ("v", "c0", "large", "cell", "flyer", "removed", "a")}
            lmp.command("variable nflyer equal count(flyer)")
            lmp.command("variable ntarget equal count(target)")
            mass = lmp.extract_atom("mass")[1]
            r["impact"] = 0.5 * lmp.extract_variable("nflyer") * mass * r["v"] ** 2   # units si
            r["dust"] = lmp.extract_compute("parts", 0, 1)[0] / lmp.extract_variable("ntarget")
            r["rho0"] = mass / (r["a"] ** 3 / np.sqrt(2.0))
        t, v = np.loadtxt(os.path.join(workdir, "spall.visar"), usecols=(1, 2), unpack=True)
    r["sigma"] = spall_strength(t, v, 2 * r["flyer"] * r["cell"] / r["c0"], r["rho0"],
                                r["c0"]).sigma
    return r


def main():
    out = ["| damping | spall (runs of 3) from 1.1 vd | threshold / vd | pull-back strength "
           "sigma_sp = 1/2 rho0 c_l dU at the threshold (GPa) | energy removed / impact energy | dust / target |",
           "|---|---|---|---|---|---|"]
    for J in JS:
        runs = {ratio: [impact(ratio, s, J) for s in SEEDS] for ratio in RATIOS}
        counts = [sum(r["large"] >= 2 for r in runs[x]) for x in RATIOS]
        first = next((k for k in range(len(RATIOS)) if all(c == 3 for c in counts[k:])), None)
        label = "none" if J == 0 else f"J = {J}"
        shown = ", ".join(f"{x}: {c}" for x, c in zip(RATIOS, counts) if c or x in (1.1, 3.0))
        if first is None:
            out.append(f"| {label} | {shown} | above {RATIOS[-1]} | | | |")
            continue
        at = runs[RATIOS[first]]
        out.append(f"| {label} | {shown} | {RATIOS[first]} | "
                   f"{mean_sd([r['sigma'] / 1e9 for r in at], 2)} | "
                   f"{mean_sd([r['removed'] / r['impact'] for r in at], 3)} | "
                   f"{mean_sd([r['dust'] for r in at], 3)} |")
        print(out[-1], flush=True)
    out += ["", f"Aluminium clusters (al-cluster-10um, cut at 1.3 a), fcc [100], flyer 10 and "
            f"target 20 cells, 2 x 2 cells across; {len(SEEDS)} seeds per speed (1 m/s thermal "
            "start); only the speeds where some run spalled are listed; the threshold is the "
            "lowest speed from which every run spalls; sigma_sp by tools/pull_back.py with one "
            "speed (c_b = c_l = v0: Kanel's delta = 0), smoothed over a tenth of the pulse."]
    open(os.path.join(HERE, "damping.md"), "w").write("\n".join(out) + "\n")
    print("\n".join(out))


if __name__ == "__main__":
    main()
