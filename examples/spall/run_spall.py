#!/usr/bin/python3
"""Spall thresholds against the dissociation speed vd = sqrt(2D/m) (Krivtsov & Krivtsova
2002, doc/references.rst) on in.spall, for Morse (aluminium clusters, alpha a = 3.76;
alpha a = 6) and Lennard-Jones on fcc, and the aluminium clusters on the 2D triangular lattice.

    source build/env.sh; /usr/bin/python3 examples/spall/run_spall.py

Writes results.md and spall.png next to this file.
"""
import os
import time

import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from lammps_driver import script  # noqa: E402
CASES = {  # label: in.spall settings
    "Morse, alpha a = 3.76 (aluminium clusters)": {"pot": "al-cluster-10um"},
    "Morse, alpha a = 6": {"pot": "morse-lj-match"},
    "Lennard-Jones": {"pot": "lj-reduced"},
    "aluminium clusters, 2D triangular lattice": {"pot": "al-cluster-10um", "dim": 2, "cells": 4},
}
RATIOS = [round(0.6 + 0.05 * k, 2) for k in range(21)]   # v / vd = 0.6 ... 1.6


def run(ratio, pot="al-cluster-10um", **var):
    """One impact; returns spall (bool), the spalled share of the target and the wall time."""
    start = time.time()
    with script(os.path.join(HERE, "in.spall"), {"ratio": ratio, "pot": pot, **var}) as lmp:
        large = lmp.extract_variable("large")
        parts = np.array(lmp.gather("c_parts", 1, 3)).reshape(-1, 3)
        x = np.array(lmp.gather_atoms("x", 1, 3)).reshape(-1, 3)[:, 0]
    intarget = parts[:, 1] > 0
    big = intarget & (parts[:, 2] == 0)
    ids = np.unique(parts[big, 0])
    rear_share = 0.0
    if len(ids) >= 2:  # the spalled layer: the large fragment furthest from the impact
        rear = max(ids, key=lambda i: x[parts[:, 0] == i].mean())
        rear_share = np.sum(parts[:, 0] == rear) / np.sum(intarget)
    return {"spall": large >= 2, "share": rear_share, "seconds": time.time() - start}


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
