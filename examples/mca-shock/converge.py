#!/usr/bin/python3
"""The plate-impact record of the elements against their size: aluminium 6061-T6 (in.plate, the
card potentials/al.shock) at 220, 400, 1000 and 2000 m/s with elements of 10, 5 and 2.5 um
(flyer and target the same thickness, 141.4 and 282.8 um, 5 x 5 fcc cells across), and the
same readings of a peer hydrocode's records where given (--pyko DIR: DIR/al<V>.visar, columns
time (s) and free-surface velocity (m/s), e.g. pyKO's, S. T. Stewart, github.com/ImpactsWiki/pyko,
converged at 1 um cells).  Readings of each free-surface record:
  pull-back  1/2 rho0 c0 dU and 1/2 rho0 c_L dU (tools/pull_back.py: dU from the peak to the
             first minimum after it) and Kanel's sigma_sp with the elastic-plastic correction;
  rate       the strain rate of the release ahead of the pull-back, |du/dt| / (2 c0), and the
             card's rate law at it, spall (rate / spall_rate)^spall_m (what the elements'
             spall kinetics should read; plotted for the plates that spalled);
  precursor  the velocity halfway between the elastic front's arrival (target / c_L) and the
             plastic front's (target / (c0 + s v/2));
  rise       10-90 % of the peak, from the first crossing of a tenth of the peak;
  depth      the spall plane below the free face (x-t records; elements only);
  cost       the loop time on one core.
Writes convergence.md and convergence.png; runs in runs/converge (a finished run is read again).

    source ../../build/env.sh; /usr/bin/python3 converge.py [--pyko DIR] [--jobs 1] [--report]
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
from runner import keep, lmp_command, loops, parallel, table  # noqa: E402
from run_shock import METALS, time_step  # noqa: E402
from shock_records import XT, spall_strength  # noqa: E402

SPEEDS = [220, 400, 1000, 2000]
SIZES = [10.0, 5.0, 2.5]              # element size, um
FLYER_UM, TARGET_UM = 10 * 10 * math.sqrt(2), 20 * 10 * math.sqrt(2)
RUNS = os.path.join(HERE, "runs", "converge")
AL = METALS["al"]


def run(item):
    """One plate impact of aluminium at v with elements of d um and the fracture (kinetics or
    threshold; kept in its folder)."""
    v, d, fracture = item
    cells = int(round(10 * 10.0 / d))
    var = {"metal": "al", "v": v, "here": HERE + "/", "out": "run", "d": d * 1e-6,
           "flyer": cells, "target": 2 * cells, "records": 800, "fracture": fracture}

    def make(workdir):
        out = lmp_command(os.path.join(HERE, "in.plate"), var, workdir,
                          args=["-log", "log.lammps"])
        loop, _, steps, atoms = loops(out)[-1]
        return dict(loop=loop, steps=steps, atoms=atoms)
    workdir = os.path.join(RUNS, f"v{v}-d{d:g}-{fracture}")
    result = keep(workdir, make)
    dt = time_step(open(os.path.join(workdir, "log.lammps")).read())
    record = np.loadtxt(os.path.join(workdir, "run.visar"))
    xt = XT(os.path.join(workdir, "run.xt"), dt)
    log = open(os.path.join(workdir, "log.lammps")).read()
    large = int(log.split("large fragments of the target: ")[-1].split(";")[0])
    return dict(result, **readings(record[:, 1], record[:, 2], v),
                depth=spall_depth(xt, d * 1e-6), spalled=large >= 2)


def readings(t, u, v, m=AL):
    """The pull-back, precursor and rise of a free-surface record (t in s, u in m/s) of an
    impact at v on the plates of in.plate, metal m (a card of run_shock.METALS)."""
    flyer, target = FLYER_UM * 1e-6, TARGET_UM * 1e-6
    c0, cl, rho = m["c0"], m["cL"], m["rho"]
    got = {}
    try:
        r = spall_strength(t, u, 2 * flyer / c0, rho, cl, c0, flyer)
        rate = abs(r.u1) / (2.0 * c0)
        got.update(bulk=r.acoustic_bulk / 1e9, long=r.acoustic_long / 1e9, kanel=r.sigma / 1e9,
                   du=r.du, peak=r.v_peak, rate=rate,
                   law=m["spall"] * (rate / m["spall_rate"]) ** m["spall_m"] / 1e9)
    except ValueError:
        got.update(bulk=None, long=None, kanel=None, du=None, peak=float(np.max(u)), rate=None,
                   law=None)
    us = c0 + m["s"] * v / 2
    t_mid = 0.5 * (target / cl + target / us)
    got["precursor"] = float(np.interp(t_mid, t, u)) if us < cl else None
    top = got["peak"]
    first = np.argmax(u > 0.1 * top)
    ninety = first + np.argmax(u[first:] > 0.9 * top)
    got["rise"] = float(t[ninety] - t[first]) * 1e9
    return got


def spall_depth(xt, d):
    """The depth below the free face of the emptiest layer inside the target at the last
    record (um), None where no layer inside is below half the density (layers two cells
    thick)."""
    cell = d * math.sqrt(2)
    group = max(1, int(round(2 * cell / (xt.x[1] - xt.x[0]))))
    n = len(xt.x) // group * group
    density = np.nan_to_num(xt.density[:n, -1]).reshape(-1, group).mean(axis=1)
    x = xt.x[:n].reshape(-1, group).mean(axis=1)
    filled = np.where(density > 0.5 * AL["rho"])[0]
    inside = [k for k in range(filled.min(), filled.max() + 1)
              if x[k] > FLYER_UM * 1e-6 + 2 * cell and not density[k] > 0.5 * AL["rho"]]
    return float(x[filled.max()] - np.mean(x[inside])) * 1e6 if inside else None


def peer(folder, v, metal="al"):
    """The readings of a peer code's record folder/<metal><v>.visar (resampled at 0.2 ns: pyKO
    writes every step) with its times t and velocities u, or None."""
    path = os.path.join(folder, f"{metal}{v}.visar") if folder else ""
    if not os.path.exists(path):
        return None
    data = np.loadtxt(path)
    keep_rows = np.concatenate([[True], np.diff(data[:, 0]) > 0])
    t, u = data[keep_rows, 0], data[keep_rows, 1]
    grid = np.arange(t[0], t[-1], 0.2e-9)
    return dict(readings(grid, np.interp(grid, t, u), v, METALS[metal]), t=t, u=u, depth=None,
                loop=None, atoms=None)


def fmt(x, spec):
    return "-" if x is None else format(x, spec)


def main():
    import argparse
    ap = argparse.ArgumentParser(description=__doc__.strip().split("\n")[0])
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--pyko", default=None, help="folder of a peer code's al<V>.visar records")
    ap.add_argument("--sizes", default=",".join(f"{d:g}" for d in SIZES))
    ap.add_argument("--fractures", default="threshold,kinetics")
    opts = ap.parse_args()
    sizes = [float(s) for s in opts.sizes.split(",")]
    fractures = opts.fractures.split(",")
    items = [(v, d, f) for f in fractures for v in SPEEDS for d in sizes]
    results = dict(zip(items, parallel(run, items, opts.jobs) if opts.jobs > 1
                       else map(run, items)))
    rows = []
    for v in SPEEDS:
        ref = peer(opts.pyko, v) if opts.pyko else None
        for d, f in [(d, f) for f in fractures for d in sizes]:
            r = results[(v, d, f)]
            rows.append([v, f"{d:g}", f, r["atoms"], fmt(r["loop"], ".1f"), fmt(r["bulk"], ".3f"),
                         fmt(r["long"], ".3f"), fmt(r["kanel"], ".3f"),
                         fmt(r["rate"] and r["rate"] / 1e5, ".2f"), fmt(r["law"], ".3f"),
                         fmt(r["precursor"], ".0f"), fmt(r["rise"], ".1f"),
                         fmt(r["depth"], ".0f")])
        if ref:
            rows.append([v, "peer", "threshold", "-", "-", fmt(ref["bulk"], ".3f"),
                         fmt(ref["long"], ".3f"), fmt(ref["kanel"], ".3f"),
                         fmt(ref["rate"] and ref["rate"] / 1e5, ".2f"), "-",
                         fmt(ref["precursor"], ".0f"), fmt(ref["rise"], ".1f"), "-"])
    header = ["V (m/s)", "d (um)", "fracture", "elements", "run (s)", "1/2 rho0 c0 dU (GPa)",
              "1/2 rho0 c_L dU (GPa)", "Kanel (GPa)", "rate (1e5/s)", "rate law (GPa)",
              "precursor (m/s)", "rise 10-90 % (ns)",
              "spall depth (um)"]
    with open(os.path.join(HERE, "convergence.md"), "w") as f:
        f.write("# Aluminium plates against the element size (converge.py)\n\n")
        f.write("\n".join(table(header, rows)) + "\n")
    print(open(os.path.join(HERE, "convergence.md")).read())
    plot(results, sizes, fractures, opts.pyko)


def plot(results, sizes, fractures, pyko):
    """convergence.png: the free-surface records at each speed (the sizes, each fracture, the
    peer's), and the spall strength read against the strain rate beside the card's rate law."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, grid = plt.subplots(2, 3, figsize=(13.5, 8.0))
    axes = list(grid.flat)
    axes[-1].axis("off")
    styles = {"threshold": "--", "kinetics": "-", "pressure": ":"}
    for ax, v in zip(axes, SPEEDS):
        for f in fractures:
            for k, d in enumerate(sizes):
                record = np.loadtxt(os.path.join(RUNS, f"v{v}-d{d:g}-{f}", "run.visar"))
                ax.plot(record[:, 1] * 1e9, record[:, 2], styles[f], color=f"C{k}", lw=1,
                        label=f"{d:g} um, {f}")
        if pyko and os.path.exists(os.path.join(pyko, f"al{v}.visar")):
            data = np.loadtxt(os.path.join(pyko, f"al{v}.visar"))
            ax.plot(data[:, 0] * 1e9, data[:, 1], color="k", lw=1.2, label="pyKO, 1 um")
        ax.set_title(f"aluminium, {v} m/s")
        ax.set_xlabel("time (ns)")
        ax.set_xlim(30, 160)
        ax.set_ylabel("free-surface velocity (m/s)")
    axes[0].legend(fontsize=7)
    ax = axes[len(SPEEDS)]
    rates = np.logspace(4, 7, 50)
    ax.plot(rates, AL["spall"] * (rates / AL["spall_rate"]) ** AL["spall_m"] / 1e9, "k-",
            label="card: 1.2 GPa (rate / 1e5 /s)^0.2")
    for f, marker in (("threshold", "x"), ("kinetics", "o"), ("pressure", "s")):
        if f not in fractures:
            continue
        for k, d in enumerate(sizes):
            pts = [(results[(v, d, f)]["rate"], results[(v, d, f)]["kanel"]) for v in SPEEDS
                   if results[(v, d, f)]["spalled"] and results[(v, d, f)]["kanel"]]
            if pts:
                x, y = zip(*pts)
                ax.plot(x, y, marker, color=f"C{k}", label=f"{d:g} um, {f}")
    if pyko:
        pts = [(r["rate"], r["kanel"]) for r in (peer(pyko, v) for v in SPEEDS)
               if r and r["rate"] and r["kanel"]]
        if pts:
            x, y = zip(*pts)
            ax.plot(x, y, "k*", label="pyKO, 1 um (fracture at -1.2 GPa mean)")
    ax.set_xscale("log")
    ax.set_xlabel("strain rate of the release (1/s)")
    ax.set_ylabel("Kanel's sigma_sp from the record (GPa)")
    ax.set_title("spall strength against rate (spalled plates)")
    ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "convergence.png"), dpi=110)


if __name__ == "__main__":
    main()
