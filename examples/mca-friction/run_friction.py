"""Dry friction of a block on a rough substrate by the contact segments of pair_style mca
(examples/mca-friction, two dimensions, units lj): in.friction run with the settings below.
Writes friction.md (the measured numbers) and friction.png: (a) mu against the sliding
distance at two normal loads (Amontons), (b) mu for block elements of diameter 1 and 2 on the
same roughness, (c) the drive spring's force for a soft and a stiff spring (stick-slip against
smooth sliding), (d) the substrate's top row before and after sliding under a load that
breaks its links.  Runs in a temporary folder (nothing is kept); two runs at a time.
    /usr/bin/python3 run_friction.py            # about a minute on two cores
    /usr/bin/python3 run_friction.py --quick    # reduced runs (a few seconds): the test's"""
import argparse
import os
import sys
import tempfile
import time

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import parallel, script, thermo  # noqa: E402

COLUMNS = ["step", "time", "xd", "xb", "Ffr", "FN", "mu", "fspring", "wfr", "broken", "pe", "ke"]
MU0 = 0.3
SPEED = 0.01
TRANSIENT = 1.0    # sliding distance of the drive point left out of the means


def scenes(quick):
    """name: in.friction's settings."""
    steps = 10000 if quick else 100000
    base = dict(P=0.05, K=1.0, V=SPEED, d=1, br=3, mu0=MU0, steps=steps, every=50)
    return {
        "load 0.05": base,
        "load 0.2": dict(base, P=0.2),
        "diameter 2": dict(base, d=2, br=2),
        "soft spring": dict(base, K=0.005, zeta=0.0, steps=2 * steps),
        "damage": dict(base, P=0.5, strength=0.01, profile=1, steps=max(10000, steps * 3 // 10)),
    }


def run(item):
    """One scene in a temporary folder: its thermo rows, the substrate's elements before and
    after (profile scenes) and the wall time."""
    name, var = item
    with tempfile.TemporaryDirectory() as tmp:
        start = time.time()
        with script(os.path.join(HERE, "in.friction"), var, tmp, "log.lammps"):
            pass
        wall = time.time() - start
        rows = thermo(os.path.join(tmp, "log.lammps"))
        dumps = {}
        for which in ("before", "after"):
            path = os.path.join(tmp, which + ".dump")
            if os.path.exists(path):
                dumps[which] = np.loadtxt(path, skiprows=9)
    return name, rows, dumps, wall


def drag_rows(rows):
    """The drag run's rows (the second run: its step restarts at 0)."""
    restart = np.where(np.diff(rows[:, 0]) < 0)[0]
    return rows[restart[-1] + 1:] if len(restart) else rows


def col(rows, name):
    return rows[:, COLUMNS.index(name)]


def steady(rows):
    return rows[col(rows, "xd") > TRANSIENT]


def top_row(before, after):
    """The substrate's top row (the elements within 0.3 of the highest before sliding): x, y
    before and after, each sorted by x, and how many of them rose more than 0.5 (torn off)."""
    top = before[:, 2] > before[:, 2].max() - 0.3
    ids = before[top, 0]
    now = after[np.isin(after[:, 0], ids)]
    b = before[top][np.argsort(before[top, 1])]
    a = now[np.argsort(now[:, 1])]
    torn = int((a[:, 2] > b[:, 2].max() + 0.5).sum())
    return (b[:, 1], b[:, 2]), (a[:, 1], a[:, 2]), torn


def measure(name, rows):
    s = steady(rows)
    mu, fs, xb = col(s, "mu"), col(s, "fspring"), col(s, "xb")
    whole = rows
    work_path = np.trapz(col(whole, "Ffr"), col(whole, "xb"))
    work_drive = np.trapz(col(whole, "fspring"), col(whole, "xd"))
    return dict(name=name, FN=col(s, "FN").mean(), mu=mu.mean(), mu_sd=mu.std(),
                fs_mean=fs.mean(), fs_sd=fs.std(), fs_pp=fs.max() - fs.min(),
                slide=col(rows, "xb")[-1], wfr=col(rows, "wfr")[-1], work_path=work_path,
                work_drive=work_drive, broken=col(rows, "broken")[-1],
                vmax=np.abs(np.diff(xb) / np.diff(col(s, "time"))).max() / SPEED)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="reduced runs (a few seconds)")
    args = parser.parse_args()
    start = time.time()
    done = parallel(run, list(scenes(args.quick).items()), jobs=2)
    results = {name: (drag_rows(rows), dumps, wall) for name, rows, dumps, wall in done}
    table = {name: measure(name, r[0]) for name, r in results.items()}
    total = time.time() - start

    fig, ax = plt.subplots(2, 2, figsize=(12, 8.5))
    a = ax[0, 0]
    for name in ("load 0.05", "load 0.2"):
        r = results[name][0]
        a.plot(col(r, "xb"), col(r, "mu"), lw=0.7,
               label=f"{name}: mean mu {table[name]['mu']:.4f}")
    a.axhline(MU0, color="k", ls=":", lw=0.8, label="mu0")
    a.set(xlabel="sliding distance of the block", ylabel="mu = F_fr / F_N",
          title="(a) Amontons: two normal loads, stiff spring")
    a.legend(fontsize=8)
    a = ax[0, 1]
    for name in ("load 0.05", "diameter 2"):
        r = results[name][0]
        label = "diameter 1" if name == "load 0.05" else name
        a.plot(col(r, "xb"), col(r, "mu"), lw=0.7,
               label=f"block elements of {label}: sd {table[name]['mu_sd']:.4f}")
    a.set(xlabel="sliding distance of the block", ylabel="mu",
          title="(b) element size: the same roughness, load 0.05")
    a.legend(fontsize=8)
    a = ax[1, 0]
    for name in ("soft spring", "load 0.05"):
        r = results[name][0]
        k = scenes(args.quick)[name]["K"]
        a.plot(col(r, "time"), col(r, "fspring"), lw=0.7, label=f"spring K = {k}, dashpot zeta = {scenes(args.quick)[name].get('zeta', 0.3)}")
    a.set(xlabel="time", ylabel="drive spring force",
          title=f"(c) stick-slip: soft against stiff spring, V = {SPEED}, load 0.05")
    a.legend(fontsize=8)
    a = ax[1, 1]
    dumps = results["damage"][1]
    (xb, yb), (xa, ya), torn = top_row(dumps["before"], dumps["after"])
    a.plot(xb, yb, ".-", ms=3, lw=0.7, label="before (under the load)")
    a.plot(xa, ya, ".-", ms=3, lw=0.7, label="after")
    a.set(xlabel="x", ylabel="y of the substrate's top row elements",
          title=f"(d) load 0.5, sigma_c = 0.01: {table['damage']['broken']:.0f} links broken, "
                f"{torn} torn off")
    table["damage"]["torn"] = torn
    a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "friction.png"), dpi=110)

    lines = ["# Measured (run_friction.py" + (" --quick" if args.quick else "") + ")", "",
             f"mu0 = {MU0}, drive speed {SPEED}, means over the drive point's sliding beyond "
             f"{TRANSIENT}; wall time {total:.0f} s on two cores.", "",
             "| scene | settings | F_N | mean mu | sd mu | spring force mean | sd | max - min "
             "| block's top speed / V | slid | friction work c_pw[6] | int F_fr dx_block "
             "| drive work | broken links |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, m in table.items():
        v = scenes(args.quick)[name]
        settings = f"P {v['P']}, K {v['K']}, d {v['d']}" + \
            (f", sigma_c {v['strength']}" if "strength" in v else "")
        lines.append(f"| {name} | {settings} | {m['FN']:.4f} | {m['mu']:.4f} | {m['mu_sd']:.4f} "
                     f"| {m['fs_mean']:.5f} | {m['fs_sd']:.5f} | {m['fs_pp']:.5f} "
                     f"| {m['vmax']:.2f} | {m['slide']:.2f} | {m['wfr']:.5f} "
                     f"| {m['work_path']:.5f} | {m['work_drive']:.5f} | {m['broken']:.0f} |")
    r = table["load 0.2"]["mu"] / table["load 0.05"]["mu"]
    lines += ["", f"Amontons: mean mu at load 0.2 / at load 0.05 = {r:.4f}.",
              f"Element size: sd of mu, diameter 2 / diameter 1 = "
              f"{table['diameter 2']['mu_sd'] / table['load 0.05']['mu_sd']:.3f}.",
              f"Stick-slip: spring force max - min, soft / stiff = "
              f"{table['soft spring']['fs_pp'] / table['load 0.05']['fs_pp']:.2f}.",
              f"Damage: {table['damage']['torn']} elements of the top row torn off (risen more "
              f"than 0.5 above it)."]
    with open(os.path.join(HERE, "friction.md"), "w") as out:
        out.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
