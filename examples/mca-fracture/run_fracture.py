"""Movable cellular automata in fracture (examples/mca-fracture): the tension bar (fcc and
three random packings) and the Brazilian disc.  Writes fracture.md (the table) and
fracture.png (stress-strain curves, the bar's fragments, the disc's load-approach curve and
its crack).  About 6 minutes on one core; runs in runs/ (one folder per run: a finished
run is read again; delete the folder to run it again)."""
import os
import shutil
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import finished, mean_sd, script, thermo, wall_time  # noqa: E402

STRENGTH = 0.01
SEEDS = [1, 2, 3]


def frames(path):
    """The frames of a text dump: [(step, columns dict)]."""
    out, blocks = [], open(path).read().split("ITEM: TIMESTEP\n")[1:]
    for block in blocks:
        lines = block.splitlines()
        names = lines[7].split()[2:]
        data = np.array([[float(v) for v in line.split()] for line in lines[8:]])
        out.append((int(lines[0]), {k: data[:, i] for i, k in enumerate(names)}))
    return out


def run(name, inp, **var):
    """Run an input in runs/<name> (kept: a finished run is read again, not repeated); its
    folder, LAMMPS's wall time (s) and the disc's D and t from the log."""
    workdir = os.path.join(HERE, "runs", name)
    os.makedirs(workdir, exist_ok=True)
    log = os.path.join(workdir, "log.lammps")
    if not finished(log):
        shutil.copy(os.path.join(HERE, "..", "mca-elastic", "in.random"), workdir)    # in.bar's
        with script(os.path.join(HERE, inp), var, workdir, "log.lammps"):
            pass
    extra = {}
    for line in open(log):
        words = line.split()
        if words[:1] == ["variable"] and len(words) == 4 and words[1] in ("Deff", "t") \
                and words[2] == "equal" and words[3][0].isdigit():    # the substituted echo
            extra[words[1]] = float(words[3])
    return workdir, wall_time(log), extra


def bar(packing, seed, steps):
    workdir, wall, _ = run(f"bar-{packing}-{seed}", "in.bar", packing=packing, seed=seed,
                           steps=steps)
    th = thermo(os.path.join(workdir, "log.lammps"))
    last = open(os.path.join(workdir, "fragments.dump")).read().split("ITEM: ENTRIES")[-1]
    sizes = np.sort(np.array(last.split()[1:], dtype=float))[::-1]
    peak = th[:, 2].argmax()
    parted = np.where(th[:, 4] < 0.9 * sizes.sum())[0]    # the largest fragment below 90 %
    return dict(strain=th[:, 1], sigma=th[:, 2] / STRENGTH, peak=th[peak, 2] / STRENGTH,
                at=th[peak, 1], sizes=sizes, n=sizes.sum(), wall=wall,
                parted=th[parted[0], 1] if len(parted) else float("nan"),
                dump=frames(os.path.join(workdir, "bar.dump")), broken=th[-1, 3])


def parting(r):
    """The strain at which the bar parted in two, or the strain it reached unparted."""
    return f"{r['parted']:.4f}" if np.isfinite(r["parted"]) else f"not by {r['strain'][-1]:.3f}"


def disc():
    workdir, wall, extra = run("disc", "in.disc", steps=40000)
    th = thermo(os.path.join(workdir, "log.lammps"))
    peak = th[:, 2].argmax()
    first = np.where(th[:, 4] > 0)[0][0]
    return dict(approach=th[:, 1], P=th[:, 2], split=th[:, 3] / STRENGTH,
                peak=th[peak, 3] / STRENGTH, first=th[first, 3] / STRENGTH,
                step_peak=th[peak, 0], dump=frames(os.path.join(workdir, "disc.dump")),
                wall=wall, **extra)


def main():
    bars = {("fcc", 1): bar("fcc", 1, 40000)}
    for seed in SEEDS:
        bars[("random", seed)] = bar("random", seed, 100000)
    d = disc()

    fig, ax = plt.subplots(2, 2, figsize=(11, 8.5))
    a = ax[0, 0]
    for (packing, seed), r in bars.items():
        a.plot(r["strain"] * 100, r["sigma"], label=f"{packing}" + (f", seed {seed}"
                                                                    if packing == "random" else
                                                                    " [100]"))
    a.axhline(1.0, color="k", ls=":", lw=1)
    a.set_xlabel("strain between the grips (%)")
    a.set_ylabel("mean axial stress of the gauge / $\\sigma_c$")
    a.set_title("tension bars (n = 4, strain rate 1e-5)")
    a.legend(fontsize=8)
    a = ax[0, 1]
    step, f = bars[("fcc", 1)]["dump"][-1]
    ids, counts = np.unique(f["c_dust[1]"], return_counts=True)
    big = ids[np.argsort(counts)[::-1][:2]]
    colour = np.where(f["c_dust[1]"] == big[0], "tab:blue",
                      np.where(f["c_dust[1]"] == big[1], "tab:orange", "tab:red"))
    a.scatter(f["x"], f["z"], c=colour, s=18)
    a.set_aspect("equal")
    a.set_xlabel("x")
    a.set_ylabel("z")
    a.set_title(f"fcc bar at step {step}: the two large fragments, dust in red")
    a = ax[1, 0]
    a.plot(d["approach"], d["P"])
    a.set_xlabel("approach of the platens")
    a.set_ylabel("load P (force units)")
    b = a.twinx()
    b.set_ylim(np.array(a.get_ylim()) / d["P"].max() * d["peak"])
    b.set_ylabel("2P / ($\\pi$ D t $\\sigma_c$)")
    a.set_title("Brazilian disc (D = 20, fcc [111] layers)")
    a = ax[1, 1]
    after = [fr for fr in d["dump"] if fr[0] >= d["step_peak"] + 2000]
    step, f = (after or d["dump"])[0]
    first = d["dump"][0][1]
    order0 = np.argsort(first["id"])
    order = np.argsort(f["id"])
    lost = first["c_links[9]"][order0] - f["c_links[9]"][order]
    disc_el = f["type"][order] == 1
    x, y = f["x"][order], f["y"][order]
    a.scatter(x[~disc_el], y[~disc_el], c="0.6", s=6)
    a.scatter(x[disc_el], y[disc_el], c=np.minimum(lost[disc_el], 6), cmap="viridis_r", s=8,
              vmin=0, vmax=6)
    a.set_aspect("equal")
    a.set_title(f"disc at step {step}: links lost per element (dark: 6 or more)")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "fracture.png"), dpi=90)

    fcc = bars[("fcc", 1)]
    rand = [bars[("random", s)] for s in SEEDS]
    peaks = np.array([r["peak"] for r in rand])
    lines = ["| scene | peak / sigma_c | strain at the peak | strain at parting | two largest fragments (share of the elements) | broken links | wall time (s) |",
             "|---|---|---|---|---|---|---|",
             f"| bar, fcc [100], 4 x 4 x 16 cells ({int(fcc['n'])} elements) | {fcc['peak']:.3f} | "
             f"{fcc['at']:.4f} | {parting(fcc)} | {fcc['sizes'][0] / fcc['n']:.2f}, "
             f"{fcc['sizes'][1] / fcc['n']:.2f} | {int(fcc['broken'])} | {fcc['wall']:.0f} |"]
    for s, r in zip(SEEDS, rand):
        second = r["sizes"][1] / r["n"] if len(r["sizes"]) > 1 else 0.0
        lines.append(f"| bar, random packing, seed {s} ({int(r['n'])} elements) | {r['peak']:.3f} | "
                     f"{r['at']:.4f} | {parting(r)} | {r['sizes'][0] / r['n']:.2f}, {second:.2f} | "
                     f"{int(r['broken'])} | {r['wall']:.0f} |")
    parted = sum(np.isfinite(r["parted"]) for r in rand)
    lines.append(f"| bar, random packing, 3 seeds | {mean_sd(peaks, 3)} "
                 f"| | {parted} of {len(rand)} parted | | | |")
    lines.append(f"| Brazilian disc, D = {d['Deff']:.2f}, t = {d['t']:.3f}: 2 P_max / (pi D t) | "
                 f"{d['peak']:.3f} | | | first link broken at {d['first']:.3f} | | {d['wall']:.0f} |")
    with open(os.path.join(HERE, "fracture.md"), "w") as out:
        out.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
