#!/usr/bin/python3
"""The 3D dusting thresholds as the cluster-dynamics dusting paper reads them (Piskunov,
Tsaplin & Veselov 2011, section 1): thresholds by two definitions, first dust (one cluster
beyond the body) and more than one layer of the section (the paper's baseline: "значительно
превышает единичный слой кластеров"), from ensembles of in.shock3d runs.

    source build/env.sh; /usr/bin/python3 examples/shock-3d/run_thresholds.py [--jobs 2] [--report]

Phases, most needed first (each run cached in runs/, its result kept in thresholds_runs.json,
so an interrupted study continues, in another checkout too):
1. fcc [100], 2x2 cells: from rest (seed 0) and five seeds of a 1 m/s thermal start at each
   speed of the grids around both thresholds;
2. 5 um against 10 um clusters with the same periods of cross-section (2x2 cells), Rc = 1.1,
   u = 2 km/s, five seeds each (the paper's comparison);
3. the simple hexagonal sample (the paper's density at spacing a), from rest, down to 50 m/s;
4. the 4x4 section: the same seeds at the speeds of GRIDS4, Rc = 1.3 and 1.2 first.
--report writes thresholds.md and thresholds.png from the cached runs only and lists what is
not run yet.
"""
import json
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
from run_ensembles import cached, run_logged  # noqa: E402
from run_sweep import PAPER_UCR  # noqa: E402
from runner import arguments, parallel, tag  # noqa: E402

SEEDS = [1, 2, 3, 4, 5]
# speeds around both thresholds of each Rc (from ensembles.md: first dust and more than 8)
GRIDS = {1.05: [200, 300, 400], 1.1: [400, 500, 600], 1.2: [1200, 1400, 1600, 2000],
         1.3: [800, 1200, 1600, 2000, 2500]}
# the 4x4 section (four times the clusters, 70-300 s a run): the speeds at and above the 2x2
# brackets of both definitions, the contested Rc first (the whole grid is 1.5 hours on 2 cores)
GRIDS4 = {1.3: [2000, 2500], 1.2: [1400, 1600, 2000], 1.1: [400, 500], 1.05: [300, 400]}


def grid(cells, grids=GRIDS):
    out = []
    for rc, us in grids.items():
        for u in us:
            out.append(dict(rc=rc, u=u, cells=cells, seed=0))
            out += [dict(rc=rc, u=u, cells=cells, seed=s) for s in SEEDS]
    return out


def sizes():
    """5 um and 10 um clusters at the same periods of cross-section (2x2 cells)."""
    return [dict(rc=1.1, u=2000, cells=2, seed=s, **pot) for s in SEEDS
            for pot in ({}, {"pot": "al-cluster-5um"})]


# the simple hexagonal sample from rest: from far below each fcc threshold to the lowest
# grid speed of fcc
SH_SPEEDS = {1.05: [50, 100, 200], 1.1: [100, 200, 400], 1.2: [200, 600, 1200],
             1.3: [200, 400, 800]}


def simple_hexagonal():
    """The paper's density at spacing a (in.shock3d -var lattice sh), from rest: how far
    below fcc a lattice that collapses under compression (in.sh_stability) dusts."""
    return [dict(rc=rc, u=u, cells=2, seed=0, lattice="sh") for rc, us in SH_SPEEDS.items()
            for u in us]


def phases():
    yield grid(2)
    yield sizes()
    yield simple_hexagonal()
    yield grid(4, GRIDS4)


# the results of every finished run, kept in git (runs/ is not): the report needs no rerun
RECORD = os.path.join(HERE, "thresholds_runs.json")
KEPT = ("surface", "dustmass", "natoms", "seconds")


def recorded():
    return json.load(open(RECORD)) if os.path.exists(RECORD) else {}


def result(var, record=None):
    """A run's result: from runs/ or from the kept record."""
    r = cached(var)
    if r is not None:
        return r
    return (recorded() if record is None else record).get(tag(var))


def keep(runs):
    """Add the finished runs' results to the record."""
    record = recorded()
    for v in runs:
        r = cached(v)
        if r is not None:
            record[tag(v)] = {k: r[k] for k in KEPT}
    with open(RECORD, "w") as f:
        json.dump(record, f, indent=0, sort_keys=True)


def main():
    args = arguments(__doc__, report=True)
    if not args.report:
        start = time.time()
        for phase in phases():
            todo = [v for v in phase if result(v) is None]
            parallel(run_logged, todo, args.jobs)
            keep(phase)
        print(f"done in {time.time() - start:.0f} s of wall time")
    keep([v for phase in phases() for v in phase])
    from threshold_report import report
    record = recorded()
    report(phases, lambda v: result(v, record), HERE, PAPER_UCR, GRIDS)


if __name__ == "__main__":
    main()
