#!/usr/bin/python3
"""The time step at equal accuracy: the aluminium plates of bench/bench_shock_cost.sh (in.plate
with 10 um elements and the spall kinetics; in.tlsph, LAMMPS's smd/tlsph, with its pairwise
failure, one body) at 400 and 1000 m/s, each at four steps halving from the example's (theta
0.1 d / c_L for the elements, cfl 0.1 h / c_L / 1.3 for smd/tlsph) to 1/8 of it, read as
converge.py reads them (the precursor, Kanel's pull-back, the peak) against each method's own
finest run.  For a bound b on every reading (1, 2 and 3 %), each method's largest step within
it at both speeds, its steps and the loop times of those runs (LAMMPS's own: the runs go two
at a time, so a loop time is read to about 10 %): the cost of a plate run at equal accuracy.
Writes time_step_peers.md; runs in runs/time_step_peers (a finished run is read again).

    source ../../build/env.sh; /usr/bin/python3 time_step_peers.py [--jobs 2]
"""
import argparse
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
from converge import readings  # noqa: E402
from runner import keep, lmp_command, loops, parallel, table  # noqa: E402

SHARES = [0.0125, 0.025, 0.05, 0.1]    # theta (mca) or cfl (smd/tlsph), finest first
SPEEDS = [400, 1000]
BOUNDS = [0.01, 0.02, 0.03]
RUNS = os.path.join(HERE, "runs", "time_step_peers")
READINGS = [("precursor", "precursor (m/s)", ".1f"), ("kanel", "Kanel (GPa)", ".3f"),
            ("peak", "peak (m/s)", ".1f")]
METHODS = {
    "mca": ("in.plate", "theta", {"metal": "al", "here": HERE + "/", "d": 1.0e-5,
                                  "records": 800}),
    "tlsph": ("in.tlsph", "cfl", {"metal": "al", "failure": "pairwise", "bodies": 1,
                                  "records": 200}),
}


def run(item):
    """One plate of method at v with the step's share (kept in its folder): its readings,
    steps and loop time."""
    method, v, share = item
    script, name, var = METHODS[method]
    var = dict(var, v=v, out="run", **{name: share})

    def make(workdir):
        try:
            out = lmp_command(os.path.join(HERE, script), var, workdir,
                              args=["-log", "log.lammps"])
        except subprocess.CalledProcessError as failed:
            stop = [x for x in failed.stdout.splitlines() if x.startswith("ERROR")]
            sys.exit(f"time_step_peers.py: {method} at {v} m/s, {name} {share:g} stopped: "
                     f"{stop[0] if stop else 'no message'} (folder {workdir})")
        loop, _, steps, atoms = loops(out)[-1]
        return dict(loop=loop, steps=steps, atoms=atoms)
    workdir = os.path.join(RUNS, f"{method}-v{v}-{name}{share:g}")
    result = keep(workdir, make)
    record = np.loadtxt(os.path.join(workdir, "run.visar"))
    return dict(result, **readings(record[:, 1], record[:, 2], v))


def deviation(x, x0):
    """|x / x0 - 1|; a reading one run has and the other lacks (no spall, an overdriven
    shock: None) is off without bound."""
    if x is None or x0 is None:
        return 0.0 if x is None and x0 is None else float("inf")
    return abs(x / x0 - 1.0)


def worst(results, method, share):
    """The largest deviation of any reading at either speed from the finest run's."""
    return max(deviation(results[(method, v, share)][k], results[(method, v, SHARES[0])][k])
               for v in SPEEDS for k, _, _ in READINGS)


def fmt(x, spec):
    return "-" if x is None else format(x, spec)


def main():
    ap = argparse.ArgumentParser(description=__doc__.strip().split("\n")[0])
    ap.add_argument("--jobs", type=int, default=2)
    opts = ap.parse_args()
    items = [(m, v, s) for m in METHODS for v in SPEEDS for s in SHARES]
    results = dict(zip(items, parallel(run, items, opts.jobs) if opts.jobs > 1
                       else map(run, items)))
    rows = []
    for m, v, s in items:
        r, ref = results[(m, v, s)], results[(m, v, SHARES[0])]
        cells = []
        for key, _, spec in READINGS:
            cells += [fmt(r[key], spec), f"{100 * deviation(r[key], ref[key]):.2f}"]
        rows.append([m, METHODS[m][1], s, v] + cells + [r["steps"], f"{r['loop']:.1f}"])
    header = ["method", "step", "theta or cfl", "V (m/s)"]
    for _, label, _ in READINGS:
        header += [label, "off the finest (%)"]
    header += ["steps", "loop (s)"]
    equal = []
    for bound in BOUNDS:
        pick = {}
        for m in METHODS:
            # the largest step within the bound whose finer steps are all within it too (the
            # finest, the reference, always is)
            good = [s for s in SHARES if worst(results, m, s) <= bound]
            pick[m] = max(s for s in good if all(u in good for u in SHARES if u <= s))
        # where only the finest run is within the bound, a method needs that step or a finer
        # one: its cost is a lower bound
        finest = {m: pick[m] == SHARES[0] for m in METHODS}
        cost = {m: sum(results[(m, v, pick[m])]["loop"] for v in SPEEDS) for m in METHODS}
        steps = {m: results[(m, SPEEDS[0], pick[m])]["steps"] for m in METHODS}
        label = {m: f"{pick[m]:g}" + (" or finer" if finest[m] else "") for m in METHODS}
        more = {m: " or more" if finest[m] else "" for m in METHODS}
        ratio = cost["mca"] / cost["tlsph"]
        ratio = ("unknown" if finest["mca"] and finest["tlsph"] else
                 f"at most {ratio:.2f}" if finest["tlsph"] else
                 f"at least {ratio:.2f}" if finest["mca"] else f"{ratio:.2f}")
        equal.append([f"{100 * bound:g}", label["mca"], label["tlsph"],
                      f"{steps['mca']}{more['mca']} / {steps['tlsph']}{more['tlsph']}",
                      f"{cost['mca']:.1f}{more['mca']} / {cost['tlsph']:.1f}{more['tlsph']}",
                      ratio])
    lines = ["# The time step at equal accuracy (time_step_peers.py)", "",
             "Aluminium plates of bench/bench_shock_cost.sh: in.plate (10 um elements, the spall "
             "kinetics) and in.tlsph (smd/tlsph, pairwise failure, one body); each reading "
             f"against the method's own finest run (share {SHARES[0]:g}).", "",
             *table(header, rows), "",
             "Each method's largest step with every reading within the bound of its own finest "
             "run at both speeds, and every finer step too ('or finer': only the finest run, "
             "the reference, is; its steps and time are then lower bounds); the steps of one "
             "run and the loop times of the two speeds' runs added:", "",
             *table(["bound (%)", "mca theta", "smd/tlsph cfl", "steps of a run (mca / tlsph)",
                     "loop s, both speeds (mca / tlsph)", "mca / tlsph per run"], equal)]
    with open(os.path.join(HERE, "time_step_peers.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
