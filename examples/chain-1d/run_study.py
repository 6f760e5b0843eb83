#!/usr/bin/python3
"""The 1D chain study of the cluster-dynamics dusting paper (sections 2-5), on in.chain.

    source build/env.sh; /usr/bin/python3 examples/chain-1d/run_study.py [--quick]

Runs the scenes with the lammps Python module and writes, next to this file, results.md
(our numbers next to the paper's) and the PNG plots embedded in README.md.
"""
import argparse
import math
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import global_array, script  # noqa: E402

A, RC = 1.0e-5, 1.2


def run(**var):
    """Run in.chain with -var settings; return its results and time series."""
    start = time.time()
    with script(os.path.join(HERE, "in.chain"), var) as lmp:
        series = global_array(lmp, "series")
        work = global_array(lmp, "work")
        order = np.argsort(np.array(lmp.gather_atoms("id", 0, 1)))
        x = np.array(lmp.gather_atoms("x", 1, 3)).reshape(-1, 3)[order, 0]
        v = np.array(lmp.gather_atoms("v", 1, 3)).reshape(-1, 3)[order, 0]
        out = {"surface": lmp.extract_variable("surface"), "vfree": lmp.extract_variable("vfree"),
               "removed": lmp.extract_variable("removed"), "pchain": lmp.extract_variable("pchain"),
               "dt": lmp.extract_global("dt"), "c0": lmp.extract_variable("c0"),
               "e_end": lmp.get_thermo("pe") + lmp.get_thermo("ke"),
               "steps": lmp.extract_variable("steps"),
               "c_u": lmp.extract_compute("law", 0, 2)[0][3],      # c(u), T_min(u): the shock
               "tmin": lmp.extract_compute("law", 0, 2)[0][4]}     # table's row for u
    dt = out["dt"]
    out["work"] = np.trapz(work[:, 0], dx=dt)     # velocity Verlet: trapezoid rule
    cumulative = np.concatenate([[0.0], np.cumsum(0.5 * dt * (work[1:, 0] + work[:-1, 0]))])
    out["work_series"] = cumulative[::int(var.get("every", 50))]
    out["impulse"] = np.trapz(work[:, 1], dx=dt)
    out["series"], out["x"], out["v"], out["seconds"] = series, x, v, time.time() - start
    e0 = series[0, 21] + series[0, 22]
    out["balance"] = abs(e0 + out["work"] - out["e_end"] - out["removed"]) / out["work"]
    out["detached"] = detached(x, int(var.get("neighbours", 1)))
    return out


def detached(x, neighbours):
    """Clusters torn off the free surface: the chain splits at every gap that no interacting
    pair spans (the n-th neighbour interacts up to n Rc a); the body is the largest piece,
    and the clusters beyond its right end tore off."""
    n = len(x)
    cuts = [gap for gap in range(1, n)
            if not any(x[j] - x[i] < (j - i) * RC * A
                       for i in range(max(0, gap - neighbours), gap)
                       for j in range(gap, min(n, i + neighbours + 1)))]
    edges = [0] + cuts + [n]
    pieces = [(edges[k + 1] - edges[k], edges[k + 1]) for k in range(len(edges) - 1)]
    body_end = max(pieces)[1]
    return n - body_end


def plot_boundary(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, len(results), figsize=(5 * len(results), 7), sharex="col")
    for col, (title, r) in enumerate(results.items()):
        s = r["series"]
        t = s[:, 0] * 1e9
        for k in range(10):
            axes[0, col].plot(t, (s[:, 1 + k] - s[0, 1 + k]) * 1e6 + k * 10, lw=0.8)
            axes[1, col].plot(t, s[:, 11 + k], lw=0.8)
        axes[0, col].set_title(title)
        axes[0, col].set_ylabel("displacement + 10 k (um)")
        axes[1, col].set_ylabel("velocity (m/s)")
        axes[1, col].set_xlabel("time (ns)")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_relative(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(results), figsize=(5 * len(results), 3.5), sharey=True)
    for ax, (title, r) in zip(axes, results.items()):
        s = r["series"]
        for k in range(1, 10):
            ax.plot(s[:, 0] * 1e9, s[:, 11 + k] - s[:, 10 + k], lw=0.8)
        ax.set_title(title + ": v(k) - v(k-1)")
        ax.set_xlabel("time (ns)")
    axes[0].set_ylabel("relative velocity (m/s)")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_energy(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for title, r in results.items():
        s = r["series"]
        e0 = s[0, 21] + s[0, 22]
        ax.plot(s[:, 0] * 1e9, (s[:, 21] + s[:, 22] - e0) * 1e6, label=f"{title}: kinetic + potential")
        if r["removed"] > 0:
            ax.plot(s[:, 0] * 1e9, (s[:, 21] + s[:, 22] + s[:, 23] - e0) * 1e6, "--",
                    label=f"{title}: kinetic + potential + removed")
        ax.plot(s[:, 0] * 1e9, r["work_series"][:len(s)] * 1e6, ":", label=f"{title}: piston work")
    ax.set_xlabel("time (ns)")
    ax.set_ylabel("energy - initial energy (uJ)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def plot_onset(speeds, counts, ucr, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for law, ys in counts.items():
        ax.plot(speeds, ys, "o-", label=law)
    ax.axvline(ucr, color="k", ls="--", label=f"1D estimate u_cr = {ucr:.0f} m/s")
    ax.set_xlabel("piston speed u (m/s)")
    ax.set_ylabel("clusters torn off the free surface")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--quick", action="store_true", help="fewer onset speeds")
    args = ap.parse_args()
    start = time.time()
    rows, timing = [], []

    def scene(name, **var):
        r = run(**var)
        timing.append((name, r["seconds"]))
        return r

    # 1. Morse vs harmonic at u = 4000 m/s
    morse = scene("Morse u=4000", u=4000, law="morse")
    harm = scene("harmonic u=4000", u=4000, law="harmonic")
    rows.append(("Morse, u = 4000 m/s: clusters torn off", "at least the last ten", f"{morse['detached']}"))
    rows.append(("Harmonic, u = 4000 m/s: clusters torn off", "2, bonded to each other",
                 f"{harm['detached']}, " + ("bonded to each other" if harm["x"][-1] - harm["x"][-2] < RC * A
                                            else "apart")))

    # 2. Morse at u = 2000 m/s: no damping, absolute, relative
    plain = scene("Morse u=2000", u=2000)
    absolute = scene("absolute damping", u=2000, damp="absolute")
    relative = scene("relative damping", u=2000, damp="relative")
    for title, r, paper in (("no damping", plain, "dusting"),
                            ("absolute damping (fix viscous, J = 50)", absolute,
                             "no dust; free flight slowed unphysically"),
                            ("relative damping (fix viscous/relative, J = 50)", relative,
                             "no dust; free surface at about 2u")):
        rows.append((f"Morse, u = 2000 m/s, {title}: torn off; free-surface speed / 2u", paper,
                     f"{r['detached']}; {r['vfree'] / 4000:.3f}"))
    e0 = relative["series"][0, 21] + relative["series"][0, 22]
    balance = (e0 + relative["work"] - relative["e_end"] - relative["removed"]) / relative["work"]
    rows.append(("relative damping: (piston work + initial - kinetic - potential - removed) / work",
                 "balance holds to high accuracy", f"{balance:.2e}"))
    rows.append(("relative damping: chain momentum / piston impulse", "momentum conserved (damping adds none)",
                 f"{relative['pchain'] / relative['impulse']:.12f}"))

    # 3. onset of dusting against u
    speeds = [200, 300, 400, 500, 700, 1000, 1500, 2000, 3000, 4000]
    if args.quick:
        speeds = [300, 500, 1000, 4000]
    counts = {law: [scene(f"onset {law} u={u}", u=u, law=law)["detached"] for u in speeds]
              for law in ("morse", "harmonic")}
    ucr = (RC - 1) * plain["c0"] / (2 * math.sqrt(2))
    first = next((u for u, c in zip(speeds, counts["morse"]) if c > 0), None)
    rows.append(("Morse: lowest u with clusters torn off (scan)", f"1D estimate u/c0 > (Rc-1)/(2 sqrt 2): {ucr:.0f} m/s",
                 f"{first} m/s"))

    # 4. long-range chain, N = 5 neighbours per side, u = 2000 m/s
    longrange = scene("N = 5, u=2000", u=2000, neighbours=5)
    rows.append(("Morse, u = 2000 m/s, 5 neighbours per side: torn off (1 neighbour: "
                 f"{plain['detached']})", "dusting reduced but not removed", f"{longrange['detached']}"))

    with open(os.path.join(HERE, "results.md"), "w") as out:
        out.write("| quantity | paper | ours |\n|---|---|---|\n")
        for row in rows:
            out.write("| " + " | ".join(row) + " |\n")
        out.write("\n| scene | wall time (s) |\n|---|---|\n")
        for name, seconds in timing:
            out.write(f"| {name} | {seconds:.2f} |\n")
        out.write(f"| whole study | {time.time() - start:.1f} |\n")
    plot_boundary({"Morse, u = 4000 m/s": morse, "harmonic, u = 4000 m/s": harm,
                   "Morse, u = 2000 m/s, relative damping": relative},
                  os.path.join(HERE, "boundary.png"))
    plot_relative({"Morse, u = 4000 m/s": morse, "harmonic, u = 4000 m/s": harm},
                  os.path.join(HERE, "relative.png"))
    plot_energy({"relative damping": relative, "absolute damping": absolute},
                os.path.join(HERE, "energy.png"))
    plot_onset(speeds, counts, ucr, os.path.join(HERE, "onset.png"))
    print(open(os.path.join(HERE, "results.md")).read())


if __name__ == "__main__":
    main()
