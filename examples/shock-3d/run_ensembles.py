#!/usr/bin/python3
"""Dust-count ensembles of in.shock3d: bonds by distance against neighbour-fixed links.

    source build/env.sh; /usr/bin/python3 examples/shock-3d/run_ensembles.py [--jobs 2] [--report]

Every point is SEEDS runs that differ only in the seed of a random thermal velocity (rms 1 m/s
per component).  Runs go two at a time (one per core) in the order of SCENES, most needed
first; each result is cached in runs/, so an interrupted sweep continues where it stopped.
--report writes ensembles.md and the plots from the cached runs only, and lists the points not
run.
"""
import argparse
import json
import multiprocessing
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from run_sweep import PAPER_UCR, run_one  # noqa: E402

SEEDS = [1, 2, 3, 4, 5]
GRIDS = {1.05: [200, 300, 400, 500, 600], 1.1: [400, 500, 600, 800, 1000, 1500, 2000, 3000, 4000],
         1.2: [800, 1000, 1200, 1400, 1600, 2000, 3000], 1.3: [1600, 2000, 2500, 3000, 3500]}
HARMONIC = [2000, 4000]
MODELS = {"distance": {}, "link 1.05": {"link": 1.05}}
# the distance model's brackets (its single-run thresholds, README): ensembles there first
DISTANCE_BRACKETS = {1.05: [300, 400], 1.1: [500, 600], 1.2: [1400, 1600], 1.3: [1600, 2000]}
SECTION4 = {1.2: [1400, 1600]}    # 4x4 section (22,656 clusters): where it fits
TEMPERATURE = dict(rc=1.1, u=600)    # the thermal speed checked at 0.1 and 1 m/s


def scene(model, seed, **var):
    return dict(var, **MODELS[model], seed=seed)


def scenes():
    """Every run, in the order they are run (most needed first)."""
    out = []
    for seed in SEEDS:    # one seed of every point first: the curves, then the spreads
        for model in MODELS:
            for rc, us in GRIDS.items():
                for u in us:
                    if model == "distance" and u not in DISTANCE_BRACKETS[rc] and seed > 1:
                        continue
                    out.append(scene(model, seed, rc=rc, u=u))
            for u in HARMONIC:
                out.append(scene(model, seed, rc=1.2, u=u, law="harmonic"))
    for model in MODELS:    # 5 um against 10 um clusters on equal areas (2x2 cells of 5 um)
        for seed in SEEDS:
            out.append(scene(model, seed, rc=1.1, u=2000, cells=1))
            out.append(scene(model, seed, rc=1.1, u=2000, pot="al-cluster-5um"))
    for seed in SEEDS:
        out.append(scene("distance", seed, vtherm=0.1, **TEMPERATURE))
    for model in MODELS:
        for rc, us in SECTION4.items():
            for u in us:
                for seed in SEEDS:
                    out.append(scene(model, seed, rc=rc, u=u, cells=4))
    return out


def cached(var):
    tag = "-".join(f"{k}{v}" for k, v in sorted(var.items()))
    path = os.path.join(HERE, "runs", tag, "result.json")
    return json.load(open(path)) if os.path.exists(path) else None


def run_logged(var):
    start = time.time()
    result = run_one(var)
    print(f"{time.time() - start:7.1f} s  {var}: {result['surface']:.0f} dust", flush=True)
    return var


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--report", action="store_true")
    args = ap.parse_args()
    if not args.report:
        todo = [v for v in scenes() if cached(v) is None]
        start = time.time()
        with multiprocessing.Pool(args.jobs) as pool:
            for _ in pool.imap(run_logged, todo, chunksize=1):
                pass
        print(f"{len(todo)} runs in {time.time() - start:.0f} s of wall time")
    from ensemble_report import report
    report(scenes(), cached, HERE)


if __name__ == "__main__":
    main()
