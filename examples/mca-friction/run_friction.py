"""Dry friction of a block on a rough substrate by the contact segments of pair_style mca
(examples/mca-friction, two dimensions, units lj): in.friction run with the settings below.
Writes friction.md (the measured numbers) and friction.png:
  (a) Amontons: mu against sliding at two normal loads (stiff spring);
  (b) the friction force F(x) of a slow stiff-spring run and its critical stiffness
      K_c = max(-dF/dx) (Prandtl-Tomlinson);
  (c) stick-slip: the spring force against the drive distance for K = 0.3 K_c (a saw tooth)
      and 3 K_c (smooth, follows F(x)), and the block's speed;
  (d) the stick fraction (drive time with the block's speed below 0.05 V) for K / K_c in
      {0.3, 1, 3} at two drive speeds;
  (e) element size: mu for block elements of diameter 1 and 2 on a short-wave roughness;
  (f) the substrate's top row before and after sliding under a load that breaks its links.
And (not --quick) friction_runin.png, the running-in: three laps of the periodic substrate
(3 x 40 of sliding) at twice the damage scene's strength: mu against sliding with the laps'
boundaries, the top row's profile before, after the first and after the last lap.
And friction3d.png, the 3D alternative (in.friction3d: an fcc block on a flat counterface, a
large element or fix wall/gran): mu against sliding at two loads, a soft spring's drive.
Runs in temporary folders (nothing is kept); two runs at a time.
    /usr/bin/python3 run_friction.py            # about 70 s on two cores
    /usr/bin/python3 run_friction.py --quick --out /tmp/x   # reduced runs (the test's)"""
import argparse
import math
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
SPEED = 0.01       # the slow drive; the fast one is 10 times faster
TRANSIENT = 1.0    # drive distance left out of the means
STICK = 0.05       # the block sticks while its speed is below STICK * V
DT = 0.02
# Prandtl-Tomlinson scene: a short block (4 elements in contact) on a long wave only
PT_LOAD = 0.2
PT_WIDTH = 4
PT_WAVE = (0.3, 4.0, 8.0)           # A2, l2, d2 (d2 = 2 l2: one period a piece)
PT_ROUGH = "0 0.4 2 {} {} {} 4711".format(*PT_WAVE)
K_FACTORS = (0.3, 1.0, 3.0)
# element size: a short wave with the half-period of a diameter-1 element's contact
SIZE_ROUGH = "0.4 0.5 2 0 5 10 4711"
FLAT = "0 0.5 2 0 5 10 4711"
# 3D (in.friction3d): the two counterfaces, two loads, a soft spring
WALLS = {"large": "large element", "gran": "fix wall/gran"}
LOADS_3D = (0.2, 0.8)
SOFT_3D = 0.01
FLAT_VIEW = (-0.5, 7.0)   # panel (f): the surface region
DAMAGE_ROUGH = "0.35 0.4 2.0 0.25 5.0 15.0 4711"
# running-in: the damage scene's load and roughness, twice its strength, three laps of the
# periodic substrate (its length, 40)
LAP = 40.0
LAPS = 3
RUNIN_STRENGTH = 0.02
BLOCK_CENTRE = 10.0      # the 10-wide block's centre at the start (its elements at x 5 to 15)
AWAY = 8.0               # the profile away from the block: beyond its centre +- 8 (its dimple)


def steps_for(distance, speed=SPEED):
    return int(round(distance / speed / DT))


def pt_base(quick):
    slide = 12.0 if quick else 24.0
    return dict(P=PT_LOAD, K=1.0, V=SPEED, d=1, br=3, bw=PT_WIDTH, mu0=MU0, rough=PT_ROUGH,
                steps=steps_for(slide), every=50)


def stiff_scenes(quick):
    """The stiff-spring runs: F(x), K_c, Amontons, the energy balance."""
    base = pt_base(quick)
    return {"stiff, load 0.2": base, "stiff, load 0.05": dict(base, P=0.05)}


def drive_scenes(quick, kc):
    """Springs K = f K_c, slow and (not --quick) 10 times faster; the spring starts at
    0.65 mu0 P (below the smallest friction force: the block starts stuck)."""
    base = dict(pt_base(quick), zeta=0.3, pre=round(0.65 * MU0 * PT_LOAD, 6))
    out = {}
    for f in (K_FACTORS[0], K_FACTORS[-1]) if quick else K_FACTORS:
        out[f"K {f} K_c, V {SPEED}"] = dict(base, K=round(f * kc, 6))
        if not quick:
            out[f"K {f} K_c, V {10 * SPEED}"] = dict(base, K=round(f * kc, 6), V=10 * SPEED,
                                                     steps=base["steps"] // 10)
    return out


def other_scenes(quick):
    slide = 4.0 if quick else 8.0
    base = dict(P=0.05, K=1.0, V=SPEED, d=1, br=3, mu0=MU0, rough=SIZE_ROUGH,
                steps=steps_for(slide), every=50)
    return {
        "size: diameter 1": base,
        "size: diameter 2": dict(base, d=2, br=2),
        "size: no roughness": dict(base, rough=FLAT),
        "damage": dict(base, P=0.5, strength=0.01, profile=1, rough=DAMAGE_ROUGH,
                       steps=steps_for(2.0 if quick else 12.0)),
    }


def runin_scene():
    """The running-in (full run only, its longest scene): the damage scene at twice its
    strength for LAPS laps, the substrate's elements dumped at the start of the drag and after each lap."""
    return {"running-in": dict(P=0.5, K=1.0, V=SPEED, d=1, br=3, mu0=MU0, rough=DAMAGE_ROUGH,
                               strength=RUNIN_STRENGTH, steps=LAPS * steps_for(LAP),
                               pdump=steps_for(LAP), every=100)}


def scenes_3d(quick):
    """The 3D counterfaces: a stiff spring at two loads (Amontons) and (not --quick) a soft one
    starting at 0.65 mu0 P (stuck at first)."""
    base = dict(K=1.0, V=SPEED, steps=steps_for(2.0 if quick else 4.0), every=50)
    out = {}
    for wall in WALLS:
        for load in LOADS_3D:
            out[f"3D {wall}, load {load}"] = dict(base, wall=wall, P=load)
        if not quick:
            out[f"3D {wall}, soft K {SOFT_3D}"] = dict(
                base, wall=wall, P=LOADS_3D[0], K=SOFT_3D, pre=round(0.65 * MU0 * LOADS_3D[0], 6),
                steps=steps_for(6.0))
    return out


def run(item):
    """A scene of in.friction (see run_script)."""
    return run_script(item, "in.friction")


def run_3d(item):
    """A scene of in.friction3d (see run_script)."""
    return run_script(item, "in.friction3d")


def run_script(item, path):
    """One scene in a temporary folder: its drag rows, the substrate's elements before and
    after (profile scenes; "laps": the frames of profile.dump) and the wall time."""
    name, var = item
    with tempfile.TemporaryDirectory() as tmp:
        start = time.time()
        with script(os.path.join(HERE, path), var, tmp, "log.lammps"):
            pass
        wall = time.time() - start
        rows = drag_rows(thermo(os.path.join(tmp, "log.lammps")))
        dumps = {}
        for which in ("before", "after"):
            path = os.path.join(tmp, which + ".dump")
            if os.path.exists(path):
                dumps[which] = np.loadtxt(path, skiprows=9)
        path = os.path.join(tmp, "profile.dump")
        if os.path.exists(path):
            dumps["laps"] = dump_frames(path)
    return name, rows, dumps, wall


def dump_frames(path):
    """The frames of a dump of id x y: a list of arrays, each sorted by id."""
    frames = []
    for block in open(path).read().split("ITEM: TIMESTEP\n")[1:]:
        lines = block.splitlines()
        n = int(lines[2])
        a = np.array([[float(v) for v in line.split()] for line in lines[8:8 + n]])
        frames.append(a[np.argsort(a[:, 0])])
    return frames


def drag_rows(rows):
    """The drag run's rows (the second run: its step restarts at 0)."""
    restart = np.where(np.diff(rows[:, 0]) < 0)[0]
    return rows[restart[-1] + 1:] if len(restart) else rows


def col(rows, name):
    return rows[:, COLUMNS.index(name)]


def drive(rows):
    """The drive point's travel from the start of the drag."""
    return col(rows, "xd") - col(rows, "xd")[0]


def steady(rows):
    return rows[drive(rows) > TRANSIENT]


def speed(rows):
    """The block's speed (its centre's travel over the thermo interval)."""
    return np.gradient(col(rows, "xb"), col(rows, "time"))


def stick_fraction(rows, v_drive):
    s = drive(rows) > TRANSIENT
    return float(np.mean(np.abs(speed(rows)[s]) < STICK * v_drive))


def smoothed_force(rows, window=1.0):
    """F_fr against the block's position, averaged over `window` (the substrate's element
    spacing: the ripple of the loaded surface's dimples is left out) on a grid of 0.01."""
    s = steady(rows)
    xb, f = col(s, "xb"), col(s, "Ffr")
    order = np.argsort(xb)
    grid = np.arange(xb.min(), xb.max(), 0.01)
    fg = np.interp(grid, xb[order], f[order])
    n = int(round(window / 0.01))
    smooth = np.convolve(fg, np.ones(n) / n, mode="valid")
    return grid[n // 2:n // 2 + len(smooth)], smooth


def critical_stiffness(rows):
    """K_c = max(-dF/dx) of the smoothed F(x) of a stiff-spring run."""
    x, f = smoothed_force(rows)
    return float((-np.gradient(f, x)).max())


def closed_form_kc(load):
    """mu0 P A2_eff pi / l2: the long wave's mean amplitude A2 averaged over the block's
    PT_WIDTH contacts one apart and over a contact's length S = 1/sqrt(3)."""
    a2, l2, _ = PT_WAVE
    n = PT_WIDTH
    block = abs(math.sin(math.pi * n / (2 * l2)) / (n * math.sin(math.pi / (2 * l2))))
    u = math.pi / math.sqrt(3.0) / (2 * l2)
    a2_eff = a2 * block * math.sin(u) / u
    return MU0 * load * a2_eff * math.pi / l2, a2_eff


def measure(name, rows, v_drive=SPEED):
    s = steady(rows)
    mu, fs = col(s, "mu"), col(s, "fspring")
    return dict(name=name, FN=col(s, "FN").mean(), mu=mu.mean(), mu_sd=mu.std(),
                fs_mean=fs.mean(), fs_sd=fs.std(), fs_pp=fs.max() - fs.min(),
                slide=col(rows, "xb")[-1], wfr=col(rows, "wfr")[-1],
                work_path=np.trapz(col(rows, "Ffr"), col(rows, "xb")),
                work_drive=np.trapz(col(rows, "fspring"), col(rows, "xd")),
                broken=col(rows, "broken")[-1], stick=stick_fraction(rows, v_drive),
                vmax=np.abs(speed(rows)[drive(rows) > TRANSIENT]).max() / v_drive)


def measure_3d(name, rows, v_drive=SPEED):
    """measure() and the drive's work on the block, int f_spring dx_block, less the kinetic
    energy's change: the work the counterface's friction (and the block's damping) took."""
    m = measure(name, rows, v_drive)
    ke = col(rows, "ke")
    m["work_block"] = np.trapz(col(rows, "fspring"), col(rows, "xb")) - (ke[-1] - ke[0])
    return m


def simulate_3d(quick):
    """The 3D scenes: {name: rows}, their settings and the wall time of each."""
    settings = scenes_3d(quick)
    done = parallel(run_3d, list(settings.items()), jobs=2)
    return {name: rows for name, rows, _, _ in done}, settings, \
        {name: wall for name, _, _, wall in done}


def top_row(before, after):
    """The substrate's top row (the elements within 0.3 of the highest before sliding): x, y
    before and after, each sorted by x, and how many of them rose more than 0.5 (torn off)."""
    top = before[:, 2] > before[:, 2].max() - 0.3
    ids = before[top, 0]
    now = after[np.isin(after[:, 0], ids)]
    b = before[top][np.argsort(before[top, 1])]
    a = now[np.argsort(now[:, 1])]
    torn = int((a[:, 2] > b[:, 2].max() + 0.5).sum())
    risen = int((after[:, 2] > b[:, 2].max() + 0.5).sum())
    return (b[:, 1], b[:, 2]), (a[:, 1], a[:, 2]), torn, risen


def profile_stats(x, y, period):
    """A row of elements' profile over a periodic length: the rms height about its mean line
    and the mean |slope| between neighbours (sorted by x, wrapped)."""
    x = np.mod(x, period)
    order = np.argsort(x)
    x, y = x[order], y[order]
    dx = np.diff(np.r_[x, x[0] + period])
    dy = np.diff(np.r_[y, y[0]])
    return float(y.std()), float(np.mean(np.abs(dy / dx)))


def runin_laps(rows, frames, every):
    """Per lap (the drive's travel, the first lap from TRANSIENT): mean and sd of mu, mean F_N,
    the links broken and the friction work in the lap.  After it (frames every `every` steps),
    the top row (the elements within 0.3 of the highest at the start of the drag): how many of
    it and of the whole substrate have risen more than 0.5 above the start's top (torn off);
    of those in place away from the block (beyond its centre +- AWAY: its elastic dimple, which
    shifts with the spring's stretch, left out), the rms height about the mean line, the mean
    |slope| and the rms of their height change since the start.  Row 0: the start of the
    drag."""
    first = frames[0]
    top = first[:, 2] > first[:, 2].max() - 0.3
    ids, ymax = first[top, 0], first[top, 2].max()
    y0 = dict(zip(first[top, 0], first[top, 2]))
    laps = []
    d = drive(rows)
    step = col(rows, "step")
    for k, frame in enumerate(frames):
        row = frame[np.isin(frame[:, 0], ids)]
        row = row[row[:, 2] <= ymax + 0.5]
        centre = BLOCK_CENTRE + col(rows, "xb")[np.argmin(np.abs(step - k * every))]
        off = np.abs((row[:, 1] - centre + LAP / 2) % LAP - LAP / 2)
        away = row[off > AWAY]
        rms, slope = profile_stats(away[:, 1], away[:, 2], LAP) \
            if len(away) > 1 else (float("nan"), float("nan"))
        change = np.array([y - y0[i] for i, y in zip(away[:, 0], away[:, 2])])
        m = dict(lap=k, rms=rms, slope=slope, flown=len(ids) - len(row),
                 change=float(np.sqrt(np.mean(change ** 2))) if len(change) else float("nan"),
                 risen=int((frame[:, 2] > ymax + 0.5).sum()), x=row[:, 1] % LAP,
                 y=row[:, 2], centre=centre % LAP)
        if k > 0:
            s = (d > max((k - 1) * LAP, TRANSIENT)) & (d <= k * LAP)
            before = rows[d <= (k - 1) * LAP][-1]
            after = rows[s][-1]
            mu = col(rows[s], "mu")
            m.update(mu=mu.mean(), mu_sd=mu.std(), FN=col(rows[s], "FN").mean(),
                     broken=after[COLUMNS.index("broken")] - before[COLUMNS.index("broken")],
                     wfr=after[COLUMNS.index("wfr")] - before[COLUMNS.index("wfr")])
        laps.append(m)
    return laps


def simulate(quick):
    """All scenes: the stiff runs first (they give K_c), then the springs and the rest."""
    stiff = {name: (rows, wall) for name, rows, _, wall in
             parallel(run, list(stiff_scenes(quick).items()), jobs=2)}
    kc = critical_stiffness(stiff["stiff, load 0.2"][0])
    scenes = dict(drive_scenes(quick, kc), **other_scenes(quick))
    if not quick:
        scenes = dict(runin_scene(), **scenes)   # the longest first
    done = parallel(run, list(scenes.items()), jobs=2)
    results = {name: (rows, dumps, wall) for name, rows, dumps, wall in done}
    for name, (rows, wall) in stiff.items():
        results[name] = (rows, {}, wall)
    settings = dict(stiff_scenes(quick), **scenes)
    return results, settings, kc


def plot(results, settings, table, kc, path):
    fig, ax = plt.subplots(3, 2, figsize=(13, 12.5))
    a = ax[0, 0]
    for name in ("stiff, load 0.05", "stiff, load 0.2"):
        r = results[name][0]
        a.plot(col(r, "xb"), col(r, "mu"), lw=0.7,
               label=f"{name}: mean mu {table[name]['mu']:.4f}")
    a.axhline(MU0, color="k", ls=":", lw=0.8, label="mu0")
    a.set(xlabel="sliding distance of the block", ylabel="mu = F_fr / F_N",
          title=f"(a) Amontons: two loads, K = 1, long wave only, {PT_WIDTH} elements in contact")
    a.legend(fontsize=8)
    a = ax[0, 1]
    r = results["stiff, load 0.2"][0]
    x, f = smoothed_force(r)
    a.plot(col(r, "xb"), col(r, "Ffr"), lw=0.6, color="0.6", label="F_fr (stiff spring, V 0.01)")
    a.plot(x, f, lw=1.2, label="averaged over 1 (the substrate's spacing)")
    i = int(np.argmax(-np.gradient(f, x)))
    a.plot(x[i] + np.array([-1.5, 1.5]), f[i] - kc * np.array([-1.5, 1.5]), "k--", lw=0.8,
           label=f"max -dF/dx = K_c = {kc:.4f}")
    a.set(xlabel="block position x (from its start)", ylabel="friction force F(x)",
          title=f"(b) F(x), load {PT_LOAD}: A2 {PT_WAVE[0]}, l2 {PT_WAVE[1]}, d2 {PT_WAVE[2]}")
    a.legend(fontsize=8)
    a = ax[1, 0]
    a.plot(col(r, "xb"), col(r, "Ffr"), lw=0.6, color="0.7", label="F(x) (the stiff run)")
    for fct in (K_FACTORS[0], K_FACTORS[-1]):
        name = f"K {fct} K_c, V {SPEED}"
        rr = results[name][0]
        a.plot(drive(rr), col(rr, "fspring"), lw=1.0,
               label=f"spring force, K = {fct} K_c = {settings[name]['K']:.4g}: "
                     f"stick {table[name]['stick']:.2f}")
    a.set(xlabel="drive distance V t", ylabel="force",
          title=f"(c) stick-slip, V = {SPEED}: spring force against the drive")
    a.legend(fontsize=8)
    a = ax[1, 1]
    for fct in (K_FACTORS[0], K_FACTORS[-1]):
        name = f"K {fct} K_c, V {SPEED}"
        rr = results[name][0]
        a.plot(drive(rr), speed(rr) / SPEED, lw=0.8, label=f"K = {fct} K_c")
    a.axhline(STICK, color="k", ls=":", lw=0.8, label=f"{STICK} V (stuck below)")
    a.set(xlabel="drive distance V t", ylabel="block speed / V", title="(d) the block's speed")
    speeds = sorted({v["V"] for n, v in settings.items() if n.startswith("K ")})
    text = ["stick fraction", "K/K_c  " + "  ".join(f"V {v:g}" for v in speeds)]
    for fct in K_FACTORS:
        cells = [table.get(f"K {fct} K_c, V {v:g}") for v in speeds]
        if all(c is None for c in cells):
            continue
        text.append(f"{fct:<5g}  " + "  ".join("  --  " if c is None else f"{c['stick']:6.2f}"
                                              for c in cells))
    a.text(0.98, 0.97, "\n".join(text), transform=a.transAxes, ha="right", va="top",
           family="monospace", fontsize=8, bbox=dict(fc="w", ec="0.7"))
    a.legend(fontsize=8, loc="upper left")
    a = ax[2, 0]
    for name in ("size: diameter 1", "size: diameter 2", "size: no roughness"):
        rr = results[name][0]
        m = table[name]
        a.plot(col(rr, "xb"), col(rr, "mu"), lw=0.7,
               label=f"{name[6:]}: sd / mean {m['mu_sd'] / m['mu']:.3f}")
    a.set(xlabel="sliding distance of the block", ylabel="mu",
          title=f"(e) element size: roughness A1 l1 d1 = {' '.join(SIZE_ROUGH.split()[:3])}, "
                f"no long wave, load 0.05")
    a.legend(fontsize=8)
    a = ax[2, 1]
    dumps = results["damage"][1]
    (xb, yb), (xa, ya), torn, risen = top_row(dumps["before"], dumps["after"])
    a.plot(xb, yb, ".-", ms=3, lw=0.7, label="top row before (under the load)")
    a.plot(xa, ya, ".", ms=4, label="top row after")
    rest = dumps["after"]
    a.plot(rest[:, 1], rest[:, 2], ".", ms=1.5, color="0.6", label="all substrate elements after")
    away = int((rest[:, 2] > FLAT_VIEW[1]).sum())
    a.set(xlabel="x", ylabel="y", ylim=FLAT_VIEW,
          title=f"(f) load 0.5, sigma_c = 0.01: {table['damage']['broken']:.0f} links broken, "
                f"{risen} elements risen > 0.5,\n{away} of them torn off and flown above "
                f"y = {FLAT_VIEW[1]:g} (out of view)")
    a.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def plot_runin(rows, laps, path):
    """friction_runin.png: (a) mu against the block's sliding, the laps' boundaries and the
    mean of each lap; (b) the top row's profile at the start, after the first and after the
    last lap (the elements still in place, x over the substrate's period)."""
    fig, ax = plt.subplots(2, 1, figsize=(13, 9))
    a = ax[0]
    xb = col(rows, "xb")
    a.plot(xb, col(rows, "mu"), lw=0.4, color="0.6", label="mu = F_fr / F_N")
    x, f = smoothed_force(rows, window=LAP / 8)
    fn = col(steady(rows), "FN").mean()
    a.plot(x, f / fn, lw=1.2, label=f"F_fr averaged over {LAP / 8:g}, / mean F_N")
    for m in laps[1:]:
        k = m["lap"]
        a.axvline(k * LAP, color="k", ls=":", lw=0.8)
        a.plot([(k - 1) * LAP, k * LAP], [m["mu"]] * 2, "r-", lw=1.5)
        a.text((k - 0.5) * LAP, 0.02, f"lap {k}: mu {m['mu']:.3f} +- {m['mu_sd']:.3f}\n"
               f"{m['broken']:.0f} links broken, {m['flown']} of the top row torn off",
               ha="center", fontsize=8, bbox=dict(fc="w", ec="0.7"))
    a.axhline(MU0, color="k", lw=0.6, ls="--", label=f"mu0 = {MU0}")
    a.set(xlabel="sliding distance of the block (laps of the 40-long periodic substrate)",
          ylabel="mu", ylim=(0, 0.8),
          title=f"(a) running-in: load 0.5, sigma_c = {RUNIN_STRENGTH}, roughness "
                f"{DAMAGE_ROUGH}, K = 1, V = {SPEED}")
    a.legend(fontsize=8, loc="upper left")
    a = ax[1]
    for m in laps:
        o = np.argsort(m["x"])
        name = "start of the drag (loaded)" if m["lap"] == 0 else f"after lap {m['lap']}"
        if len(o) < 2:
            a.plot([], [], "o", mfc="none", label=f"{name}: {m['flown']} torn off, none in place")
            continue
        a.plot(m["x"][o], m["y"][o], ".-" if m["lap"] < 2 else "o", ms=3 + m["lap"], lw=0.7,
               mfc="none", label=f"{name}: {len(o)} in place; away from the block rms "
                                 f"{m['rms']:.4f}, mean |slope| {m['slope']:.4f}; rms change "
                                 f"{m['change']:.4f}")
    c = laps[0]["centre"]
    a.axvspan(c - AWAY, c + AWAY, color="0.9", zorder=0,
              label=f"the block's centre +- {AWAY:g} at each frame (its elastic dimple)")
    a.set(xlabel="x (over the substrate's period 40)", ylabel="y",
          title="(b) the substrate's top row (elements risen > 0.5 above it left out: torn off)")
    a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def report_runin(laps):
    lines = ["", "## Running-in (three laps of the periodic substrate)", "",
             f"The damage scene (load 0.5, roughness {DAMAGE_ROUGH}, K 1, V {SPEED}, bw 10) at "
             f"the substrate's strength {RUNIN_STRENGTH} for {LAPS} laps of its period "
             f"{LAP:g}.  Per lap of the drive (the first from {TRANSIENT}): mu, F_N, the links "
             f"broken and the friction work c_pw[6] in the lap; after it, the top row's rms "
             f"height about its mean line and mean |slope| between neighbours away from the "
             f"block (beyond its centre +- {AWAY:g}: its elastic dimple left out) and the rms "
             f"of these elements' height change since the start, over the elements still in "
             f"place; the top row's elements and all "
             f"substrate elements risen more than 0.5 above the start's top row (torn off).", "",
             "| after lap | mean mu | sd mu | F_N | links broken | friction work | top row rms "
             "(away) | mean slope (away) | rms change | top row torn off "
             "| substrate elements torn off |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for m in laps:
        cells = ["--"] * 5 if m["lap"] == 0 else [
            f"{m['mu']:.4f}", f"{m['mu_sd']:.4f}", f"{m['FN']:.4f}", f"{m['broken']:.0f}",
            f"{m['wfr']:.4f}"]
        lines.append(f"| {m['lap']} | " + " | ".join(cells) +
                     f" | {m['rms']:.4f} | {m['slope']:.4f} | {m['change']:.4f} | {m['flown']} "
                     f"| {m['risen']} |")
    return lines


def plot_3d(results, settings, table, flat_mu, path):
    """friction3d.png: (a) mu against sliding, two counterfaces at two loads; (b) the soft
    spring's force against the drive; (c) the block's speed."""
    soft = [n for n in settings if "soft" in n]
    fig, ax = plt.subplots(1, 3 if soft else 1, figsize=(18 if soft else 7, 5), squeeze=False)
    a = ax[0, 0]
    for name in settings:
        if "soft" in name:
            continue
        r = results[name]
        a.plot(col(r, "xb"), col(r, "mu"), lw=0.8,
               ls="-" if "large" in name else "--",
               label=f"{WALLS[settings[name]['wall']]}, load {settings[name]['P']}: "
                     f"mean mu {table[name]['mu']:.4f}")
    a.axhline(MU0, color="k", ls=":", lw=0.8, label=f"mu0 = {MU0}")
    if flat_mu is not None:
        a.axhline(flat_mu, color="0.5", lw=0.6, label=f"2D segments, no roughness: {flat_mu:.4f}")
    a.set(xlabel="sliding distance of the block", ylabel="mu = F_fr / F_N", ylim=(0.297, 0.3015),
          title="(a) 3D: fcc block (32 elements on the face) on a flat counterface, K = 1")
    a.legend(fontsize=8, loc="lower right")
    if soft:
        a, b = ax[0, 1], ax[0, 2]
        for name in soft:
            r = results[name]
            lab = WALLS[settings[name]["wall"]]
            a.plot(drive(r), col(r, "fspring"), lw=1.0, ls="-" if "large" in name else "--",
                   label=f"{lab}: spring force, stick {table[name]['stick']:.2f}")
            a.plot(drive(r), col(r, "Ffr"), lw=0.6, ls="-" if "large" in name else "--",
                   label=f"{lab}: F_fr")
            b.plot(drive(r), speed(r) / SPEED, lw=0.8, ls="-" if "large" in name else "--",
                   label=lab)
        p = settings[soft[0]]["P"]
        a.axhline(MU0 * p, color="k", ls=":", lw=0.8, label="mu0 P")
        a.set(xlabel="drive distance V t", ylabel="force",
              title=f"(b) soft spring K = {SOFT_3D}, V = {SPEED}, load {p}, starting at 0.65 mu0 P")
        a.legend(fontsize=8)
        b.axhline(STICK, color="k", ls=":", lw=0.8, label=f"{STICK} V (stuck below)")
        b.set(xlabel="drive distance V t", ylabel="block speed / V", title="(c) the block's speed")
        b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def report_3d(settings, table, walls, flat_mu):
    lines = ["", "## 3D: a flat counterface (in.friction3d)", "",
             f"An fcc block of 4 x 4 x 2 cells (128 elements of diameter 1, 32 on its (001) face) "
             f"on a large element (radius 1e4) or fix wall/gran (granular hooke, linear_history); "
             f"mu0 = {MU0}, no roughness.  Means beyond a drive of {TRANSIENT}.  Friction work "
             f"per distance: c_pw[6] (the pair's tally: the large element only), int F_fr "
             f"dx_block, and the drive's work on the block less the kinetic energy's change, each "
             f"over the block's slide.", "",
             "| scene | settings | F_N | mean mu | sd mu | mu / mu0 | stick fraction "
             "| block's top speed / V | slid | c_pw[6] / slide | int F_fr dx / slide "
             "| (drive - kinetic) / slide | wall time (s) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, m in table.items():
        v = settings[name]
        text = f"{WALLS[v['wall']]}, P {v['P']}, K {v['K']:.4g}, V {v['V']}" + \
            (f", pre {v['pre']}" if "pre" in v else "")
        s = m["slide"]
        lines.append(f"| {name} | {text} | {m['FN']:.4f} | {m['mu']:.5f} | {m['mu_sd']:.5f} "
                     f"| {m['mu'] / MU0:.5f} | {m['stick']:.3f} | {m['vmax']:.2f} | {s:.3f} "
                     f"| {m['wfr'] / s:.5f} | {m['work_path'] / s:.5f} "
                     f"| {m['work_block'] / s:.5f} | {walls[name]:.1f} |")
    lines.append("")
    for wall in WALLS:
        hi, lo = (table[f"3D {wall}, load {p}"]["mu"] for p in (LOADS_3D[1], LOADS_3D[0]))
        lines.append(f"Amontons ({WALLS[wall]}): mean mu at load {LOADS_3D[1]} / at load "
                     f"{LOADS_3D[0]} = {hi / lo:.5f}.")
    if flat_mu is not None:
        lines.append(f"2D segments without roughness (size: no roughness): mean mu {flat_mu:.4f}.")
    return lines


def report(results, settings, table, kc, total, quick):
    kc_closed, a2_eff = closed_form_kc(PT_LOAD)
    lines = ["# Measured (run_friction.py" + (" --quick" if quick else "") + ")", "",
             f"mu0 = {MU0}; means over the drive point's travel beyond {TRANSIENT}; the block "
             f"sticks while its speed is below {STICK} V; wall time {total:.0f} s on two cores.",
             "",
             "| scene | settings | F_N | mean mu | sd mu | spring force mean | sd | max - min "
             "| block's top speed / V | stick fraction | slid | friction work c_pw[6] "
             "| int F_fr dx_block | drive work | broken links |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name, m in table.items():
        v = settings[name]
        text = f"P {v['P']}, K {v['K']:.4g}, V {v['V']}, d {v['d']}, bw {v.get('bw', 10)}" + \
            (f", sigma_c {v['strength']}" if "strength" in v else "")
        lines.append(f"| {name} | {text} | {m['FN']:.4f} | {m['mu']:.4f} | {m['mu_sd']:.4f} "
                     f"| {m['fs_mean']:.5f} | {m['fs_sd']:.5f} | {m['fs_pp']:.5f} "
                     f"| {m['vmax']:.2f} | {m['stick']:.3f} | {m['slide']:.2f} | {m['wfr']:.5f} "
                     f"| {m['work_path']:.5f} | {m['work_drive']:.5f} | {m['broken']:.0f} |")
    amontons = table["stiff, load 0.2"]["mu"] / table["stiff, load 0.05"]["mu"]
    energy = table["stiff, load 0.2"]["wfr"] / table["stiff, load 0.2"]["work_path"]
    d1, d2, flat = (table[f"size: {k}"] for k in ("diameter 1", "diameter 2", "no roughness"))
    rel = [m["mu_sd"] / m["mu"] for m in (d1, d2, flat)]
    lines += ["",
              f"Amontons: mean mu at load 0.2 / at load 0.05 = {amontons:.4f}.",
              f"Energy: c_pw[6] / int F_fr dx_block (stiff, load 0.2) = {energy:.4f}.",
              f"K_c measured = max(-dF/dx) of F(x) averaged over 1 = {kc:.5f}; closed form "
              f"mu0 P A2_eff pi / l2 = {kc_closed:.5f} (A2_eff = {a2_eff:.4f}, the mean "
              f"amplitude; the pieces' amplitudes are drawn in [A2/2, 3A2/2]).",
              "Stick fraction: " + ", ".join(f"{n}: {table[n]['stick']:.3f}"
                                             for n in table if n.startswith("K ")) + ".",
              f"Element size: sd / mean of mu: diameter 1 {rel[0]:.4f}, diameter 2 {rel[1]:.4f} "
              f"(ratio {rel[1] / rel[0]:.3f}), no roughness {rel[2]:.4f}.",
              f"Damage: {table['damage']['torn']} elements of the top row and "
              f"{table['damage']['risen']} substrate elements in all risen more than 0.5 above "
              f"the top row."]
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="reduced runs (the test's)")
    parser.add_argument("--out", default=HERE,
                        help="folder for friction.md and friction.png (default: this one)")
    args = parser.parse_args()
    start = time.time()
    results, settings, kc = simulate(args.quick)
    table = {}
    for name in settings:
        table[name] = measure(name, results[name][0], settings[name]["V"])
    dumps = results["damage"][1]
    _, _, table["damage"]["torn"], table["damage"]["risen"] = top_row(dumps["before"],
                                                                      dumps["after"])
    results_3d, settings_3d, walls_3d = simulate_3d(args.quick)
    table_3d = {name: measure_3d(name, results_3d[name], settings_3d[name]["V"])
                for name in settings_3d}
    total = time.time() - start
    plot(results, settings, table, kc, os.path.join(args.out, "friction.png"))
    runin = []
    if "running-in" in results:
        rows, dumps, _ = results["running-in"]
        laps = runin_laps(rows, dumps["laps"], settings["running-in"]["pdump"])
        plot_runin(rows, laps, os.path.join(args.out, "friction_runin.png"))
        runin = report_runin(laps)
    flat_mu = table["size: no roughness"]["mu"]
    plot_3d(results_3d, settings_3d, table_3d, flat_mu, os.path.join(args.out, "friction3d.png"))
    lines = report(results, settings, table, kc, total, args.quick) + runin + \
        report_3d(settings_3d, table_3d, walls_3d, flat_mu)
    with open(os.path.join(args.out, "friction.md"), "w") as out:
        out.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
