"""Movable cellular automata (pair_style mca) against LAMMPS's bonded-particle models on an fcc
block: the Poisson's ratios each model reaches and the cost of a time step (bpm_compare.md).

    source ../../build/env.sh
    /usr/bin/python3 bpm_compare.py            # bpm_compare.md, about 40 s on 2 cores
    /usr/bin/python3 bpm_compare.py --quick    # one setting per model, short timing, < 30 s

Elastic constants (in.bpm_elastic, units lj, fcc with nearest-neighbour distance 1, elements of
diameter 1): a periodic block strained by 1e-4 along x, y, z in turn (run 0: on fcc the affine
state is an equilibrium).  The block along the cube axes gives C11 and C12, hence E and nu for
uniaxial stress along [100]; a block with z along [111] gives E and nu along [111] (for this
orientation the normal 3x3 block of C gives S33 exactly: a stress along a 3-fold axis makes no
shear strain); C44 follows from 1/E111 = S11 - 2 (S11 - S12 - S44/2) / 3.

  bond_style bpm/rotational: Kr = 1, Ks = ratio * Kr, Kt = Kb = 0.1 (force*distance; they do not
    enter the static moduli: a homogeneous strain rotates no element against its neighbours),
    thresholds 1e10 with break no, damping 0.
  bond_style bpm/spring: k = 1, without volume/factor, or with volume/factor yes and a_v = factor*k.
    The term a_v ([(V_i+V_j)/(V0_i+V0_j)]^(1/3) - r/r0), V_i = sum of the element's bond lengths
    cubed, adds -(2 sqrt(2)/3) a_v delta_ij delta_kl to C on fcc and a_v to the bond stiffness:
    C11 = sqrt2 (k + a_v/3), C12 = sqrt2 (k/2 - a_v/6), C44 = (k + a_v)/sqrt2; LAMMPS takes any
    a_v; the lattice is stable (C44 > 0, C11 > C12) for a_v > -k.
  pair_style mca: E = 1 and nu as given.

Cost (in.bpm_timing): the same fcc block (4 n^3 elements), run with `lmp -in` (1 MPI rank, 1
thread), LAMMPS's own timing breakdown, median of `repeats` runs.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import lmp_command, loops, script  # noqa: E402

STRAIN = 1.0e-4
NUS = (0.1, 0.2, 0.3, 0.4, 0.45)
RATIOS = (0.0, 0.25, 0.5, 1.0, 2.0)                       # bpm/rotational Ks/Kr
FACTORS = (None, -0.75, -0.5, -0.25, 0.0, 0.5, 1.0, 2.0, 3.0)  # bpm/spring a_v/k (None: off)
KBT = 0.1                                                  # bpm/rotational Kt = Kb
STYLES = ("mca", "rotational", "spring", "granular")
TOL = 0.02                                                 # "reaches nu" within this


# ---------------------------------------------------------------------- elastic constants

def stiffness(model, orient, n=None, **var):
    """Normal 3x3 block of the stiffness (C_ij = stress_i / strain_j, symmetrized) of the
    block with orientation '100' or '111'."""
    if n is None:
        n = 3 if orient == "100" else 4
    v = dict(model=model, orient=orient, n=n, strain=STRAIN, **var)
    with script(os.path.join(HERE, "in.bpm_elastic"), v) as lmp:
        c = np.array([[lmp.extract_variable(f"s_{d}_{k}{k}") for d in "xyz"] for k in "xyz"])
    return 0.5 * (c + c.T) / STRAIN


def moduli(c100, c111):
    """Cubic constants and uniaxial-stress moduli from the two blocks."""
    s100 = np.linalg.inv(c100)
    s111 = np.linalg.inv(c111)
    c11 = np.mean(np.diag(c100))
    c12 = np.mean([c100[0, 1], c100[0, 2], c100[1, 2]])
    s11 = (c11 + c12) / ((c11 - c12) * (c11 + 2 * c12))
    s12 = -c12 / ((c11 - c12) * (c11 + 2 * c12))
    e100 = np.mean(1.0 / np.diag(s100))
    nu100 = np.mean([-s100[k, j] / s100[k, k] for k in range(3) for j in range(3) if j != k])
    e111 = 1.0 / s111[2, 2]
    nu111 = -(s111[0, 2] + s111[1, 2]) / (2 * s111[2, 2])
    s44 = 3.0 * (1.0 / e111 - s11) + 2.0 * (s11 - s12)
    c44 = 1.0 / s44
    bulk = (c11 + 2 * c12) / 3.0
    mu_v = (c11 - c12 + 3 * c44) / 5.0                     # Voigt average
    nu_v = (3 * bulk - 2 * mu_v) / (2 * (3 * bulk + mu_v))
    return dict(c11=c11, c12=c12, c44=c44, zener=2 * c44 / (c11 - c12), e100=e100, nu100=nu100,
                e111=e111, nu111=nu111, nu_voigt=nu_v, aniso=e100 / e111)


def blocks(model, n=None, **var):
    """The normal stiffness blocks (c100, c111) of one model setting."""
    return stiffness(model, "100", n, **var), stiffness(model, "111", n, **var)


def moduli_mca(nu, n=None):
    """pair_style mca with E = 1 and Poisson's ratio nu."""
    return moduli(*blocks("mca", n, nu=nu))


def _rotational_var(ratio, kbt=KBT):
    return dict(ratio=ratio, kbt=kbt)


def _spring_var(factor):
    return dict(volume="no") if factor is None else dict(volume="yes", av=factor)


def moduli_bpm_rotational(ratio, kbt=KBT, n=None):
    """bond_style bpm/rotational with Kr = 1, Ks = ratio, Kt = Kb = kbt."""
    return moduli(*blocks("rotational", n, **_rotational_var(ratio, kbt)))


def moduli_bpm_spring(factor, n=None):
    """bond_style bpm/spring with k = 1; factor None: no volume/factor, else volume/factor yes
    with a_v = factor."""
    return moduli(*blocks("spring", n, **_spring_var(factor)))


BASE = {}


def linear_model(model):
    """The blocks at parameter 0 and their change per unit parameter (Ks/Kr or a_v/k): both
    models are linear in it (checked against the sweep in the report)."""
    if model not in BASE:
        var = _rotational_var if model == "rotational" else _spring_var
        b0 = blocks(model, **var(0.0))
        b1 = blocks(model, **var(1.0))
        BASE[model] = (b0, tuple(c1 - c0 for c0, c1 in zip(b0, b1)))
    return BASE[model]


def moduli_linear(model, p):
    """Moduli at parameter p from the linear model (p = inf: the slope alone)."""
    b0, d = linear_model(model)
    if np.isinf(p):
        return moduli(*d)
    return moduli(*(c0 + p * dc for c0, dc in zip(b0, d)))


LIMITS = {"rotational": (0.0, np.inf), "spring": (-1.0, np.inf)}   # Ks >= 0; a_v > -k


def match(model, target):
    """The parameter p (Ks/Kr or a_v/k) giving nu[100] = target, solved from the linear model
    (nu[100] = C12 / (C11 + C12) with C linear in p), clipped to the allowed range, then checked
    by a run at p."""
    (c0, _), (d, _) = linear_model(model)
    a11, a12 = np.mean(np.diag(c0)), c0[0, 1]
    b11, b12 = np.mean(np.diag(d)), d[0, 1]
    p = (target * (a11 + a12) - a12) / (b12 - target * (b11 + b12))
    lo = LIMITS[model][0]
    clipped = p < lo
    if clipped:
        p = lo if model == "rotational" else lo + 0.01
    m = moduli_bpm_rotational(p) if model == "rotational" else moduli_bpm_spring(p)
    return dict(param=p, clipped=clipped, reach=abs(m["nu100"] - target) <= TOL, **m)


# ---------------------------------------------------------------------- cost

ROWS = ("Pair", "Bond", "Neigh", "Comm", "Output", "Modify", "Other")


def timing_once(style, steps=1000, n=10):
    """One serial run of in.bpm_timing; LAMMPS's timing breakdown (seconds) and the loop time."""
    env = dict(os.environ, OMP_NUM_THREADS="1")
    env.pop("LAMMPS_PLUGIN_PATH", None)
    out = lmp_command("in.bpm_timing", {"style": style, "n": n, "steps": steps}, HERE, env=env)
    res = {k: 0.0 for k in ROWS}
    for k in ROWS:
        m = re.search(rf"^{k}\s*\|([^|]*)\|([^|]*)\|", out, re.M)
        if m:
            res[k] = float(m.group(2))                      # avg time
    res["loop"], res["procs"], res["steps"], res["atoms"] = loops(out)[0]
    res["version"] = re.search(r"^LAMMPS \((.*)\)", out, re.M).group(1)
    return res


def timing(style, steps=1000, n=10, repeats=3):
    """Median over `repeats` runs; times per element-step in microseconds."""
    runs = [timing_once(style, steps, n) for _ in range(repeats)]
    res = {k: statistics.median(r[k] for r in runs) for k in ROWS + ("loop",)}
    norm = 1e6 / (runs[0]["atoms"] * runs[0]["steps"])
    res.update(atoms=runs[0]["atoms"], steps=runs[0]["steps"], procs=runs[0]["procs"],
               version=runs[0]["version"], repeats=repeats,
               force_us=(res["Pair"] + res["Bond"]) * norm, loop_us=res["loop"] * norm,
               loops=[r["loop"] for r in runs])
    return res


def machine():
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        return re.search(r"Model name:\s*(.*)", out).group(1).strip()
    except Exception:                                       # noqa: BLE001
        return "unknown"


# ---------------------------------------------------------------------- report

def sweep(quick=False):
    rows = []
    for nu in ((0.3,) if quick else NUS):
        rows.append(("mca", f"nu input {nu}", moduli_mca(nu)))
    for r in ((0.5,) if quick else RATIOS):
        rows.append(("bpm/rotational", f"Ks/Kr = {r}", moduli_bpm_rotational(r)))
    for f in ((0.5,) if quick else FACTORS):
        name = "no volume/factor" if f is None else f"a_v/k = {f}"
        rows.append(("bpm/spring", name, moduli_bpm_spring(f)))
    return rows


def elastic_table(rows):
    lines = ["| model | parameter | C11 | C12 | C44 | C12/C44 | Zener A | nu[100] | nu[111] | "
             "nu Voigt | E[100] | E[100]/E[111] |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for model, par, m in rows:
        lines.append(f"| {model} | {par} | {m['c11']:.4f} | {m['c12']:.4f} | {m['c44']:.4f} | "
                     f"{m['c12'] / m['c44']:.3f} | {m['zener']:.3f} | {m['nu100']:.4f} | "
                     f"{m['nu111']:.4f} | {m['nu_voigt']:.4f} | {m['e100']:.4f} | "
                     f"{m['aniso']:.4f} |")
    return "\n".join(lines) + "\n"


def ranges(rows):
    """Range of nu over the sweep and over the whole allowed parameter range (linear model)."""
    out = []
    for model in ("mca", "bpm/rotational", "bpm/spring"):
        ms = [m for mo, _, m in rows if mo == model]
        line = (f"- {model}: over the settings above nu[100] {min(m['nu100'] for m in ms):.3f} "
                f"to {max(m['nu100'] for m in ms):.3f}, nu[111] {min(m['nu111'] for m in ms):.3f} "
                f"to {max(m['nu111'] for m in ms):.3f}")
        if model == "mca":
            line += "; nu along any direction equals the input (E too)"
        else:
            key = model.split("/")[1]
            lo, hi = LIMITS[key]
            m_lo = moduli_linear(key, lo if key == "rotational" else lo + 1e-3)
            m_hi = moduli_linear(key, hi)
            pname = "Ks/Kr" if key == "rotational" else "a_v/k"
            line += (f"; over the whole allowed range {pname} {'>=' if key == 'rotational' else '>'}"
                     f" {lo:g}: nu[100] from {m_lo['nu100']:.3f} ({pname} = {lo:g}) to "
                     f"{m_hi['nu100']:.3f} ({pname} -> inf), nu[111] from {m_lo['nu111']:.3f} to "
                     f"{m_hi['nu111']:.3f}, nu Voigt from {m_lo['nu_voigt']:.3f} to "
                     f"{m_hi['nu_voigt']:.3f}")
        out.append(line)
    return "\n".join(out) + "\n"


def linearity(rows):
    """Largest difference between the sweep and the linear model (C11, C12, C44)."""
    err = 0.0
    for model, par, m in rows:
        if model == "mca" or "=" not in par:
            continue
        p = float(par.split("=")[1])
        ml = moduli_linear(model.split("/")[1], p)
        err = max(err, *(abs(m[k] - ml[k]) for k in ("c11", "c12", "c44")))
    return err


def _signed(x):
    return f"{round(x, 3) + 0.0:+.3f}"


def target_table(nus=NUS):
    lines = ["| target nu | model | parameter | nu[100] | reached (±0.02) | nu[111] | nu Voigt | "
             "E[111]/E[100] - 1 |", "|---|---|---|---|---|---|---|---|"]
    for nu in nus:
        for model, pname in (("rotational", "Ks/Kr"), ("spring", "a_v/k")):
            r = match(model, nu)
            par = f"{pname} = {r['param']:.4f}" + (" (limit)" if r["clipped"] else "")
            lines.append(f"| {nu} | bpm/{model} | {par} | {r['nu100']:.4f} | "
                         f"{'yes' if r['reach'] else 'no'} | {r['nu111']:.4f} | "
                         f"{r['nu_voigt']:.4f} | {_signed(1.0 / r['aniso'] - 1.0)} |")
        m = moduli_mca(nu)
        lines.append(f"| {nu} | mca | nu input {nu} | {m['nu100']:.4f} | "
                     f"{'yes' if abs(m['nu100'] - nu) <= TOL else 'no'} | {m['nu111']:.4f} | "
                     f"{m['nu_voigt']:.4f} | {_signed(1.0 / m['aniso'] - 1.0)} |")
    return "\n".join(lines) + "\n"


def timing_table(res):
    lines = ["| model | elements | steps | Pair s | Bond s | Neigh s | Comm s | Modify s | loop s | "
             "force µs/element-step | loop µs/element-step |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    names = {"mca": "pair mca (E 1, nu 0.3)",
             "rotational": "bond bpm/rotational (Ks/Kr 0.0769) + pair bpm/spring",
             "spring": "bond bpm/spring volume/factor (a_v/k 0.2308) + pair bpm/spring",
             "granular": "pair granular hertz/material + mindlin (no bonds)"}
    for style, r in res.items():
        lines.append(f"| {names[style]} | {r['atoms']} | {r['steps']} | {r['Pair']:.4g} | "
                     f"{r['Bond']:.4g} | {r['Neigh']:.4g} | {r['Comm']:.4g} | {r['Modify']:.4g} | "
                     f"{r['loop']:.4g} ({min(r['loops']):.3g}-{max(r['loops']):.3g}) | {r['force_us']:.3f} | "
                     f"{r['loop_us']:.3f} |")
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true",
                    help="one setting per model, timing of 100 steps on 4x4x4 (256 elements)")
    ap.add_argument("--output", default=None, help="markdown file (default: bpm_compare.md; "
                    "--quick writes none unless given)")
    args = ap.parse_args()
    quick = args.quick

    rows = sweep(quick)
    text = ["# pair_style mca against LAMMPS's bonded-particle models on fcc\n\n",
            "Written by bpm_compare.py.  Units lj, fcc with nearest-neighbour distance 1, "
            "unit-diameter elements.  Constants per unit normal bond stiffness for bpm "
            "(Kr = k = 1), per unit E for mca.  bpm/rotational: Kt = Kb = 0.1, damping 0, "
            "break no; bpm/spring: volume/factor yes with a_v = (a_v/k) k, or without.  "
            "[100] from a block along the cube axes (C11, C12), [111] from a block with z "
            "along [111]; C44 from 1/E[111] = S11 - 2 (S11 - S12 - S44/2)/3; nu Voigt is the "
            "Poisson's ratio of the Voigt-averaged isotropic solid.\n\n",
            "## Elastic constants and Poisson's ratios\n\n", elastic_table(rows),
            "\nRange of Poisson's ratio:\n\n", ranges(rows)]
    if not quick:
        kb = [moduli_bpm_rotational(0.5, kbt)["nu100"] for kbt in (0.0, 1.0)]
        text.append(f"\nChecks: bpm/rotational Ks/Kr = 0.5 with Kt = Kb = 0 and 1 gives nu[100] = "
                    f"{kb[0]:.4f} and {kb[1]:.4f} (Kt, Kb do not enter); the constants of both "
                    f"bpm models are linear in their parameter to {linearity(rows):.1e} (from "
                    f"the runs at 0 and 1).\n")
        text += ["\n## Matching a target nu along [100]\n\n",
                 "The parameter is solved from the constants (linear in it), limited to "
                 "Ks/Kr >= 0 (bpm/rotational) and a_v/k > -1 (bpm/spring: C44 > 0), then "
                 "run.  With the normal stiffness scaled so that E[100] equals the target E, "
                 "E along [111] is off by E[111]/E[100] - 1 (the largest deviation over "
                 "directions for a cubic solid).\n\n", target_table()]
    steps, n, repeats = (100, 4, 1) if quick else (1000, 10, 3)
    res = {s: timing(s, steps, n, repeats) for s in STYLES}
    version = next(iter(res.values()))["version"]
    text += [f"\n## Cost per element-step (serial: 1 MPI rank, 1 thread)\n\n"
             f"Machine: {machine()} (lscpu Model name), {os.cpu_count()} cores, other jobs "
             f"possibly running; LAMMPS {version}.  in.bpm_timing: fcc {n}x{n}x{n} block, "
             f"{steps} steps, timestep 0.01, neighbor 0.3 bin, neigh_modify every 1 delay 0 "
             f"check yes, velocity create T = 1e-6; mca E = 1, nu = 0.3; bpm parameters give "
             f"nu[100] = 0.3 (table above); granular: diameters 1.02 (overlap 0.02).  Seconds "
             f"are LAMMPS's timing breakdown (avg column), median of {repeats} runs; force = "
             f"Pair + Bond; loop s with the range over the runs.\n\n", timing_table(res)]
    out = "".join(text)
    print(out)
    path = args.output or (None if quick else os.path.join(HERE, "bpm_compare.md"))
    if path:
        with open(path, "w") as f:
            f.write(out)


if __name__ == "__main__":
    main()
