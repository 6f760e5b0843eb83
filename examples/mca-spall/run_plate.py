#!/usr/bin/python3
"""The aluminium plate impact of in.plate with three mesoscale methods side by side: movable
cellular automata (pair_style mca), peridynamics (pair_style peri/lps) and cluster dynamics
(examples/spall/in.spall with the aluminium clusters of the dusting paper, on the same plates:
5 x 5 cells across).  For each method: the spall threshold (ensembles of 3 seeds, 1 m/s thermal
start), the free-surface velocity history with its pull-back and the spall strength read from
it (tools/pull_back.py: sigma_sp = 1/2 rho0 c_b (dU + delta), Kanel's correction delta for the
elastic-plastic release of the yielding elements, one speed c_b = c_l and delta = 0 for the
elastic elements, peridynamics and the clusters), the target's fragments and the run time
per microsecond of physical time.  Writes comparison.md and plate.png; runs in runs/ (a
finished run is read again; delete its folder to run it again).  About 25 minutes on one core.

    source ../../build/env.sh; /usr/bin/python3 run_plate.py
"""
import math
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import keep, loops, mean_sd, script  # noqa: E402
from shock_records import XT, spall_strength  # noqa: E402

RHO, K, G, SIGMA = 2700.0, 75.5e9, 26.1e9, 1.2e9      # aluminium, in.plate's defaults
YIELD = 0.3e9         # the elements' yield stress of the elastic-plastic variant (mca-yield)
C_L = math.sqrt((K + 4.0 * G / 3.0) / RHO)             # longitudinal (uniaxial strain) speed
C_B = math.sqrt(K / RHO)                                # bulk speed (the yielding elements)
VD = 1451.0                                            # al-cluster-10um: sqrt(2D/m)
FLYER = 10 * math.sqrt(2.0) * 1e-5                     # 10 cells of sqrt(2) a, a = 10 um
SEEDS = [1, 2, 3]
METHODS = {  # label, speeds of the sweep (m/s)
    "mca": ("movable cellular automata (pair mca)", list(range(80, 210, 10)) + [300, 400]),
    "mca-yield": ("movable cellular automata, yield 0.3 GPa",
                  list(range(80, 300, 10)) + [300, 400, 600]),
    "peri": ("peridynamics (pair peri/lps)", list(range(80, 210, 10)) + [300, 400]),
    "cd": ("cluster dynamics (morse/spline, aluminium clusters)",
           [400] + list(range(1200, 2300, 100))),
}
# the equivalent stress of mca's pairs at 45 degrees to the impact, per unit sigma_xx, in
# uniaxial strain (sigma_yy = sigma_zz = lambda / (lambda + 2G) sigma_xx): the pairs that break
LAMBDA = K - 2.0 * G / 3.0
LATERAL = LAMBDA / (LAMBDA + 2.0 * G)
PAIR45 = math.sqrt(((1 + LATERAL) / 2) ** 2 + 3 * ((1 - LATERAL) / 2) ** 2)


def inputs(method, v, **var):
    """The input script and its -var settings for an impact at v: in.plate, or for cluster
    dynamics examples/spall/in.spall on the same plates (5 x 5 cells, v = ratio vd)."""
    if method == "cd":
        return (os.path.join(HERE, "..", "spall", "in.spall"),
                {"pot": "al-cluster-10um", "cells": 5, "ratio": v / VD, **var})
    if method == "mca-yield":
        return os.path.join(HERE, "in.plate"), {"method": "mca", "yield": YIELD, "v": v, **var}
    return os.path.join(HERE, "in.plate"), {"method": method, "v": v, **var}


def loop_time(workdir):
    """LAMMPS's loop time of the last run in workdir/log.lammps (s)."""
    return loops(open(os.path.join(workdir, "log.lammps")).read())[-1][0]


def folder(method, v, seed):
    return os.path.join(HERE, "runs", f"{method}-v{v}-seed{seed}")


def run(method, v, seed):
    """One impact in runs/<method>-v<v>-seed<seed>; a summary dict (kept as result.json)."""
    return keep(folder(method, v, seed), lambda workdir: impact(method, v, seed, workdir))


def impact(method, v, seed, workdir):
    """One impact run in workdir: its summary dict."""
    start = time.time()
    with script(*inputs(method, v, seed=seed, out="plate"), workdir, "log.lammps") as lmp:
        r = {"spall": bool(lmp.extract_variable("spalled")),
             "large": lmp.extract_variable("large"), "v": lmp.extract_variable("v"),
             "c0": lmp.extract_variable("c0"), "dt": lmp.extract_global("dt"),
             "steps": lmp.extract_variable("steps"), "natoms": lmp.get_natoms()}
        parts = np.array(lmp.gather("c_parts", 1, 3)).reshape(-1, 3)
        x = np.array(lmp.gather_atoms("x", 1, 3)).reshape(-1, 3)[:, 0]
        if method == "peri":
            damage = np.array(lmp.gather("c_damage", 1, 1))
            x0 = np.array(lmp.gather("f_x0", 1, 1))
    r["wall"] = time.time() - start
    r["loop"] = loop_time(workdir)
    target = parts[:, 1] > 0
    big = target & (parts[:, 2] == 0)
    ids, sizes = np.unique(parts[big, 0], return_counts=True)
    r["fragments"] = sorted((sizes / target.sum()).tolist(), reverse=True)
    r["dust"] = float(np.sum(target & (parts[:, 2] > 0)) / target.sum())
    r["rear"] = 0.0
    if method == "peri" and r["spall"]:    # the spalled layer: beyond the cut (in.plate)
        planes = np.round((x0[target] - x0[target].min()) / 1e-5).astype(int)
        mean = np.bincount(planes, damage[target]) / np.maximum(np.bincount(planes), 1)
        mean[:4], mean[-4:] = 0.0, 0.0                 # a horizon inside the faces
        r["rear"] = float(np.mean(planes > np.argmax(mean)))
    elif len(ids) >= 2:        # the spalled layer: the large fragment furthest from the impact
        rear = max(ids, key=lambda i: x[parts[:, 0] == i].mean())
        r["rear"] = float(np.sum(parts[:, 0] == rear) / target.sum())
    t, u = np.loadtxt(os.path.join(workdir, "plate.visar"), usecols=(1, 2), unpack=True)
    r.update(t=t.tolist(), u=u.tolist(), **reading(method, r, t, u))
    return r


def speeds(method, r):
    """(c_l, c_b) of a method's target: the elements' and peridynamics' c_L, the clusters' own
    c0 along the impact; the bulk speed below c_l only for the yielding elements (their release
    is elastic-plastic)."""
    c_long = C_L if method != "cd" else r["c0"]
    return c_long, (C_B if method == "mca-yield" else c_long)


def reading(method, r, t, u):
    """The spall strength of a run's free-surface record (tools/pull_back.py): the peak, the
    minimum, sigma_sp = 1/2 rho0 c_b (dU + delta) and delta; h = the flyer's thickness (the
    target is twice as thick)."""
    c_long, c_bulk = speeds(method, r)
    try:
        got = spall_strength(t, u, 2 * FLYER / c_bulk, rho0(method, r), c_long, c_bulk, FLYER)
    except ValueError as err:          # no pull-back in the record: the peak, nothing read
        return dict(peak=[float(t[np.argmax(u)]), float(np.max(u))], low=None, c0l=c_long,
                    c_bulk=c_bulk, sigma=None, delta=None, refused=str(err))
    return dict(peak=[got.t_peak, got.v_peak], low=[got.t_min, got.v_min], c0l=c_long,
                c_bulk=c_bulk, sigma=got.sigma, delta=got.delta)


def read_mean(runs, value, digits):
    """mean ± sd of value(r) over the runs whose record tools/pull_back.py read, with how many
    of them where not all; - where none."""
    read = [value(r) for r in runs if r["sigma"] is not None]
    if not read:
        return "-"
    text = mean_sd(read, digits) if len(read) > 1 else f"{read[0]:.{digits}f}"
    return text + ("" if len(read) == len(runs) else f" ({len(read)} of {len(runs)} read)")


TIMED = 400


def timing(method):
    """The best of 3 loop times of one impact at TIMED m/s without records (runs/timing-*)."""
    best = None
    for k in range(3):
        r = keep(os.path.join(HERE, "runs", f"timing-{method}-{k}"),
                 lambda workdir: timed(method, workdir))
        best = r if best is None or r["loop"] < best["loop"] else best
    return best


def timed(method, workdir):
    """One impact at TIMED m/s without records in workdir: steps, time step, particles and
    LAMMPS's loop time."""
    with script(*inputs(method, TIMED, records=0), workdir, "log.lammps") as lmp:
        r = {"dt": lmp.extract_global("dt"), "steps": lmp.extract_variable("steps"),
             "natoms": lmp.get_natoms()}
    r["loop"] = loop_time(workdir)
    return r


def xt(method, v, seed, r):
    """The run's x-t records (the densities of peri/lps, whose per-particle mass is its
    density, scaled to kg/m^3)."""
    records = XT(os.path.join(folder(method, v, seed), "plate.xt"), r["dt"])
    if method == "peri":
        records.density *= 1e-5 ** 3
    return records


def rho0(method, r):
    """The density of the plates: the material's (mca, peri); the clusters' (cd: fcc of a)."""
    return RHO if method != "cd" else 2.338e-12 / (1e-5 ** 3 / math.sqrt(2.0))


def acoustic_threshold(method):
    """The impact speed at which the elastic tension 1/2 rho c v where the release waves meet
    reaches the break criterion: mca, the 45-degree pairs' equivalent stress reaches sigma_c;
    peri, the bonds along the impact stretch to s00 = sigma_sp / (K + 4G/3)."""
    if method in ("mca", "mca-yield"):
        return 2 * SIGMA / PAIR45 / (RHO * C_L)
    if method == "peri":
        return 2 * SIGMA / (RHO * C_L)
    return None


def main():
    results = {m: {v: [run(m, v, s) for s in SEEDS] for v in speeds}
               for m, (_, speeds) in METHODS.items()}
    out = ["# Aluminium plate impact: three mesoscale methods on one scene", "",
           "Flyer 141 um, target 283 um, 71 um x 71 um periodic, particles of 10 um; "
           f"ensembles of {len(SEEDS)} seeds (1 m/s thermal start), mean ± sd.", "",
           "## Spall threshold", "",
           "| method | particles | spall (runs of 3) at each impact speed (m/s) | threshold (m/s) | "
           "expected (m/s) |", "|---|---|---|---|---|"]
    thresholds = {}
    for m, (label, speeds) in METHODS.items():
        counts = [sum(r["spall"] for r in results[m][v]) for v in speeds]
        # the lowest speed from which every run spalls
        first = next(k for k in range(len(speeds)) if all(c == len(SEEDS) for c in counts[k:]))
        below = speeds[first - 1] if first > 0 else None
        thresholds[m] = (below, speeds[first])
        acoustic = acoustic_threshold(m)
        out.append(f"| {label} | {results[m][speeds[0]][0]['natoms']} | "
                   + ", ".join(f"{v}: {c}" for v, c in zip(speeds, counts))
                   + f" | {below}-{speeds[first]} | "
                   + (f"{acoustic:.0f} (acoustic)" if acoustic else
                      "1.2-1.25 vd = 1741-1814 (examples/spall, 2 x 2 cells)") + " |")
    out += ["", "## Free-surface velocity, pull-back and spall strength", "",
            "| method | impact (m/s) | peak U_fs (m/s) | pull-back dU (m/s) | "
            "sigma_sp = 1/2 rho0 c_b (dU + delta) (GPa) | "
            "largest tension of the layers, virial (GPa) | "
            "spalled layer (share of the target) | large fragments (mca, cd) | dust (share) |",
            "|---|---|---|---|---|---|---|---|---|"]
    shown = {}
    for m, (label, speeds) in METHODS.items():
        top = thresholds[m][1]
        for v in [s for s in speeds if s >= top][:1] + [s for s in speeds if s >= 2 * top][:1] \
                + ([400] if m == "cd" else []):
            runs = results[m][v]
            du = read_mean(runs, lambda r: r["peak"][1] - r["low"][1], 0)
            sigma = read_mean(runs, lambda r: r["sigma"] / 1e9, 2)
            records = [xt(m, v, s, r) for s, r in zip(SEEDS, runs)]
            tension = (mean_sd([-np.nanmin(x.pressure) / 1e9 for x in records], 2)
                       if records[0].pressure is not None else "-")
            spalled = all(r["spall"] for r in runs)    # no pull-back without a spall
            out.append(f"| {m} | {v} | {mean_sd([r['peak'][1] for r in runs], 0)} | "
                       f"{du if spalled else '-'} | {sigma if spalled else '-'} | "
                       f"{tension} | {mean_sd([r['rear'] for r in runs], 2)} | "
                       f"{mean_sd([sum(f > 0.1 for f in r['fragments']) for r in runs], 1) if m != 'peri' else '-'} | "
                       f"{mean_sd([r['dust'] for r in runs], 3)} |")
            shown.setdefault(m, []).append((v, runs[0], records[0]))
    out += ["", "sigma_sp by tools/pull_back.py (G. I. Kanel 1996, 2010): 1/2 rho0 c_b (dU + "
            f"delta); mca-yield: c_b = sqrt(K/rho0) = {C_B:.0f} m/s, c_l = {C_L:.0f} m/s, h = "
            "the flyer's 141 um, delta from the release's and the spall front's slopes; mca, peri "
            f"(elastic) and cd (clusters): one speed, c_b = c_l ({C_L:.0f} m/s; cd its own c0), "
            "delta = 0, 1/2 rho0 c_l dU.  The records smoothed over a tenth of the pulse "
            "2 H / c_b."]
    out += ["", "## Run time", "",
            f"One impact at {TIMED} m/s without records, alone on one core, best of 3; the "
            "simulated time is the gap's closing and 4 target transit times.", "",
            "| method | particles | time step (ns) | steps | loop time (s) | physical time (ns) | "
            "loop time per us of physical time (s) | us per particle-step |",
            "|---|---|---|---|---|---|---|---|"]
    for m, (label, _) in METHODS.items():
        r = timing(m)
        out.append(f"| {label} | {r['natoms']} | {r['dt'] * 1e9:.3f} | {r['steps']:.0f} | "
                   f"{r['loop']:.2f} | {r['steps'] * r['dt'] * 1e9:.0f} | "
                   f"{r['loop'] / (r['steps'] * r['dt'] * 1e6):.1f} | "
                   f"{r['loop'] / (r['steps'] * r['natoms']) * 1e6:.2f} |")
    out += ["", f"{sum(len(s) for _, s in METHODS.values()) * len(SEEDS)} runs; their wall "
            f"time {sum(r['wall'] for m in results for v in results[m] for r in results[m][v]) / 60:.0f} min."]
    open(os.path.join(HERE, "comparison.md"), "w").write("\n".join(out) + "\n")
    plot(results, shown, thresholds)
    print("\n".join(out))


def plot(results, shown, thresholds):
    """Top: the free-surface velocity histories of each method (dots: the peak and the
    pull-back minimum) and spall against impact speed; bottom: x-t diagrams of the velocity
    at each method's first record speed."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 5, figsize=(22, 8))
    for k, (m, (label, speeds)) in enumerate(METHODS.items()):
        ax = axes[0, k]
        for v, r, _ in shown[m]:
            t0 = r["t"][next(i for i, u in enumerate(r["u"]) if u > 0.5 * r["peak"][1])]
            t = (np.array(r["t"]) - t0) * 1e9
            line, = ax.plot(t, r["u"], lw=0.9, label=f"{v} m/s")
            dots = [r["peak"]] + ([r["low"]] if r["low"] else [])
            ax.plot([(d[0] - t0) * 1e9 for d in dots], [d[1] for d in dots], "o",
                    color=line.get_color(), ms=4)
        ax.set_xlim(-10, 80)
        ax.set_xlabel("time from the shock's arrival (ns)")
        ax.set_ylabel("free-surface velocity (m/s)")
        ax.set_title(label, fontsize=9)
        ax.legend(fontsize=8)
        v, r, records = shown[m][0]
        ax = axes[1, k]
        image = ax.imshow(records.velocity.T, origin="lower", aspect="auto", cmap="RdBu_r",
                          vmin=-v, vmax=v,
                          extent=[records.x[0] * 1e6, records.x[-1] * 1e6,
                                  records.t[0] * 1e9, records.t[-1] * 1e9])
        fig.colorbar(image, ax=ax, label="velocity (m/s)")
        filled = records.x[np.any(records.count > 0, axis=1)] * 1e6
        ax.set_xlim(filled.min() - 10, filled.max() + 10)
        ax.set_xlabel("x (um)")
        ax.set_ylabel("time (ns)")
        ax.set_title(f"{m}, {v} m/s: x-t velocity (blank: empty layers)", fontsize=9)
    ax = axes[0, 4]
    for m, (label, speeds) in METHODS.items():
        share = [np.mean([r["spall"] for r in results[m][v]]) for v in speeds]
        ax.plot(speeds, share, "o-", ms=3, label=m)
    for m, colour in (("mca", "C0"), ("peri", "C2")):
        ax.axvline(acoustic_threshold(m), ls=":", lw=0.8, color=colour)
    ax.axvline(1.25 * VD, ls=":", lw=0.8, color="C3")
    ax.set_xscale("log")
    ax.set_xlabel("impact speed (m/s)")
    ax.set_ylabel("share of runs that spall")
    ax.set_title("spall against impact speed (dotted: the acoustic thresholds;\n"
                 "cd: 1.25 vd from examples/spall)", fontsize=9)
    ax.legend(fontsize=8)
    axes[1, 4].axis("off")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "plate.png"), dpi=70)
    plt.close(fig)


if __name__ == "__main__":
    main()
