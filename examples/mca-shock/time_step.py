#!/usr/bin/python3
"""The time step of the shock law's elements: aluminium plates of in.plate (5 um elements, the
spall kinetics, the example's defaults) at 400 and 1000 m/s with the step theta d / c_L for
theta from 0.0125 to 0.6, each read as converge.py reads them: the shock speed in the target (the
x-t records, run_shock.front_speed), the precursor (the HEL's particle velocity), Kanel's
pull-back and the spall depth, against the finest run (theta 0.0125, the converged run); whether
the run finished (a larger step stops with links beyond the list, or runs away: a reading off by
more than half); its steps and loop time.  The largest theta that keeps every reading within
1 % of the finest run at both speeds is the recommendation.  Writes time_step.md; runs in
runs/time_step (a finished run is read again).

    source ../../build/env.sh; /usr/bin/python3 time_step.py [--jobs 2]
"""
import argparse
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
from converge import FLYER_UM, TARGET_UM, readings, spall_depth  # noqa: E402
from run_shock import METALS, front_speed, time_step  # noqa: E402
from runner import keep, lmp_command, loops, parallel, table  # noqa: E402
from shock_records import XT  # noqa: E402

THETAS = [0.0125, 0.025, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.6]
SPEEDS = [400, 1000]
D_UM = 5.0
RUNS = os.path.join(HERE, "runs", "time_step")
AL = METALS["al"]
READINGS = [("us", "shock speed (m/s)", ".0f"), ("precursor", "precursor (m/s)", ".1f"),
            ("kanel", "Kanel (GPa)", ".3f"), ("depth", "spall depth (um)", ".1f")]


def run(item):
    """One plate at v with the step theta d / c_L (kept in its folder): its readings, or why
    it stopped."""
    v, theta = item
    cells = int(round(10 * 10.0 / D_UM))
    var = {"metal": "al", "v": v, "here": HERE + "/", "out": "run", "d": D_UM * 1e-6,
           "flyer": cells, "target": 2 * cells, "records": 800, "theta": theta}

    def make(workdir):
        try:
            out = lmp_command(os.path.join(HERE, "in.plate"), var, workdir,
                              args=["-log", "log.lammps"])
        except subprocess.CalledProcessError as failed:
            stop = [x for x in failed.stdout.splitlines() if x.startswith("ERROR")]
            return dict(stopped=stop[0][:120] if stop else "no message")
        loop, _, steps, atoms = loops(out)[-1]
        return dict(loop=loop, steps=steps, atoms=atoms)
    workdir = os.path.join(RUNS, f"v{v}-theta{theta:g}")
    result = keep(workdir, make)
    if "stopped" in result:
        return result
    dt = time_step(open(os.path.join(workdir, "log.lammps")).read())
    record = np.loadtxt(os.path.join(workdir, "run.visar"))
    xt = XT(os.path.join(workdir, "run.xt"), dt)
    flyer, target = FLYER_UM * 1e-6, TARGET_UM * 1e-6
    us = front_speed(xt, v / 4, flyer + 0.15 * target, flyer + 0.8 * target)
    got = readings(record[:, 1], record[:, 2], v)
    if not np.all(np.isfinite(record[:, 2])) or got["peak"] > 1.5 * v:
        return dict(result, stopped="the free surface ran away")
    return dict(result, **got, us=us, depth=spall_depth(xt, D_UM * 1e-6))


def main():
    ap = argparse.ArgumentParser(description=__doc__.strip().split("\n")[0])
    ap.add_argument("--jobs", type=int, default=2)
    opts = ap.parse_args()
    items = [(v, theta) for v in SPEEDS for theta in THETAS]
    results = dict(zip(items, parallel(run, items, opts.jobs) if opts.jobs > 1
                       else map(run, items)))
    rows, within = [], {}
    for v, theta in items:
        r, ref = results[(v, theta)], results[(v, THETAS[0])]
        if "stopped" in r:
            rows.append([v, theta, "no: " + r["stopped"]] + ["-"] * (2 * len(READINGS) + 2))
            within[(v, theta)] = False
            continue
        cells, worst = [], 0.0
        for key, _, spec in READINGS:
            x, x0 = r.get(key), ref.get(key)
            if x is None or x0 is None:
                cells += ["-", "-"]
                worst = float("inf") if (x is None) != (x0 is None) else worst
                continue
            dev = abs(x / x0 - 1.0)
            worst = max(worst, dev)
            cells += [format(x, spec), f"{100 * dev:.2f}"]
        within[(v, theta)] = worst <= 0.01
        finished = "yes" if worst < 0.5 else "ran away (a reading off by more than half)"
        rows.append([v, theta, finished] + cells + [r["steps"], f"{r['loop']:.1f}"])
    header = ["V (m/s)", "theta", "finished"]
    for _, label, _ in READINGS:
        header += [label, f"off theta {THETAS[0]:g} (%)"]
    header += ["steps", "loop (s)"]
    good = [t for t in THETAS if all(within[(v, t)] for v in SPEEDS)]
    best = max((t for t in good if all(u in good for u in THETAS if u <= t)), default=None)
    lines = ["# The shock law's time step (time_step.py)", "",
             f"Aluminium plates of in.plate, {D_UM:g} um elements, the spall kinetics; the step "
             f"theta d / c_L; every reading against the finest run, theta {THETAS[0]:g}.", "",
             *table(header, rows), "",
             f"The largest theta with every reading within 1 % of theta {THETAS[0]:g} at both "
             f"speeds (and every smaller theta too): {best}."]
    with open(os.path.join(HERE, "time_step.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
