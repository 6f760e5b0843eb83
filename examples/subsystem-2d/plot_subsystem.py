"""Plots and tables of examples/subsystem-2d from the runs' tables: strip.png (stress-strain
and deflection of the clamped strip, Hooke's slope from the law, Euler's and Timoshenko's
buckling strains) and plate_faces.png (the end-face stresses of the Fig. 2 plate at each
resolution next to SfePy's solution for Poisson 0.3 and 1/3).  Run after the inputs
(README.md says how)."""
import glob
import math
import os
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
D, A, N, M = 0.25, 1.0, 1.0, 0.5              # in.strip: Mie k = 0.25 in units lj
C = D * N * M / A ** 2                        # U''(a)
E2D = 2 * C / math.sqrt(3)                    # nearest-neighbour triangular lattice
NU = 1.0 / 3.0
NX, NY = 11, 116                              # in.strip's defaults
WIDTH = NX - 0.5                              # load-carrying width (bonds across)
LENGTH = (NY - 1) * math.sqrt(3) / 2          # between the clamped rows


def buckling_strains(h=WIDTH, length=LENGTH, e_over_g=2 * (1 + NU)):
    """Clamped-clamped Euler strain pi^2 h^2 / (3 L^2) and its Timoshenko shear correction."""
    euler = math.pi ** 2 * h ** 2 / (3 * length ** 2)
    return euler, euler / (1 + 1.2 * euler * e_over_g)


def strip_plot():
    load = np.loadtxt(os.path.join(HERE, "strip_load.dat"))
    unload = np.loadtxt(os.path.join(HERE, "strip_unload.dat"))
    euler, timo = buckling_strains()
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    ax1.plot(100 * load[:, 0], load[:, 1], "o-", label="descent/normalized (load, unload)")
    ax1.plot(100 * unload[:, 0], unload[:, 1], "s", mfc="none", label="no imperfection")
    eps = np.linspace(0, load[:, 0].max(), 2)
    ax1.plot(100 * eps, E2D * eps, "k--", label=f"Hooke, E = 2C/sqrt(3) = {E2D:.4f} D/a$^2$")
    top = load[:, 1].max()
    for e, name, y in ((euler, "Euler", 0.05), (timo, "Timoshenko", 0.2)):
        ax1.axvline(100 * e, color="gray", ls=":")
        ax1.text(100 * e, y * top, f" {name} {100 * e:.2f}%", fontsize=8, va="bottom")
    ax1.set_xlabel("strain (%)")
    ax1.set_ylabel("stress (D/a$^2$, force per length)")
    ax1.legend(fontsize=8)
    turn = int(np.argmax(load[:, 0])) + 1
    ax2.plot(100 * load[:turn, 0], load[:turn, 2], "o-", label="loading")
    ax2.plot(100 * load[turn - 1:, 0], load[turn - 1:, 2], "s--", mfc="none", label="unloading")
    ax2.plot(100 * unload[:, 0], unload[:, 2], "^:", label="no imperfection")
    ax2.legend(fontsize=8)
    ax2.set_xlabel("strain (%)")
    ax2.set_ylabel("mid-height lateral displacement (a)")
    fig.suptitle(f"clamped strip {NX} x {NY} particles, Mie k = 0.25, link 1.05")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "strip.png"), dpi=110)
    eps, sig = load[:4, 0], load[:4, 1]
    slope = (eps @ sig) / (eps @ eps)                  # through the origin
    print(f"strip: Hooke slope {slope:.5f} D/a^2 against 2C/sqrt(3) = {E2D:.5f} "
          f"({slope / E2D - 1:+.2%}); Euler {100 * euler:.2f} %, Timoshenko {100 * timo:.2f} %; "
          f"residual after unloading {unload[-1, 6]:.3g} a")


def plate_plot():
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    runs = sorted(glob.glob(os.path.join(HERE, "plate_faces_*.txt")),
                  key=lambda p: int(re.findall(r"_(\d+)\.txt", p)[0]))
    for path in runs:
        nx = int(re.findall(r"_(\d+)\.txt", path)[0])
        d = np.loadtxt(path, skiprows=9)          # id x y fx fy
        a = 0.010 / (nx - 0.5)
        ymid = 0.5 * (d[:, 2].min() + d[:, 2].max())
        for ax, face in zip(axes, (d[:, 2] < ymid, d[:, 2] > ymid)):
            x, fy = d[face, 1], d[face, 4]
            o = np.argsort(x)
            sign = -1 if ax is axes[0] else 1        # compression positive on both faces
            ax.plot(1e3 * (x[o] - x.min()), sign * fy[o] / a / 1e6, ".-", lw=0.8,
                    label=f"particles, {nx} across")
    for nu, style in ((0.3, "k-"), (1 / 3, "k--")):
        fe = np.loadtxt(os.path.join(HERE, f"fe_faces_nu{nu:.3g}.txt"))
        for ax, col in zip(axes, (1, 2)):
            ax.plot(fe[:, 0], fe[:, col], style, label=f"SfePy, nu = {nu:.3g}")
    for ax, name in zip(axes, ("lower (fixed) face", "upper (moving) face")):
        ax.axhline(1700, color="r", ls=":", label="1700 MPa (paper's line)")
        ax.set_title(name)
        ax.set_xlabel("x (mm)")
    axes[0].set_ylabel("normal stress on the face (MPa, compression)")
    axes[1].legend(fontsize=7)
    fig.suptitle("duralumin plate 10 x 100 mm, E = 72 GPa, 3 % upsetting, clamped faces")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "plate_faces.png"), dpi=110)


if __name__ == "__main__":
    strip_plot()
    plate_plot()
