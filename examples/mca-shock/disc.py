#!/usr/bin/python3
"""A flyer disc on a wide target (in.disc: aluminium at 400 m/s, about 313,000 elements of
5 um) beside the plate impact of the same thicknesses (in.plate -var flyer 7 -var target 14):
the free face's velocity on the axis and at half the disc's radius against the plate's, with
the peak and Kanel's pull-back of each; the slab's frames (the velocity, then the elements'
damage: a spall of finite extent); the run's time and memory, and what a 10^6-element run
would take from the measured cost.  Writes disc.md and disc.png; runs in runs/disc (a finished
run is read again).

    source ../../build/env.sh; /usr/bin/python3 disc.py [--v 400] [--ranks 2]
"""
import argparse
import math
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
from run_shock import METALS  # noqa: E402
from runner import keep, lmp_command, loops  # noqa: E402
from shock_records import spall_strength  # noqa: E402

RUNS = os.path.join(HERE, "runs", "disc")
D = 5.0e-6
CELL = D * math.sqrt(2.0)
FLYER, TARGET, RADIUS = 7, 14, 21    # fcc cells, in.disc's defaults


def memory(text):
    """LAMMPS's memory report of the run: the ranks' sum (MB)."""
    found = re.findall(r"Per MPI rank memory allocation \(min/avg/max\) = \S+ \| (\S+) \| \S+",
                       text)
    return float(found[-1])


def pair_time(text):
    """The Pair line of LAMMPS's timing breakdown (average seconds over the ranks)."""
    return float(re.findall(r"^Pair\s+\|\s+\S+\s+\|\s+(\S+)", text, re.M)[-1])


def run_disc(v, ranks):
    var = {"metal": "al", "v": v, "here": HERE + "/", "out": "disc"}

    def make(workdir):
        out = lmp_command(os.path.join(HERE, "in.disc"), var, workdir, nprocs=ranks,
                          args=["-log", "log.lammps"])
        loop, _, steps, atoms = loops(out)[-1]
        return dict(loop=loop, steps=steps, atoms=atoms, ranks=ranks, memory=memory(out) * ranks,
                    pair=pair_time(out),
                    large=int(re.search(r"large fragments of the target: (\d+)", out).group(1)))
    workdir = os.path.join(RUNS, f"disc-v{v}-np{ranks}")
    return keep(workdir, make), workdir


def run_plate(v):
    var = {"metal": "al", "v": v, "here": HERE + "/", "out": "plate", "d": D, "flyer": FLYER,
           "target": TARGET, "records": 200}

    def make(workdir):
        out = lmp_command(os.path.join(HERE, "in.plate"), var, workdir)
        loop, _, steps, atoms = loops(out)[-1]
        return dict(loop=loop, steps=steps, atoms=atoms)
    workdir = os.path.join(RUNS, f"plate-v{v}")
    return keep(workdir, make), workdir


def frames(path):
    """The dump's frames: (step, columns id x y vx damage links as an array)."""
    out, lines = [], open(path).read().splitlines()
    k = 0
    while k < len(lines):
        step, n = int(lines[k + 1]), int(lines[k + 3])
        data = np.array([list(map(float, x.split())) for x in lines[k + 9:k + 9 + n]])
        out.append((step, data))
        k += 9 + n
    return out


def reading(t, u, v):
    """The peak and Kanel's pull-back (GPa) of a free-face record; None where refused."""
    m = METALS["al"]
    try:
        r = spall_strength(t, u, 2 * FLYER * CELL / m["c0"], m["rho"], m["cL"], m["c0"],
                           FLYER * CELL)
        return float(np.max(u)), r.sigma / 1e9
    except ValueError:
        return float(np.max(u)), None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--v", type=float, default=400.0)
    parser.add_argument("--ranks", type=int, default=2)
    args = parser.parse_args()
    disc, disc_dir = run_disc(args.v, args.ranks)
    plate, plate_dir = run_plate(args.v)
    rec = np.loadtxt(os.path.join(disc_dir, "disc.visar"))
    ref = np.loadtxt(os.path.join(plate_dir, "plate.visar"))
    readings = {"plate (1D, in.plate)": reading(ref[:, 1], ref[:, 2], args.v),
                "disc, on the axis": reading(rec[:, 1], rec[:, 2], args.v),
                "disc, at half the radius": reading(rec[:, 1], rec[:, 3], args.v)}
    shots = frames(os.path.join(disc_dir, "disc.slice"))
    log = open(os.path.join(disc_dir, "log.lammps")).read()
    dt = float(re.findall(r"dt ([0-9.e+-]+) s", log)[-1])
    per = disc["loop"] * disc["ranks"] / (disc["steps"] * disc["atoms"])    # core-s per element-step
    million = per * 1e6 * disc["steps"]                                     # core-seconds

    lines = [
        "# A flyer disc on a wide target (in.disc)", "",
        f"Aluminium at {args.v:g} m/s, elements of 5 um: a disc of radius {RADIUS * CELL * 1e6:.0f}"
        f" um and {FLYER * CELL * 1e6:.1f} um thick on a target {TARGET * CELL * 1e6:.0f} um thick"
        f" and {70 * CELL * 1e6:.0f} um wide; {disc['atoms']:,} elements, {disc['steps']} steps "
        f"of {dt:.3g} s on {disc['ranks']} MPI ranks of this 2-core machine.  Written by disc.py.",
        "",
        "| record | peak (m/s) | Kanel's pull-back (GPa) |", "|---|---|---|"]
    for name, (peak, kanel) in readings.items():
        lines.append(f"| {name} | {peak:.0f} | {'refused' if kanel is None else f'{kanel:.2f}'} |")
    lines += [
        "", f"- Run: {disc['loop']:.0f} s wall on {disc['ranks']} ranks, Pair {disc['pair']:.0f} s "
        f"(the ranks' average); {per * 1e6:.2f} us per element-step per core (the loop).",
        f"- Memory: {disc['memory']:.0f} MB (LAMMPS's report, the ranks' sum), "
        f"{disc['memory'] * 1048.576 / disc['atoms']:.2f} kB per element.",
        f"- The target after the run: {disc['large']} large fragments (compute dust; 2: a spall "
        "scab beside the target).",
        f"- A 10^6-element run of as many steps: {million / 3600:.1f} core-hours at this cost per "
        f"element-step, {disc['memory'] * 1e6 / disc['atoms'] / 1024:.1f} GB in all; on 16 "
        f"ranks (62,500 elements each, within the 20k-300k per rank measured here) about "
        f"{million / 16 / 60 / 0.85:.0f} min at the parallel efficiency of 2 ranks on the widest "
        "plate (0.85, bench/bench_mca_scale.sh); more ranks were not measured.",
        "", "![disc](disc.png)", ""]
    open(os.path.join(HERE, "disc.md"), "w").write("\n".join(lines))
    print("\n".join(lines))
    plot(shots, rec, ref, args.v, dt)


def plot(shots, rec, ref, v, dt):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = len(shots) - 1
    fig = plt.figure(figsize=(13, 8.5))
    grid = fig.add_gridspec(2, n, wspace=0.5, hspace=0.35)
    for k, (step, data) in enumerate(shots[1:]):
        ax = fig.add_subplot(grid[0, k])
        sc = ax.scatter(data[:, 1] * 1e6, data[:, 2] * 1e6, c=data[:, 3], s=0.4, cmap="viridis",
                        vmin=-0.1 * v, vmax=1.1 * v, rasterized=True)
        ax.set_title(f"t = {step * dt * 1e9:.1f} ns", fontsize=10)
        ax.set_xlabel("x (um)")
        ax.set_xticks([0, 75, 150])
        if k == 0:
            ax.set_ylabel("y (um)")
        ax.set_aspect("equal")
    fig.colorbar(sc, ax=fig.axes[:n], label="vx (m/s)", shrink=0.8)
    step, data = shots[-1]
    ax = fig.add_subplot(grid[1, :n // 2])
    sc = ax.scatter(data[:, 1] * 1e6, data[:, 2] * 1e6, c=data[:, 4], s=0.4, cmap="inferno",
                    vmin=0.0, vmax=1.0, rasterized=True)
    ax.set_title(f"damage of the spall kinetics, t = {step * dt * 1e9:.1f} ns", fontsize=10)
    ax.set_xlabel("x (um)")
    ax.set_xticks([0, 75, 150])
    ax.set_ylabel("y (um)")
    ax.set_aspect("equal")
    fig.colorbar(sc, ax=ax, label="D", pad=0.02)
    ax = fig.add_subplot(grid[1, n // 2:])
    ax.set_title("the free face's velocity", fontsize=10)
    ax.plot(ref[:, 1] * 1e9, ref[:, 2], "k-", label="plate (1D)")
    ax.plot(rec[:, 1] * 1e9, rec[:, 2], "C0-", label="disc, on the axis")
    ax.plot(rec[:, 1] * 1e9, rec[:, 3], "C1--", label="disc, at half the radius")
    ax.set_xlabel("t (ns)")
    ax.set_ylabel("free-face velocity (m/s)")
    ax.legend(fontsize=9)
    ax.grid(alpha=0.3)
    fig.savefig(os.path.join(HERE, "disc.png"), dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main()
