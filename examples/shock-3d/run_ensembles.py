#!/usr/bin/python3
"""Dust-count ensembles of in.shock3d: bonds by distance against neighbour-fixed links.

    source build/env.sh; /usr/bin/python3 examples/shock-3d/run_ensembles.py [--jobs 2] [--report]

Ensemble members differ only in the seed of a random thermal velocity (rms 1 m/s per
component).  Runs go two at a time (one per core) in the order of phases(), most needed first;
each result is cached in runs/, so an interrupted sweep continues where it stopped.
--report writes ensembles.md and the plots from the cached runs only, and lists the points not
run.
"""
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
from run_sweep import run_one  # noqa: E402
from runner import arguments, kept, parallel, tag  # noqa: E402

SEEDS = [1, 2, 3, 4, 5]
# the README's grids, extended down where a model dusts at the lowest speed of the old grid
GRIDS = {1.05: [200, 300, 400, 500, 600], 1.1: [400, 500, 600, 800, 1000, 1500, 2000, 3000, 4000],
         1.2: [400, 600, 800, 1000, 1200, 1400, 1600, 2000, 3000],
         1.3: [800, 1200, 1600, 2000, 2500, 3000, 3500]}
HARMONIC = [2000, 4000]
MODELS = {"distance": {}, "link 1.05": {"link": 1.05}}


def scene(model, seed, **var):
    return dict(var, **MODELS[model], seed=seed)


def curve(model, seed):
    """Every grid point of one model with one seed."""
    out = [scene(model, seed, rc=rc, u=u) for rc, us in GRIDS.items() for u in us]
    return out + [scene(model, seed, rc=1.2, u=u, law="harmonic") for u in HARMONIC]


def brackets(model):
    """Per Rc, the grid speeds around the first dusting of the seed-1 curve: the last speed
    without dust below the first with dust (None where seed 1 is not run yet)."""
    out = {}
    for rc, us in GRIDS.items():
        counts = [cached(scene(model, 1, rc=rc, u=u)) for u in us]
        if any(c is None for c in counts):
            return None
        first = next((k for k, c in enumerate(counts) if c["surface"] > 0), None)
        if first is None:
            out[rc] = [us[-1]]
        else:
            out[rc] = us[max(first - 1, 0):first + 1]
    return out


def phases():
    """The runs in the order they are run: the seed-1 curves of both models, then seeds 2-5
    at the speeds that bracket each threshold and at the harmonic points, then the check of
    the thermal velocity, 5 um against 10 um clusters and the 4x4 section.  (The full grid for
    five seeds, the 4x4 section and the 5 um / 10 um comparison on equal areas do not fit the
    session's two cores: README.)"""
    yield curve("distance", 1) + curve("link 1.05", 1)
    later = []
    for seed in SEEDS[1:]:
        for model in MODELS:
            for rc, us in (brackets(model) or {}).items():
                later += [scene(model, seed, rc=rc, u=u) for u in us]
            later += [scene(model, seed, rc=1.2, u=u, law="harmonic") for u in HARMONIC]
    yield later
    # does the thermal velocity move the mean?  The same points without it (seed 0: the
    # symmetric perfect crystal) and with a ten times smaller one (0.1 m/s)
    check = []
    for rc, u in THERMAL_CHECK:
        check += [scene(model, 0, rc=rc, u=u) for model in MODELS]
        check += [scene("distance", seed, rc=rc, u=u, vtherm=0.1) for seed in SEEDS]
    yield check
    # 5 um against 10 um clusters on equal areas: 2x2 cells of 5 um = 1x1 cell of 10 um
    yield [scene(model, seed, rc=1.1, u=2000, **var) for seed in SEEDS for model in MODELS
           for var in ({"cells": 1}, {"pot": "al-cluster-5um"})]
    # the 4x4 section (22,656 clusters) at the Rc = 1.2 brackets of each model
    section = []
    for model in MODELS:
        for u in (brackets(model) or {}).get(1.2, []):
            section += [scene(model, seed, rc=1.2, u=u, cells=4) for seed in SEEDS]
    yield section


THERMAL_CHECK = [(1.05, 300), (1.1, 500), (1.2, 1400)]


def scenes():
    return [v for phase in phases() for v in phase]


def cached(var):
    """The kept result of run_sweep.run_one(var), or None if it has not run."""
    return kept(os.path.join(HERE, "runs", tag(var)))


def run_logged(var):
    start = time.time()
    result = run_one(var)
    print(f"{time.time() - start:7.1f} s  {var}: {result['surface']:.0f} dust", flush=True)
    return var


def main():
    args = arguments(__doc__, report=True)
    if not args.report:
        start, count = time.time(), 0
        for phase in phases():
            todo = [v for v in phase if cached(v) is None]
            count += len(parallel(run_logged, todo, args.jobs))
        print(f"{count} runs in {time.time() - start:.0f} s of wall time")
    from ensemble_report import report
    report(scenes(), cached, HERE)


if __name__ == "__main__":
    main()
