#!/usr/bin/python3
"""Plate impacts of aluminium and copper from handbook data (the material cards
potentials/al.shock and cu.shock, read by card()), four ways side by side on the same plates (a
flyer of 10 fcc cells of 14.14 um on a target of 20, 5 x 5 cells across, elements or particles
of the same volume):
  mca    movable cellular automata with the shock equation of state (in.plate, with the
         links' strength as the fracture, `-var fracture threshold`, elements of 10 um);
  mca5k  the same elements as in.plate runs them by default: 5 um, the spall kinetics (the
         card's rate law; spall_rate.py's, at the converged resolution of converge.py);
  tlsph  LAMMPS's smd/tlsph: *EOS_SHOCK, *STRENGTH_LINEAR_PLASTIC and the pairwise-strain
         failure at sigma_sp / (K + 4G/3) (in.tlsph, one body as in.plate, sides held);
  peri   LAMMPS's peri/lps with the metal's K, G, density and critical stretch
         sigma_sp / (K + 4G/3) (../mca-spall/in.plate: linear elastic, no equation of state);
  cd     cluster dynamics with the calibrated clusters of potentials/ (../spall/in.spall).
For each: the shock speed in the target (x-t records) against c0 + s up, the free-surface
peak, the pull-back and the spall strength read from it by tools/pull_back.py, Kanel's
sigma_sp = 1/2 rho0 c_b (dU + delta) (mca, mca5k and tlsph, elastic-plastic: c_b the bulk c0,
c_l = sqrt((K + 4G/3)/rho0), h the flyer's thickness; peri, elastic: one speed c_L; cd, the
clusters: one speed, their c0, delta = 0),
whether and where it spalled, and the cost per particle-step (LAMMPS's timing breakdown).
And the Hugoniot of the elements (in.piston: us at up = 0.2-2 km/s, the energy they hold
against the piston's work) with the elastic precursor at up = 100 m/s.  Writes
comparison.md and shock.png; runs in runs/ (a finished run is read again: delete its folder
to run it again).  About 20 minutes on one core.

    source ../../build/env.sh; /usr/bin/python3 run_shock.py
"""
import math
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import keep, lmp_command, loops  # noqa: E402
from shock_records import XT, spall_strength  # noqa: E402

CELL = 1.0e-5 * math.sqrt(2.0)
FLYER, TARGET = 10 * CELL, 20 * CELL
CARDS = os.path.join(HERE, "..", "..", "potentials")


def card(metal, folder=CARDS):
    """The handbook data of a material card folder/<metal>.shock (SI), from its lines
    `variable NAME equal NUMBER` (rho, c0, s, gamma, G, Y, spall, upmax) and `variable material
    string "..."` (as name)."""
    text = open(os.path.join(folder, f"{metal}.shock")).read()
    data = {k: float(v) for k, v in re.findall(
        r"^variable\s+(\w+)\s+equal\s+([-+0-9.eE]+)\s*(?:#.*)?$", text, re.M)}
    data["name"] = re.search(r'^variable\s+material\s+string\s+"([^"]*)"', text, re.M).group(1)
    return data


METALS = {
    "al": dict(card("al"), vd=1170.0, pot="al-hugoniot-10um", speeds=[400, 1000, 2000]),
    "cu": dict(card("cu"), vd=792.0, pot="cu-hugoniot-10um", speeds=[400, 1000]),
}
for m in METALS.values():
    m["K"] = m["rho"] * m["c0"] ** 2
    m["cL"] = math.sqrt((m["K"] + 4.0 * m["G"] / 3.0) / m["rho"])
    nu = (3 * m["K"] - 2 * m["G"]) / (2 * (3 * m["K"] + m["G"]))
    m["hel"] = m["Y"] * (1 - nu) / (1 - 2 * nu)
METHODS = {"mca": "movable cellular automata, shock EOS (pair mca)",
           "mca5k": "the same, 5 um elements and the spall kinetics (in.plate's defaults)",
           "tlsph": "smd/tlsph, EOS_SHOCK + linear plastic + pairwise failure",
           "peri": "peri/lps, linear elastic",
           "cd": "cluster dynamics (calibrated clusters)"}
UPS = [200, 500, 1000, 2000]
SWEEP = {"al": range(150, 240, 10), "cu": range(60, 130, 10)}    # the elements' spall threshold
SEEDS = [0, 1, 2]
B1 = [0.06, 0.15, 0.3, 0.6]     # the bulk viscosity's linear coefficient against the pull-back
RUNS = os.path.join(HERE, "runs")


def inputs(method, metal, v):
    """The input script and its -var settings of one plate impact."""
    m = METALS[metal]
    if method == "mca":
        return os.path.join(HERE, "in.plate"), {"metal": metal, "v": v, "here": HERE + "/",
                                                "fracture": "threshold", "d": 1.0e-5}
    if method == "mca5k":
        return os.path.join(HERE, "in.plate"), {"metal": metal, "v": v, "here": HERE + "/"}
    if method == "tlsph":
        return os.path.join(HERE, "in.tlsph"), {"metal": metal, "v": v, "failure": "pairwise",
                                                "bodies": 1}
    if method == "peri":
        return (os.path.join(HERE, "..", "mca-spall", "in.plate"),
                {"method": "peri", "v": v, "K": m["K"], "G": m["G"], "rho": m["rho"],
                 "strength": m["spall"]})
    return (os.path.join(HERE, "..", "spall", "in.spall"),
            {"pot": m["pot"], "cells": 5, "ratio": v / m["vd"]})


def pair_time(log):
    """The Pair row of the last timing breakdown in log (s)."""
    rows = re.findall(r"^Pair\s+\|\s+\S+\s+\|\s+(\S+)", open(log).read(), re.M)
    return float(rows[-1])


def time_step(out):
    """The time step a run used (s), from its log's timestep command."""
    steps = re.findall(r"^\s*timestep\s+(\S+)", out, re.M)
    return float(steps[-1])


def front_speed(xt, level, lo, hi):
    """The speed of a front (where the layers' velocity falls through level ahead of the
    farthest layer above it, interpolated between the layers) on its first crossing of
    lo..hi: a straight line through its places and times."""
    t, x = [], []
    for k, time in enumerate(xt.t):
        v = np.nan_to_num(xt.velocity[:, k])
        moving = np.where(v > level)[0]
        if not len(moving) or moving.max() + 1 >= len(v):
            continue
        j = moving.max()
        place = xt.x[j] + (xt.x[j + 1] - xt.x[j]) * (v[j] - level) / (v[j] - v[j + 1])
        if place >= hi:
            break
        if place > lo:
            t.append(time)
            x.append(place)
    if len(t) < 3:
        return float("nan")
    return float(np.polyfit(t, x, 1)[0])


def spall_plane(xt, rho):
    """The depth below the target's rear face of the emptiest layer inside the target at the
    last record (m), or None where no layer is below half the density: the layers taken two
    cells thick (a layer of one plane of elements holds 0 or 2 as the planes move)."""
    group = max(1, int(round(2 * CELL / (xt.x[1] - xt.x[0]))))
    n = len(xt.x) // group * group
    density = np.nan_to_num(xt.density[:n, -1]).reshape(-1, group).mean(axis=1)
    x = xt.x[:n].reshape(-1, group).mean(axis=1)
    filled = np.where(density > 0.5 * rho)[0]
    inside = [k for k in range(filled.min(), filled.max() + 1)
              if x[k] > FLYER + 2 * CELL and not density[k] > 0.5 * rho]
    if not inside:
        return None
    return float(x[filled.max()] - np.mean(x[inside]))


def impact(method, metal, v, workdir, seed=0, extra=None):
    """Run one plate impact in workdir: its size, cost and whether it spalled (its records stay
    there for read_impact())."""
    script, var = inputs(method, metal, v)
    var = dict(var, out="run")
    if seed:
        var["seed"] = seed
    if extra:
        var["extra"] = extra
    try:
        out = lmp_command(script, var, workdir, args=["-log", "log.lammps"])
    except subprocess.CalledProcessError as failed:
        stop = re.search(r"^ERROR: (.*)$", failed.stdout, re.M)
        return dict(stopped=stop.group(1) if stop else "no message")
    loop, _, steps, atoms = loops(out)[-1]
    large = re.search(r"large fragments of the target: (\d+)", out)
    cracked = re.search(r"lost more than half of their partners: (\d+)", out)
    spalled = (int(large.group(1)) >= 2) if large else (int(cracked.group(1)) > 0)
    return dict(atoms=atoms, steps=steps, loop=loop,
                pair=pair_time(os.path.join(workdir, "log.lammps")), spalled=spalled)


def speeds(method, metal):
    """(c_l, c_b) of a method's target for tools/pull_back.py: the elastic-plastic metal of mca
    and tlsph has both (Kanel's correction); peri's linear elastic target one, c_L; the
    clusters one, their c0 (a metal-calibrated set's elastic and shock waves are one)."""
    m = METALS[metal]
    if method in ("mca", "mca5k", "tlsph"):
        return m["cL"], m["c0"]
    return (m["cL"], m["cL"]) if method == "peri" else (m["c0"], m["c0"])


def read_impact(method, metal, v, workdir, run):
    """A finished impact's readings from its records: the shock speed in the target, the
    free-surface peak, the pull-back's spall strength (Kanel's sigma_sp, with the acoustic
    values 1/2 rho0 c_b dU and 1/2 rho0 c_l dU beside), the spall plane."""
    if "stopped" in run:
        return run
    m = METALS[metal]
    dt = time_step(open(os.path.join(workdir, "log.lammps")).read())
    xt = XT(os.path.join(workdir, "run.xt"), dt)
    record = np.loadtxt(os.path.join(workdir, "run.visar"))
    t, u = record[:, 1], record[:, 2]
    c_long, c_bulk = speeds(method, metal)
    try:
        got = spall_strength(t, u, 2 * FLYER / c_bulk, m["rho"], c_long, c_bulk, FLYER)
        vp, strength, delta = got.v_peak, got.sigma, got.delta
        bulk, elastic = got.acoustic_bulk, got.acoustic_long
    except ValueError:
        vp, strength, delta, bulk, elastic = float(np.max(u)), None, None, None, None
    return dict(run, us=front_speed(xt, v / 4, FLYER + 0.15 * TARGET, FLYER + 0.8 * TARGET),
                peak=float(vp), strength=strength, delta=delta, bulk=bulk, elastic=elastic,
                depth=spall_plane(xt, m["rho"]) if run["spalled"] else None)


def piston(metal, up, workdir):
    """A piston run of in.piston: the shock (or at 100 m/s the precursor) speed, the
    precursor's amplitude, the piston's stress and the energy held against the work."""
    m = METALS[metal]
    out = lmp_command(os.path.join(HERE, "in.piston"),
                      {"metal": metal, "up": up, "here": HERE + "/", "out": "run"}, workdir,
                      args=["-log", "log.lammps"])
    dt = time_step(open(os.path.join(workdir, "log.lammps")).read())
    xt = XT(os.path.join(workdir, "run.xt"), dt)
    length = 60 * CELL
    ue = m["hel"] / (m["rho"] * m["cL"])
    result = dict(stress=float(re.search(r"piston stress (\S+) Pa", out).group(1)),
                  held=float(re.search(r"piston work (\S+)", out).group(1)),
                  us=front_speed(xt, up / 2, 0.2 * length, 0.7 * length),
                  elastic=front_speed(xt, ue / 2, 0.2 * length, 0.8 * length))
    # the precursor's plateau: the layers between the two fronts at the last record
    last = xt.velocity[:, -1]
    ahead = np.where(last > ue / 2)[0].max()
    behind = np.where(last > (up + ue) / 2)[0].max()
    between = np.arange(behind + (ahead - behind) // 4, ahead - (ahead - behind) // 4 + 1)
    result["plateau"] = float(np.nanmean(last[between])) if len(between) >= 2 else None
    return result


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    return "\n".join(lines + ["| " + " | ".join(str(c) for c in r) + " |" for r in rows])


def fmt(value, spec):
    return "-" if value is None or (isinstance(value, float) and math.isnan(value)) \
        else format(value, spec)


def main():
    pistons = {(metal, up): keep(os.path.join(RUNS, f"piston-{metal}-{up}"),
                                 lambda w, metal=metal, up=up: piston(metal, up, w))
               for metal in METALS for up in [100] + UPS}
    runs = {}
    for metal, m in METALS.items():
        for v in m["speeds"]:
            for method in METHODS:
                folder = os.path.join(RUNS, f"{method}-{metal}-{v}")
                runs[(method, metal, v)] = read_impact(
                    method, metal, v, folder,
                    keep(folder, lambda w, a=method, b=metal, c=v: impact(a, b, c, w)))
    sweep = {}
    for metal in METALS:
        for v in SWEEP[metal]:
            for seed in SEEDS:
                folder = os.path.join(RUNS, f"sweep-{metal}-{v}-{seed}")
                sweep[(metal, v, seed)] = read_impact(
                    "mca", metal, v, folder,
                    keep(folder, lambda w, a=metal, b=v, c=seed: impact("mca", a, b, w, c)))
    report = ["# Plate impacts of aluminium and copper: four methods side by side "
              "(written by run_shock.py)", ""]
    report += ["## The elements' Hugoniot (in.piston)", ""]
    rows = []
    for metal, m in METALS.items():
        for up in UPS:
            r = pistons[(metal, up)]
            us = m["c0"] + m["s"] * up
            rows.append([m["name"], up, f"{r['us']:.0f}", f"{us:.0f}",
                         f"{r['us'] / us:.3f}", f"{r['stress'] / 1e9:.2f}",
                         f"{m['rho'] * r['us'] * up / 1e9:.2f}", f"{r['held']:.4f}"])
    report += [table(["metal", "up (m/s)", "us (m/s)", "c0 + s up (m/s)", "ratio",
                      "piston stress (GPa)", "rho0 us up (GPa)", "energy held / work"], rows)]
    rows = []
    for metal, m in METALS.items():
        r = pistons[(metal, 100)]
        plateau = r["plateau"]
        rows.append([m["name"], f"{r['elastic']:.0f}", f"{m['cL']:.0f}",
                     fmt(None if plateau is None else m["rho"] * m["cL"] * plateau / 1e9, ".3f"),
                     f"{m['hel'] / 1e9:.3f}"])
    report += ["", "Elastic precursor at up = 100 m/s:", "",
               table(["metal", "precursor speed (m/s)", "c_L (m/s)",
                      "its stress rho0 c_L u (GPa)", "HEL Y (1 - nu)/(1 - 2 nu) (GPa)"], rows)]
    report += ["", "## The spall strength of the elements at their threshold", "",
               "Sweeps in 10 m/s of in.plate (mca), runs from rest and with seeds 1, 2 (1 m/s "
               "thermal start); the threshold is the lowest speed at which all spall; the "
               "pull-back read there by Kanel's sigma_sp = 1/2 rho0 c_b (dU + delta) (c_b the "
               "bulk c0, c_l = sqrt((K + 4G/3)/rho0), h the flyer's 141 um; tools/pull_back.py), "
               "with the plain acoustic values beside:", ""]
    rows = []
    for metal, m in METALS.items():
        done = {v: [sweep[(metal, v, seed)] for seed in SEEDS
                    if "stopped" not in sweep[(metal, v, seed)]] for v in SWEEP[metal]}
        counts = {v: sum(r["spalled"] for r in done[v]) for v in SWEEP[metal]}
        stopped = [f"{v} m/s seed {seed}" for v in SWEEP[metal] for seed in SEEDS
                   if "stopped" in sweep[(metal, v, seed)]]
        at = next((v for v in SWEEP[metal] if done[v] and counts[v] == len(done[v])), None)
        runs_at = done[at] if at else []
        kanel = [r["strength"] for r in runs_at if r["strength"]]
        delta = [r["delta"] for r in runs_at if r["strength"]]
        elastic = [r["elastic"] for r in runs_at if r["elastic"]]
        bulk = [r["bulk"] for r in runs_at if r["bulk"]]
        rows.append([m["name"], ", ".join(f"{v}: {c}/{len(done[v])}" for v, c in counts.items())
                     + (f" (stopped with an error: {', '.join(stopped)})" if stopped else ""),
                     at, f"{2 * m['spall'] / (m['rho'] * m['cL']):.0f}",
                     f"{np.mean(kanel) / 1e9:.2f} ± {np.std(kanel, ddof=1) / 1e9:.2f}"
                     if len(kanel) > 1 else "-",
                     f"{np.mean(delta):.0f}" if delta else "-",
                     f"{np.mean(elastic) / 1e9:.2f} ± {np.std(elastic, ddof=1) / 1e9:.2f}"
                     if len(elastic) > 1 else "-",
                     f"{np.mean(bulk) / 1e9:.2f} ± {np.std(bulk, ddof=1) / 1e9:.2f}"
                     if len(bulk) > 1 else "-", f"{m['spall'] / 1e9:.1f}"])
    report += [table(["metal", "spalled / finished runs per speed (m/s)", "threshold (m/s)",
                      "acoustic threshold 2 sigma_sp / (rho c_L) (m/s)",
                      "pull-back sigma_sp = 1/2 rho0 c_b (dU + delta) (GPa)", "delta (m/s)",
                      "acoustic 1/2 rho0 c_l dU (GPa)", "acoustic 1/2 rho0 c_b dU (GPa)",
                      "strength given (GPa)"], rows)]
    viscous = {(metal, b1): read_impact(
        "mca", metal, 400, os.path.join(RUNS, f"b1-{metal}-{b1}"), keep(
        os.path.join(RUNS, f"b1-{metal}-{b1}"),
        lambda w, a=metal, b=b1: impact("mca", a, 400, w, extra=f"bulk_viscosity {b} 1.2")))
        for metal in METALS for b1 in B1}
    report += ["", "The bulk viscosity's linear coefficient b1 (b2 = 1.2) against the pull-back "
               "sigma_sp = 1/2 rho0 c_b (dU + delta) (GPa) at 400 m/s (the default b1 = 0.06):",
               "",
               table(["metal"] + [f"b1 = {b1}" for b1 in B1],
                     [[m["name"]] + [fmt(None if viscous[(metal, b1)]["strength"] is None
                                         else viscous[(metal, b1)]["strength"] / 1e9, ".2f")
                                     for b1 in B1] for metal, m in METALS.items()])]
    report += ["", "## Plate impacts", ""]
    rows = []
    for metal, m in METALS.items():
        for v in m["speeds"]:
            for method in METHODS:
                r = runs[(method, metal, v)]
                us = m["c0"] + m["s"] * v / 2
                rows.append([m["name"], v, method, r["atoms"], f"{r['us']:.0f} ({r['us'] / us:.3f})",
                             f"{r['peak'] / v:.3f}",
                             fmt(None if r["strength"] is None else r["strength"] / 1e9, ".2f"),
                             f"{m['spall'] / 1e9:.1f}",
                             ("yes" if r["spalled"] else "no") + (
                                 f", {r['depth'] * 1e6:.0f} um" if r["depth"] else ""),
                             f"{1e6 * r['pair'] / (r['atoms'] * r['steps']):.2f}",
                             f"{1e6 * r['loop'] / (r['atoms'] * r['steps']):.2f}"])
    report += [table(["metal", "v (m/s)", "method", "particles",
                      "shock speed (m/s; / c0 + s v/2)", "free-surface peak / v",
                      "pull-back sigma_sp (GPa)", "strength given (GPa)",
                      "spall, depth below the rear face", "Pair us per particle-step",
                      "loop us per particle-step"], rows)]
    report += ["", "The pull-back sigma_sp by tools/pull_back.py: 1/2 rho0 c_b (dU + delta) with "
               "Kanel's correction for mca, mca5k and tlsph (elastic-plastic: c_b the bulk c0, "
               "c_l = sqrt((K + 4G/3)/rho0), h the flyer's thickness), 1/2 rho0 c_L dU for peri "
               "(linear elastic: one speed) and 1/2 rho0 c0 dU for cd (the clusters: one speed, "
               "their c0); the records smoothed over a tenth of the pulse 2 H / c_b." + "".join(
                   f"  No spall pulse front after the minimum (u2' unknown, delta taken 0: a "
                   f"lower bound): {', '.join(lacking)}." for lacking in [[
                       f"{METALS[metal]['name']} {method} at {v} m/s"
                       for (method, metal, v), r in runs.items()
                       if method in ("mca", "mca5k", "tlsph") and r.get("strength")
                       and not r["delta"]]]
                   if lacking)]
    cost = {method: np.mean([1e6 * r["pair"] / (r["atoms"] * r["steps"])
                             for (a, _, _), r in runs.items() if a == method])
            for method in METHODS}
    report += ["", "Cost per particle-step (Pair, mean of the runs): " + ", ".join(
        f"{method} {cost[method]:.2f} us" for method in METHODS) +
        f"; mca / tlsph = {cost['mca'] / cost['tlsph']:.2f} (LAMMPS's timings of these runs, "
        "on whatever else the machine ran: the side-by-side comparison on a quiet machine is "
        "bench/bench_shock_cost.sh's, doc/benchmarks/bench_mca.md).", ""]
    with open(os.path.join(HERE, "comparison.md"), "w") as f:
        f.write("\n".join(report))
    plot(runs, pistons)


def plot(runs, pistons):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 3, figsize=(16, 9))
    for ax, (metal, v) in zip(axes[0], [("al", 400), ("al", 1000), ("cu", 400)]):
        for method, label in METHODS.items():
            record = np.loadtxt(os.path.join(RUNS, f"{method}-{metal}-{v}", "run.visar"))
            ax.plot(record[:, 1] * 1e9, record[:, 2], label=label)
        ax.set(title=f"{METALS[metal]['name']}, flyer at {v} m/s: free-surface velocity",
               xlabel="t (ns)", ylabel="v (m/s)")
        ax.legend(fontsize=7, loc="center left")
    for ax, method in zip(axes[1][:2], ["mca", "tlsph"]):
        folder = os.path.join(RUNS, f"{method}-al-400")
        dt = time_step(open(os.path.join(folder, "log.lammps")).read())
        xt = XT(os.path.join(folder, "run.xt"), dt)
        mesh = ax.pcolormesh(xt.t * 1e9, xt.x * 1e6, xt.velocity, shading="auto", cmap="viridis")
        fig.colorbar(mesh, ax=ax, label="vx (m/s)")
        ax.set(title=f"x-t, aluminium at 400 m/s: {method}", xlabel="t (ns)",
               ylabel="x (um)")
    ax = axes[1][2]
    for metal, m in METALS.items():
        up = np.array(UPS, dtype=float)
        ax.plot(up, m["c0"] + m["s"] * up, "-", label=f"{m['name']}: c0 + s up")
        ax.plot(up, [pistons[(metal, u)]["us"] for u in UPS], "o",
                label=f"{m['name']}: elements (in.piston)")
    ax.set(title="Hugoniot", xlabel="up (m/s)", ylabel="us (m/s)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "shock.png"), dpi=90)


if __name__ == "__main__":
    main()
