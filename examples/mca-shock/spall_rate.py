#!/usr/bin/python3
"""Spall as a material property: aluminium 6061-T6 and OFHC copper plates (in.plate with the
elements' spall kinetics, `spall S rate m` from the cards potentials/al.shock and cu.shock) at
1.1, 2 and 5 times their spall threshold and at 1 and 2 km/s, ensembles of 3 (from rest and
with thermal seeds 1 and 2, as run_shock.py), elements of 5 um (converge.py: the kinetics'
pull-back moves by 1-2 % from 5 to 2.5 um).  The threshold: the lowest speed, in steps of 10
m/s, at which all three spall (a bisection of the run from rest, then the ensemble at it and
10 m/s below).  Readings of each free-surface record (converge.readings): Kanel's sigma_sp
(tools/pull_back.py, with the elastic-plastic correction), the strain rate of the release ahead
of the pull-back |du/dt| / (2 c0), and the card's rate law sigma_sp = S (rate / rate_ref)^m at
that rate, which the reading should give.  And at the spall plane itself (the x-t records'
layers of half a cell): the largest mean tension of a layer inside the target (the virial
pressure, which the kinetics bounds) and its rate, the peak over the time since the layer was
last in compression, over K = rho0 c0^2, with the law at that rate.  Writes spall_rate.md and
spall_rate.png; runs in runs/spall (a finished run is read again).

    source ../../build/env.sh; /usr/bin/python3 spall_rate.py [--jobs 2]
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
from converge import FLYER_UM, TARGET_UM, peer, readings  # noqa: E402
from run_shock import METALS, time_step  # noqa: E402
from shock_records import XT  # noqa: E402
from runner import keep, lmp_command, loops, mean_sd, parallel, table  # noqa: E402

D_UM = 5.0
SEEDS = [0, 1, 2]
BRACKET = {"al": (200, 600), "cu": (100, 500)}    # no spall at the first, spall at the second
FAST = [1000, 2000]
RUNS = os.path.join(HERE, "runs", "spall")


def impact(metal, v, seed, fracture="kinetics"):
    """One plate of in.plate with 5 um elements and the fracture (kept in its folder): whether
    it spalled, its cost, and the readings of its free-surface record."""
    cells = int(round(10 * 10.0 / D_UM))
    var = {"metal": metal, "v": v, "here": HERE + "/", "out": "run", "d": D_UM * 1e-6,
           "flyer": cells, "target": 2 * cells, "records": 800, "fracture": fracture}
    if seed:
        var["seed"] = seed

    def make(workdir):
        out = lmp_command(os.path.join(HERE, "in.plate"), var, workdir,
                          args=["-log", "log.lammps"])
        loop, _, steps, atoms = loops(out)[-1]
        large = int(out.split("large fragments of the target: ")[1].split(";")[0])
        return dict(loop=loop, steps=steps, atoms=atoms, spalled=large >= 2)
    workdir = os.path.join(RUNS, f"{metal}-{v}-{seed}" + ("" if fracture == "kinetics"
                                                           else f"-{fracture}"))
    result = keep(workdir, make)
    record = np.loadtxt(os.path.join(workdir, "run.visar"))
    return dict(result, **readings(record[:, 1], record[:, 2], v, METALS[metal]),
                **plane(workdir, METALS[metal]))


def plane(workdir, m):
    """At the spall plane: the largest mean tension of a layer of the x-t records inside the
    target (1 um from its faces), its rate (that tension over the time since the layer was last
    in compression, over K), and the card's law at that rate."""
    dt = time_step(open(os.path.join(workdir, "log.lammps")).read())
    xt = XT(os.path.join(workdir, "run.xt"), dt)
    inside = (xt.x > (FLYER_UM + 1.0) * 1e-6) & (xt.x < (FLYER_UM + TARGET_UM - 1.0) * 1e-6)
    tension = -np.nan_to_num(xt.pressure[inside])
    layer, k = np.unravel_index(np.argmax(tension), tension.shape)
    history, peak = tension[layer], tension[layer, k]
    last = np.where(history[:k] <= 0.0)[0]
    if not len(last):
        return dict(plane=peak / 1e9, plane_rate=None, plane_law=None)
    j = last[-1]
    start = xt.t[j] + (xt.t[j + 1] - xt.t[j]) * -history[j] / (history[j + 1] - history[j])
    rate = peak / (xt.t[k] - start) / (m["rho"] * m["c0"] ** 2)
    return dict(plane=peak / 1e9, plane_rate=rate,
                plane_law=m["spall"] * (rate / m["spall_rate"]) ** m["spall_m"] / 1e9)


def threshold(metal):
    """The lowest speed (10 m/s steps) at which the run from rest spalls, by bisection in
    BRACKET, then raised until all three of the ensemble spall."""
    lo, hi = BRACKET[metal]
    while hi - lo > 10:
        mid = (lo + hi) // 20 * 10
        if impact(metal, mid, 0)["spalled"]:
            hi = mid
        else:
            lo = mid
    while not all(impact(metal, hi, seed)["spalled"] for seed in SEEDS):
        hi += 10
    return hi


def study(metal):
    """The threshold, the ensembles at 1.1, 2, 5 times it and at 1 and 2 km/s, and the runs
    from rest with the mean-tension threshold at those speeds."""
    vth = threshold(metal)
    below = [impact(metal, vth - 10, seed)["spalled"] for seed in SEEDS]
    speeds = sorted({int(round(k * vth / 10.0)) * 10 for k in (1.1, 2.0, 5.0)} | set(FAST))
    runs = {v: [impact(metal, v, seed) for seed in SEEDS] for v in speeds}
    pressure = {v: impact(metal, v, 0, "pressure") for v in speeds}
    return dict(threshold=vth, below=below, runs=runs, pressure=pressure)


def main():
    ap = argparse.ArgumentParser(description=__doc__.strip().split("\n")[0])
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--pyko", default=None, help="folder of a peer code's <metal><V>.visar")
    opts = ap.parse_args()
    metals = ["al", "cu"]
    studies = dict(zip(metals, parallel(study, metals, opts.jobs) if opts.jobs > 1
                       else map(study, metals)))
    lines = ["# Spall as a material property: the elements' spall kinetics (spall_rate.py)", "",
             "Plates of in.plate (flyer 141 um, target 283 um, 5 x 5 fcc cells across), elements "
             f"of {D_UM:g} um, ensembles of 3 (from rest, seeds 1 and 2).  Kanel: 1/2 rho0 c0 "
             "(dU + delta); rate: |du/dt| / (2 c0) of the release ahead of the pull-back; law: "
             "the card's spall (rate / spall_rate)^spall_m at that rate.  plane: the largest "
             "mean tension of a layer inside the target and its rate (from the layer's last "
             "compression), against the law at that rate.", ""]
    rows = []
    for metal in metals:
        m, st = METALS[metal], studies[metal]
        lines.append(f"- {m['name']}: spall threshold {st['threshold']} m/s (all three spall; at "
                     f"{st['threshold'] - 10} m/s {sum(st['below'])} of 3); card: "
                     f"{m['spall'] / 1e9:g} GPa at {m['spall_rate']:g} /s, m = {m['spall_m']:g}")
        for v, runs in st["runs"].items():
            spalled = sum(r["spalled"] for r in runs)
            got = [r for r in runs if r["kanel"] is not None]
            kanel = [r["kanel"] for r in got]
            law = [r["law"] for r in got]
            ratio = [r["kanel"] / r["law"] for r in got]
            at = [r for r in runs if r["plane_rate"]]
            rows.append([m["name"], v, f"{v / st['threshold']:.2f}", f"{spalled}/3",
                         spread([r["rate"] / 1e5 for r in got], 2), spread(kanel, 3),
                         spread([r["bulk"] for r in got], 3), spread(law, 3),
                         spread(ratio, 3), spread([r["plane"] for r in at], 3),
                         spread([r["plane_rate"] / 1e5 for r in at], 1),
                         spread([r["plane"] / r["plane_law"] for r in at], 3),
                         f"{np.mean([r['loop'] for r in runs]):.0f}"])
    lines += ["", *table(["metal", "v (m/s)", "v / threshold", "spalled", "rate (1e5 /s)",
                          "Kanel (GPa)", "1/2 rho0 c0 dU (GPa)", "law at the rate (GPa)",
                          "Kanel / law", "plane: mean tension (GPa)", "plane: rate (1e5 /s)",
                          "plane: tension / law", "run (s)"], rows), ""]
    lines += one_fracture(studies, opts.pyko)
    with open(os.path.join(HERE, "spall_rate.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))
    plot(studies, opts.pyko)


def one_fracture(studies, pyko):
    """The table of both codes with a threshold S on the mean tension: Kanel's reading over S."""
    rows = []
    for metal, st in studies.items():
        m = METALS[metal]
        for v, r in st["pressure"].items():
            ref = peer(pyko, v, metal)
            rows.append([m["name"], v, "yes" if r["spalled"] else "no", fmt(r["kanel"], ".3f"),
                         fmt(r["kanel"] and r["kanel"] * 1e9 / m["spall"], ".3f"),
                         fmt(ref and ref["kanel"], ".3f"),
                         fmt(ref and ref["kanel"] and ref["kanel"] * 1e9 / m["spall"], ".3f"),
                         fmt(ref and ref["kanel"] and r["kanel"] and r["kanel"] / ref["kanel"],
                             ".3f")])
    return ["", "Both codes with one fracture, a threshold S on the mean tension (the card's "
            "spall strength; the elements' run from rest with -var fracture pressure, the peer's "
            "at 1 um cells; '-' where no record was given or no pull-back could be read):", "",
            *table(["metal", "v (m/s)", "elements spalled", "elements: Kanel (GPa)",
                    "elements: Kanel / S", "peer: Kanel (GPa)", "peer: Kanel / S",
                    "elements / peer"], rows), ""]


def fmt(x, spec):
    return "-" if x is None else format(x, spec)


def spread(values, digits):
    """mean ± sd of two or more values, the value of one, '-' of none."""
    if len(values) > 1:
        return mean_sd(values, digits)
    return f"{values[0]:.{digits}f}" if values else "-"


def plot(studies, pyko):
    """spall_rate.png: the strength read from each record against its strain rate, beside the
    cards' rate laws; and each metal's records (from rest) over the peer's where given."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, *records) = plt.subplots(1, 3, figsize=(16, 5.0))
    rates = np.logspace(4.5, 6.8, 50)
    for k, (metal, st) in enumerate(studies.items()):
        m = METALS[metal]
        ax.plot(rates, m["spall"] * (rates / m["spall_rate"]) ** m["spall_m"] / 1e9, "-",
                color=f"C{k}", label=f"{m['name']}: card's rate law")
        for v, runs in st["runs"].items():
            got = [r for r in runs if r["kanel"] is not None]
            ax.plot([r["rate"] for r in got], [r["kanel"] for r in got], "o", color=f"C{k}",
                    ms=4, label=None)
    ax.plot([], [], "ko", ms=4, label="elements: Kanel's reading of each record")
    ax.set_xscale("log")
    ax.set_xlabel("strain rate of the release |du/dt| / (2 c0) (1/s)")
    ax.set_ylabel("spall strength (GPa)")
    ax.set_title("spall strength against strain rate")
    ax.legend(fontsize=7)
    for metal, bx in zip(studies, records):
        for k, v in enumerate(studies[metal]["runs"]):
            record = np.loadtxt(os.path.join(RUNS, f"{metal}-{v}-0", "run.visar"))
            bx.plot(record[:, 1] * 1e9, record[:, 2], color=f"C{k}", lw=1, label=f"{v} m/s")
            ref = peer(pyko, v, metal)
            if ref:
                bx.plot(ref["t"] * 1e9, ref["u"], ":", color=f"C{k}", lw=1)
        if pyko:
            bx.plot([], [], "k:", lw=1, label="peer (pyKO, 1 um), threshold")
        bx.set_xlim(30, 180 if metal == "al" else 230)
        bx.set_xlabel("time (ns)")
        bx.set_ylabel("free-surface velocity (m/s)")
        bx.set_title(f"{METALS[metal]['name']}, 5 um elements, kinetics (run from rest)")
        bx.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=3)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "spall_rate.png"), dpi=110)


if __name__ == "__main__":
    main()
