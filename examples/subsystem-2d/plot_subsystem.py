"""Plots and tables of examples/subsystem-2d from the runs' tables: strip.png (stress-strain
and deflection of the clamped strip, Hooke's slope from the law, Euler's and Timoshenko's
buckling strains) and plate_faces.png (the end-face stresses of the Fig. 2 plate at each
resolution next to SfePy's solution for Poisson 0.3 and 1/3), upset.png and the ensemble
table of section 3.  Run after the inputs (README.md says how): it reads what they write, which
is not tracked: strip_load.dat, strip_unload.dat, strip_load.dat.dump (in.strip),
plate_faces_*.txt (in.plate), fe_faces_nu*.txt (plate_fe.py), upset-*.dat and upset-*.dump
(run_upset.sh); and upset_runs.txt (run_upset.sh; tracked)."""
import glob
import math
import os
import re
import sys

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


def dump_frames(path):
    """The frames of a LAMMPS text dump (write_dump ... append yes) as arrays of its columns."""
    frames = []
    for block in open(path).read().split("ITEM: TIMESTEP")[1:]:
        lines = block.strip().split("\n")
        n = int(lines[2])
        frames.append(np.array([row.split() for row in lines[-n:]], float))
    return frames


def critical_strain(load):
    """Buckling strain from the post-buckling branch: the mid-height deflection w of a strip
    past a symmetric bifurcation grows as w^2 ~ (eps - eps_cr); fitted where |w| > 1 a and
    no link has broken, on converged steps."""
    post = (np.abs(load[:, 2]) > 1.0) & (load[:, 3] == 0) & (load[:, 5] < 1e-6)   # converged
    post &= np.arange(len(load)) <= np.argmax(load[:, 0])
    slope, icept = np.polyfit(load[post, 0], load[post, 2] ** 2, 1)
    return -icept / slope, slope, post


def strip_plot():
    load = np.loadtxt(os.path.join(HERE, "strip_load.dat"))
    unload = np.loadtxt(os.path.join(HERE, "strip_unload.dat"))
    frames = dump_frames(os.path.join(HERE, "strip_load.dat.dump"))
    euler, timo = buckling_strains()
    eps_cr, slope_w2, post = critical_strain(load)
    first = int(np.argmax(load[:, 3] > 0))             # the first step with broken links
    fig = plt.figure(figsize=(13, 4.6))
    ax1, ax2, ax3 = (fig.add_subplot(1, 3, k) for k in (1, 2, 3))
    ax1.plot(100 * load[:, 0], load[:, 1], "o-", ms=4, label="loading to 7 %")
    turn = int(np.argmax(unload[:, 0])) + 1
    ax1.plot(100 * unload[turn - 1:, 0], unload[turn - 1:, 1], "s--", mfc="none",
             label="unloading from 5 %")
    eps = np.linspace(0, 0.04, 2)
    ax1.plot(100 * eps, E2D * eps, "k--", lw=0.8, label=f"Hooke, E = 2C/sqrt(3) = {E2D:.4f} D/a$^2$")
    top = load[:, 1].max()
    for e, name, y, c in ((timo, "Timoshenko", 0.05, "gray"), (eps_cr, "w$^2$ fit", 0.35, "C3"),
                          (euler, "Euler", 0.6, "gray")):
        ax1.axvline(100 * e, color=c, ls=":")
        ax1.text(100 * e, y * top, f" {name} {100 * e:.2f}%", fontsize=8, color=c)
    ax1.annotate(f"first links break\n({int(load[first, 3])} links)",
                 (100 * load[first, 0], load[first, 1]), (4.3, 0.15 * top), fontsize=8,
                 arrowprops=dict(arrowstyle="->"))
    ax1.set_xlabel("strain (%)")
    ax1.set_ylabel("stress (D/a$^2$, force per length)")
    ax1.legend(fontsize=7, loc="upper left")
    ax2.plot(100 * load[:, 0], np.abs(load[:, 2]), "o-", ms=4, label="loading")
    ax2.plot(100 * unload[turn - 1:, 0], np.abs(unload[turn - 1:, 2]), "s--", mfc="none",
             label="unloading")
    e = np.linspace(eps_cr, load[post, 0].max(), 50)
    ax2.plot(100 * e, np.sqrt(slope_w2 * (e - eps_cr)), "C3-", lw=0.8,
             label=f"|w| = sqrt(s (eps - {100 * eps_cr:.2f} %))")
    ax2.set_xlabel("strain (%)")
    ax2.set_ylabel("|mid-height lateral displacement| (a)")
    ax2.legend(fontsize=7)
    steps = [int(np.argmin(np.abs(load[:, 0] - s))) for s in (0.03, 0.045)] + [first - 1, first,
                                                                                len(load) - 1]
    links0 = frames[0][:, 3]
    for k, i in enumerate(steps):
        f = frames[i + 1]                                 # frame 0 is the start
        x = f[:, 1] - frames[0][:, 1].min() + 16 * k
        lost = f[:, 3] < links0
        ax3.scatter(x[~lost], f[~lost, 2], s=0.6, c="C0")
        ax3.scatter(x[lost], f[lost, 2], s=2, c="C3")
        ax3.text(x.min(), f[:, 2].max() + 2, f"{100 * load[i, 0]:.2f}%", fontsize=7)
    ax3.set_aspect("equal")
    ax3.set_xticks([])
    ax3.set_ylabel("y (a)")
    ax3.set_title("shapes (red: atoms that lost links)", fontsize=9)
    fig.suptitle(f"clamped strip {NX} x {NY} particles, Mie k = 0.25, link 1.05, "
                 "descent/normalized with inertia 20 0.99")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "strip.png"), dpi=110)
    e4, s4 = load[:8, 0], load[:8, 1]
    slope = (e4 @ s4) / (e4 @ e4)                        # through the origin, up to 2 %
    print(f"strip: Hooke slope {slope:.5f} D/a^2 against 2C/sqrt(3) = {E2D:.5f} "
          f"({slope / E2D - 1:+.2%}); buckling strain from the w^2 fit {100 * eps_cr:.2f} % "
          f"(Euler {100 * euler:.2f} %, Timoshenko {100 * timo:.2f} %); plateau stress / E "
          f"{100 * load[post, 1].mean() / E2D:.2f} %; first links break at "
          f"{100 * load[first, 0]:.2f} %; residual after unloading {unload[-1, 6]:.3g} a")


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


def upset_plot():
    """upset.png: the wall stress against the block's strain and the shapes of in.upset's runs."""
    def table(name):
        return np.loadtxt(os.path.join(HERE, f"{name}.dat"))

    fig, axes = plt.subplots(2, 4, figsize=(15, 7.5), height_ratios=(1.3, 1))
    small = (("upset-slow-6", "slow, h = 1e-4 a"), ("upset-fast-6", "fast, h = 1e-2 a"),
             ("upset-fast-6-inertia", "fast, h = 1e-2 a, inertia 10 0.5"))
    large = (("upset-slow", "slow, h = 1e-4 a"), ("upset-fast", "fast, h = 1e-2 a"),
             ("upset-fast-inertia", "fast, inertia 10 0.5"),
             ("upset-fast-slide", "fast, walls slide"))
    for name, label in small:
        d = table(name)
        axes[0, 0].plot(100 * d[:, 2], d[:, 3], ".-", lw=0.8, ms=3, label=label)
    axes[0, 0].set_title("to 6 %: load and unload", fontsize=9)
    for name, label in large:
        d = table(name)
        axes[0, 1].plot(100 * d[:, 2], d[:, 3], ".-", lw=0.8, ms=3, label=label)
        axes[0, 2].plot(100 * d[:, 2], d[:, 4], ".-", lw=0.8, ms=3, label=label)
    axes[0, 1].set_title("to 30 %: load and unload", fontsize=9)
    for ax in axes[0, :2]:
        ax.set_xlabel("strain of the block (%)")
        ax.set_ylabel("wall stress (D/a$^2$)")
        ax.legend(fontsize=7)
    axes[0, 2].set_xlabel("strain of the block (%)")
    axes[0, 2].set_ylabel("width at mid-height / initial")
    axes[0, 2].legend(fontsize=7)
    for k, (name, label) in enumerate(small[:2]):
        f = dump_frames(os.path.join(HERE, f"{name}.dump"))
        rows = np.round(f[0][:, 2] / (math.sqrt(3) / 2)).astype(int)
        edge = [np.flatnonzero(rows == r)[np.argmax(f[0][rows == r, 1])] for r in np.unique(rows)]
        for frame, style, when in ((f[1], "-", "6 %"), (f[2], "--", "unloaded")):
            axes[0, 3].plot(frame[edge, 1] - f[0][edge, 1], f[0][edge, 2], style, color=f"C{k}",
                            label=f"{label.split(',')[0]}, {when}")
    axes[0, 3].set_xlabel("lateral displacement of the right edge (a)")
    axes[0, 3].set_ylabel("initial height (a)")
    axes[0, 3].set_title("to 6 %: the free edge", fontsize=9)
    axes[0, 3].legend(fontsize=7)
    for ax, (name, label) in zip(axes[1], large):
        f = dump_frames(os.path.join(HERE, f"{name}.dump"))
        ax.scatter(f[0][:, 1], f[0][:, 2], s=1, c="0.8", label="start")
        ax.scatter(f[1][:, 1], f[1][:, 2], s=1, c="C0", label="30 %")
        ax.scatter(f[2][:, 1] + 30, f[2][:, 2], s=1, c="C1", label="unloaded (shifted)")
        ax.set_title(label, fontsize=9)
    axes[1, 0].legend(fontsize=7, markerscale=4, loc="upper right")
    for ax in axes[1]:
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
    fig.suptitle("upsetting between a substrate and a moving top wall, rebuilt subsystems, "
                 "constant h; slow: wall 1e-5 a per iteration, fast: 1e-3 a")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "upset.png"), dpi=100)
    for name, _ in small + large:
        d = table(name)
        print(f"{name}: residual strain {d[-1, 2]:.4f}, mid-height width {d[-1, 4]:.4f}, "
              f"largest displacement {d[-1, 7]:.3g} a, largest wall stress {d[:, 3].max():.4g}")


def upset_ensembles():
    """Markdown table of upset_runs.txt (run_upset.sh): mean and spread over seeds per case."""
    rows = {}
    pat = re.compile(r"upset (?:ensemble-)?(\S+) seed (\d+): residual strain (\S+), width at "
                     r"mid-height (\S+) W0, at the walls (\S+) / (\S+) W0, largest "
                     r"displacement (\S+) a, largest wall stress (\S+)")
    for line in open(os.path.join(HERE, "upset_runs.txt")):
        m = pat.match(line)
        if m:
            rows.setdefault(m[1], []).append([float(v) for v in m.groups()[2:]])
    print("| run | runs | residual strain (%) | width at mid-height | at the moving wall | "
          "largest wall stress (D/a^2) |")
    print("|---|---|---|---|---|---|")
    for name, values in rows.items():
        v = np.array(values)
        cell = lambda j, f=1.0, fmt=".3f": (f"{f * v[:, j].mean():{fmt}} +- {f * v[:, j].std(ddof=1):{fmt}}"
                                            if len(v) > 1 else f"{f * v[0, j]:{fmt}}")
        print(f"| {name} | {len(v)} | {cell(0, 100, '.2f')} | {cell(1)} | {cell(2)} | "
              f"{cell(5, 1.0, '.4f')} |")


NEEDS = {"in.strip (README.md)": ["strip_load.dat", "strip_unload.dat", "strip_load.dat.dump"],
         "in.plate (README.md)": ["plate_faces_*.txt"],
         "plate_fe.py": ["fe_faces_nu0.3.txt", "fe_faces_nu0.333.txt"],
         "run_upset.sh": [f"upset-{n}.{e}" for n in ("slow-6", "fast-6", "fast-6-inertia", "slow",
                                                     "fast", "fast-inertia", "fast-slide")
                          for e in ("dat", "dump")] + ["upset_runs.txt"]}


def missing_inputs():
    """The run outputs this script reads that are not there, by the run that writes them."""
    return {run: [n for n in names if not glob.glob(os.path.join(HERE, n))]
            for run, names in NEEDS.items()
            if any(not glob.glob(os.path.join(HERE, n)) for n in names)}


if __name__ == "__main__":
    missing = missing_inputs()
    if missing:
        sys.exit("plot_subsystem.py: run first (the outputs are not tracked):\n" +
                 "\n".join(f"  {run}: {', '.join(names)}" for run, names in missing.items()))
    strip_plot()
    plate_plot()
    upset_plot()
    upset_ensembles()
