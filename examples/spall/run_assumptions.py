#!/usr/bin/python3
"""Which of the spall scene's assumptions moves the threshold away from vd (Krivtsov &
Krivtsova 2002: the spall speed of a monocrystalline packing is close to vd; doc/references.rst).
From the baseline of in.spall (aluminium clusters, fcc [100], flyer 10 cells = 14 a, target
20 cells = 28 a, 2x2 cells across, cut at 1.3 a) one assumption is changed at a time: the
lattice's orientation, the impactor's thickness, the plates' size, and the 2D triangular lattice
(with its rows along or across the impact, and a thick impactor).  Each threshold is an
ensemble: 3 seeds (1 m/s thermal start), each swept upwards in steps of 0.05 vd from 0.6 vd to
its first spall (confirmed by the next two speeds).

    source build/env.sh; /usr/bin/python3 examples/spall/run_assumptions.py     # about 2 min

Writes assumptions.md next to this file.
"""
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import run_spall  # noqa: E402

BASE = {"pot": "al-cluster-10um", "vtherm": 1.0}
VARIANTS = [  # label, what it changes, in.spall settings
    ("fcc [100], flyer 14 a, target 28 a, 2x2 cells", "baseline", {}),
    ("fcc [111], flyer 15 a, target 29 a (close-packed planes face the impact)", "lattice orientation",
     {"orient": 111, "flyer": 6, "target": 12}),
    ("fcc [100], flyer 28 a = target", "impactor thickness", {"flyer": 20}),
    ("fcc [100], flyer 7 a", "impactor thickness", {"flyer": 5}),
    ("fcc [100], 4x4 cells across", "plate size", {"cells": 4}),
    ("fcc [100], flyer 28 a, target 57 a", "plate size", {"flyer": 20, "target": 40}),
    ("2D triangular, rows along the impact, flyer 10 a, target 20 a, 4 cells", "2D",
     {"dim": 2, "cells": 4}),
    ("2D triangular, rows across the impact, flyer 10 a, target 21 a", "2D, lattice orientation",
     {"dim": 2, "orient": 110, "flyer": 6, "target": 12, "cells": 4}),
    ("2D triangular, rows along, flyer 20 a = target", "2D, impactor thickness",
     {"dim": 2, "cells": 4, "flyer": 20}),
]
SEEDS = [1, 2, 3]
RATIOS = [round(0.6 + 0.05 * k, 2) for k in range(25)]   # 0.6 ... 1.8 vd


def threshold(seed, confirm=2, **settings):
    """The first impact speed / vd that spalls, confirmed by the next `confirm` speeds (None if
    none in RATIOS); the number of runs."""
    runs, streak, first = 0, 0, None
    for ratio in RATIOS:
        runs += 1
        if run_spall.run(ratio, seed=seed, **{**BASE, **settings})["spall"]:
            first = ratio if streak == 0 else first
            streak += 1
            if streak > confirm:
                return first, runs
        else:
            streak, first = 0, None
    return first, runs


def main():
    start = time.time()
    lines = ["| assumption changed | scene | thresholds / vd (seeds 1, 2, 3) | mean ± sd | runs |",
             "|---|---|---|---|---|"]
    for label, what, settings in VARIANTS:
        found = [threshold(seed, **settings) for seed in SEEDS]
        values = [t for t, _ in found]
        shown = ", ".join("none" if t is None else f"{t:.2f}" for t in values)
        known = np.array([t for t in values if t is not None])
        stat = f"{known.mean():.2f} ± {known.std(ddof=1):.2f}" if len(known) > 1 else "-"
        lines.append(f"| {what} | {label} | {shown} | {stat} | {sum(n for _, n in found)} |")
        print(lines[-1], flush=True)
    lines += ["", f"Aluminium clusters (Morse, alpha a = 3.76), cut at 1.3 a; {time.time() - start:.0f} s."]
    open(os.path.join(HERE, "assumptions.md"), "w").write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
