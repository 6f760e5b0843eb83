#!/usr/bin/python3
"""Spall thresholds against the dissociation speed vd = sqrt(2D/m) (Krivtsov & Krivtsova
2002, doc/references.rst) on in.spall, for Morse (aluminium clusters, alpha a = 3.76;
alpha a = 6) and Lennard-Jones on fcc, and the aluminium clusters on the 2D triangular lattice.

    source build/env.sh; /usr/bin/python3 examples/spall/run_spall.py

Writes results.md and spall.png next to this file; then the spall records (free-surface
velocity histories with their pull-back, x-t diagrams) of ensembles at a few impact speeds,
run in runs/: records.md and spall_records.png.
"""
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import mean_sd, script, tag  # noqa: E402
from shock_records import XT, plot_xt, spall_strength  # noqa: E402

CASES = {  # label: in.spall settings
    "Morse, alpha a = 3.76 (aluminium clusters)": {"pot": "al-cluster-10um"},
    "Morse, alpha a = 6": {"pot": "morse-lj-match"},
    "Lennard-Jones": {"pot": "lj-reduced"},
    "aluminium clusters, 2D triangular lattice": {"pot": "al-cluster-10um", "dim": 2, "cells": 4},
}
RATIOS = [round(0.6 + 0.05 * k, 2) for k in range(21)]   # v / vd = 0.6 ... 1.6


def run(ratio, pot="al-cluster-10um", **var):
    """One impact; returns spall (bool), the spalled share of the target, the wall time, and
    the energy the damping removed (-var J) with the impact's kinetic energy."""
    start = time.time()
    with script(os.path.join(HERE, "in.spall"), {"ratio": ratio, "pot": pot, "records": 0,
                                                 **var}) as lmp:
        large = lmp.extract_variable("large")
        removed = lmp.extract_variable("removed")        # by the damping (-var J)
        lmp.command("variable nflyer equal count(flyer)")
        impact = 0.5 * lmp.extract_variable("nflyer") * lmp.extract_atom("mass")[1] * \
            lmp.extract_variable("v") ** 2               # mass x velocity^2: si and lj energy
        parts = np.array(lmp.gather("c_parts", 1, 3)).reshape(-1, 3)
        x = np.array(lmp.gather_atoms("x", 1, 3)).reshape(-1, 3)[:, 0]
    intarget = parts[:, 1] > 0
    big = intarget & (parts[:, 2] == 0)
    ids = np.unique(parts[big, 0])
    rear_share = 0.0
    if len(ids) >= 2:  # the spalled layer: the large fragment furthest from the impact
        rear = max(ids, key=lambda i: x[parts[:, 0] == i].mean())
        rear_share = np.sum(parts[:, 0] == rear) / np.sum(intarget)
    return {"spall": large >= 2, "share": rear_share, "seconds": time.time() - start,
            "removed": removed, "impact": impact}


# the records: (label, in.spall settings, longitudinal speed / v0 along the impact: Krivtsov &
# Krivtsova's Table 2, fcc along the fourfold axis 1.00, the triangular lattice 1.06)
RECORDS = [("aluminium clusters, fcc [100], 4x4 cells", {"pot": "al-cluster-10um", "cells": 4}, 1.00),
           ("aluminium clusters, 2D triangular, 16 cells", {"pot": "al-cluster-10um", "dim": 2,
                                                            "cells": 16}, 1.06)]
RECORD_RATIOS = [1.3, 1.5, 2.0]
SEEDS = [1, 2, 3]


def record(ratio, seed, lam, root=os.path.join(HERE, "runs"), **var):
    """One impact with records (in a folder under root): the free-surface velocity history,
    its pull-back dU and the spall strength sigma_sp = 1/2 rho0 c_l dU (tools/pull_back.py
    with one speed: a lattice of clusters has no elastic-plastic release, c_b = c_l, delta = 0;
    rho0 from the x-t density of the target at the start, c_l = lam v0), next to the largest
    tension of the x-t virial pressure."""
    workdir = os.path.join(root, tag(dict(var, ratio=ratio, seed=seed)))
    os.makedirs(workdir, exist_ok=True)
    with script(os.path.join(HERE, "in.spall"), {"ratio": ratio, "seed": seed, **var}, workdir,
                "log.lammps") as lmp:
        r = {k: float(lmp.extract_variable(k)) for k in ("v", "vd", "c0", "large", "cell", "flyer")}
        r["dt"] = lmp.extract_global("dt")
        # 2D: densities and pressures per area and per length; per volume over the thickness
        thick = lmp.extract_global("boxzhi") - lmp.extract_global("boxzlo")
        r["per"] = thick if var.get("dim") == 2 else 1.0
    xt = XT(os.path.join(workdir, "spall.xt"), r["dt"])
    xt.density /= r["per"]
    xt.pressure /= r["per"]
    t, v = np.loadtxt(os.path.join(workdir, "spall.visar"), usecols=(1, 2), unpack=True)
    c0 = lam * r["c0"]
    flyer_transit = 2 * r["flyer"] * r["cell"] / c0    # the compression pulse's duration
    target = xt.x > (r["flyer"] + 2) * r["cell"]
    rho0 = np.nanmedian(xt.density[target, 0])
    got = spall_strength(t, v, flyer_transit, rho0, c0)
    r.update(t=t, vfs=v, xt=xt, peak=(got.t_peak, got.v_peak), low=(got.t_min, got.v_min),
             rho0=rho0, c0l=c0, sigma=got.sigma, tension=-np.nanmin(xt.pressure))
    return r


def records_section(thresholds):
    out = ["## Spall records: free-surface velocity, pull-back and spall strength", "",
           "| lattice | impact / vd | spall (runs) | peak U_fs (m/s) | pull-back dU (m/s) | "
           "spall strength sigma_sp = 1/2 rho0 c_l dU (GPa) | largest virial tension (GPa) | "
           "1/2 rho0 c0 v at the threshold (GPa) |", "|---|---|---|---|---|---|---|---|"]
    shown = {}
    for label, settings, lam in RECORDS:
        for ratio in RECORD_RATIOS:
            runs = [record(ratio, seed, lam, **settings) for seed in SEEDS]
            shown[(label, ratio)] = runs[0]
            dU = [r["peak"][1] - r["low"][1] for r in runs]
            thr = thresholds.get(label)
            at_threshold = (0.5 * runs[0]["rho0"] * runs[0]["c0l"] * thr * runs[0]["vd"] / 1e9
                            if thr else float("nan"))
            out.append(f"| {label} | {ratio} | {sum(r['large'] >= 2 for r in runs)}/{len(runs)} | "
                       f"{np.mean([r['peak'][1] for r in runs]):.0f} | {np.mean(dU):.0f} ± "
                       f"{np.std(dU, ddof=1):.0f} | {mean_sd([r['sigma'] / 1e9 for r in runs])} | "
                       f"{mean_sd([r['tension'] / 1e9 for r in runs])} | {at_threshold:.2f} |")
    out += ["", f"Ensembles of {len(SEEDS)} seeds (1 m/s thermal start), mean ± sd; rho0 from "
            "the x-t density of the target at the start, c_l = c0 = v0 (fcc [100]) or 1.06 v0 "
            "(triangular), v0 from compute pair/params; sigma_sp by tools/pull_back.py with one "
            "speed (a lattice of clusters: c_b = c_l, Kanel's delta = 0; smoothed over a tenth "
            "of the pulse 2 H / c_l); the threshold from the sweep above (2x2 cells).", ""]
    plot_records(shown)
    return out


def plot_records(shown):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig = plt.figure(figsize=(14, 8))
    grid = fig.add_gridspec(2, 3)
    for k, (label, _, _) in enumerate(RECORDS):
        ax = fig.add_subplot(grid[0, k])
        for ratio in RECORD_RATIOS:
            r = shown[(label, ratio)]
            line, = ax.plot(r["t"] * 1e9, r["vfs"], lw=0.8, label=f"{ratio} vd")
            ax.plot([r["peak"][0] * 1e9, r["low"][0] * 1e9], [r["peak"][1], r["low"][1]], "o",
                    color=line.get_color())
        ax.set_xlabel("time (ns)")
        ax.set_ylabel("free-surface velocity (m/s)")
        ax.set_title(label, fontsize=9)
        ax.legend(fontsize=8)
    r = shown[(RECORDS[0][0], 1.5)]
    axes = [fig.add_subplot(grid[1, k]) for k in range(3)]
    plot_xt(fig, axes, r["xt"], "fcc [100], 1.5 vd: impact, release fans, spall plane")
    ax = fig.add_subplot(grid[0, 2])
    ax.axis("off")
    ax.text(0, 0.5, "dots: peak and pull-back minimum\n(running mean over a tenth of the pulse)\n\n"
            "spall strength = 1/2 rho0 c_l (U_peak - U_min)\n(c_b = c_l: Kanel's delta = 0)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "spall_records.png"), dpi=75)
    plt.close(fig)


def main():
    start = time.time()
    table, curves = [], {}
    for label, settings in CASES.items():
        runs = [run(r, **settings) for r in RATIOS]
        curves[label] = [int(r["spall"]) for r in runs]
        first = next((k for k, r in enumerate(runs) if r["spall"]), None)
        stays = first is not None and all(r["spall"] for r in runs[first:])
        share = runs[first]["share"] if first is not None else float("nan")
        table.append((label, RATIOS[first] if first is not None else None, stays, share,
                      sum(r["seconds"] for r in runs)))
    out = ["| law | spall threshold / vd, ours | Krivtsov | spall at every faster impact | "
           "spalled layer (share of the target) at the threshold | sweep wall time (s) |",
           "|---|---|---|---|---|---|"]
    for label, thr, stays, share, seconds in table:
        out.append(f"| {label} | {thr} | close to 1 | {'yes' if stays else 'no'} | {share:.2f} | "
                   f"{seconds:.1f} |")
    out += ["", f"Flyer 10 cells, target 20 cells (fcc [100], 2x2 cells, 480 clusters; 2D: 4 cells, "
            f"244 clusters), cut at 1.3 a; impact speeds {RATIOS[0]} ... {RATIOS[-1]} vd in steps "
            f"of 0.05; {len(RATIOS) * len(CASES)} runs in {time.time() - start:.0f} s."]
    thresholds = {RECORDS[0][0]: table[0][1], RECORDS[1][0]: table[3][1]}
    out += [""] + records_section(thresholds)
    open(os.path.join(HERE, "results.md"), "w").write("\n".join(out) + "\n")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 3.5))
    for k, (label, ys) in enumerate(curves.items()):
        ax.step(RATIOS, np.array(ys) + 0.03 * k, where="mid", label=label)
    ax.axvline(1.0, color="k", ls="--", lw=0.8, label="vd (Krivtsov: spall speed close to it)")
    ax.set_xlabel("impact speed / vd")
    ax.set_ylabel("spall (1) or not (0)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "spall.png"), dpi=90)
    plt.close(fig)
    print("\n".join(out))


if __name__ == "__main__":
    main()
