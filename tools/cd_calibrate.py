#!/usr/bin/python3
r"""Calibrate a cluster-dynamics pair law from macroscopic data and write a potentials/
parameter set (a *.cd include file) in the LAMMPS unit style named by --units.

    tools/cd_calibrate.py --density 2700 --sound-speed 6420 --spall-speed 1500 \
        --size 1e-5 --lattice fcc --law morse --name al-10um > potentials/al-10um.cd

The data are always SI (kg/m^3, m/s, m); --units (default si) names the unit style of the
numbers written: si, cgs, real, metal, electron, micro, nano, or lj (reduced units in
which the cluster size a, the cluster mass m and the bond depth D are 1).
Method: Krivtsov & Krivtsova (2002), section 8; doc/compute_pair_params.rst.

Relations, for a close-packed lattice of dimension d (chain 1, tri 2, fcc 3) with
nearest-neighbour interaction: cell volume V0 = sqrt(5 - d)/2 a^d, particle mass
m = density x V0; long-wave speed v0 = v_l / lambda (lambda = 1, 1.06, 1.10);
stiffness C = m (v0/a)^2; the spall (minimum impactor) speed is close to the dissociation
speed vd = sqrt(2D/m), so kv = v0 / v_spall and D = C a^2 / (2 kv^2).  Morse: alpha = kv/a;
LJ and Mie(n, m) reach kv through the kappa modification: kappa = kv / sqrt(n m / 2).

A metal's calibration (--hugoniot C0 S or --grueneisen G, --spall-strength, --orientation):

    tools/cd_calibrate.py --density 2700 --sound-speed 6420 --hugoniot 5350 1.34 \
        --spall-strength 1.2e9 --size 1e-5 --lattice fcc --up 200 > potentials/al.cd

matches the density, the Hugoniot us = c0 + s up of weak shocks along the impact (the law's
shape gives s, D gives c0) and the spall strength as the lattice's ideal tensile strength (the
cut Rc, written as pot_rc), by the lattice mechanics of tools/cd_uniaxial.py on chain, tri,
fcc, bcc (the first two shells bonded: nearest neighbours alone do not resist shear) or hcp
(--size is the nearest-neighbour distance a; on bcc the law's minimum r0 lies above it, where
the lattice is at zero pressure); it prints what it cannot match and the predictions
(doc/compute_pair_params.rst, doc/plate_impact.rst).
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cd_crystal  # noqa: E402
import cd_uniaxial  # noqa: E402
from cli_numbers import numbers_take_values  # noqa: E402

# Krivtsov's calibration: dimension and lambda = v_l / v0 of his close-packed lattices
LATTICES = {"chain": (1, 1.0), "tri": (2, 1.06), "fcc": (3, 1.10)}

# SI value of the unit of mass, length and energy of each LAMMPS unit style (LAMMPS's
# documentation of the units command; electron's velocities are Bohr/fs in LAMMPS's constants)
AVOGADRO = 6.02214076e23
UNITS = {
    "si": (1.0, 1.0, 1.0),
    "cgs": (1e-3, 1e-2, 1e-7),
    "real": (1e-3 / AVOGADRO, 1e-10, 4184.0 / AVOGADRO),
    "metal": (1e-3 / AVOGADRO, 1e-10, 1.602176634e-19),
    "electron": (1.66053906660e-27, 5.29177210903e-11, 4.3597447222071e-18),
    "micro": (1e-15, 1e-6, 1e-15),
    "nano": (1e-21, 1e-9, 1e-21),
}
# SI value of the unit of velocity and of pressure of each unit style (the units command's
# documentation: real A/fs and atm, metal A/ps and bar, electron Bohr/fs as LAMMPS's constants
# take it, micro um/us and pg/(um us^2), nano nm/ns and ag/(nm ns^2))
SPEED_PRESSURE = {
    "si": (1.0, 1.0), "cgs": (1e-2, 0.1), "real": (1e5, 101325.0), "metal": (100.0, 1e5),
    "electron": (5.29177210903e4, 1.0), "micro": (1.0, 1e3), "nano": (1.0, 1e6),
}


def in_units(p, units):
    """The parameter set p (SI, from calibrate()) with its numbers in the LAMMPS unit style
    units; lj: a, m and D are the units of length, mass and energy."""
    if units == "lj":
        mass, length, energy = p["m"], p["a"], p["D"]
    elif units in UNITS:
        mass, length, energy = UNITS[units]
    else:
        raise ValueError(f"unknown --units '{units}' (expected {', '.join(UNITS)} or lj)")
    d, a, m = p["D"] / energy, p["a"] / length, p["m"] / mass
    r0, b = p["r0"] / length, p["b"] / length
    law = p["law"]
    if law["name"] == "morse":
        coeff = f"{d!r} {p['kv'] / r0!r} {r0!r} kappa 1"
    elif law["name"] == "lj":
        coeff = f"{d!r} {r0!r} kappa {law['kappa']!r}"
    else:
        coeff = f"{d!r} {r0!r} {law['n']!r} {law['m']!r} kappa {law['kappa']!r}"
    speed, pressure = ((math.sqrt(p["D"] / p["m"]), p["D"] / p["a"] ** 3) if units == "lj" else
                       SPEED_PRESSURE[units])
    out = dict(p, coeff=coeff, m=m, a=a, r0=r0, b=b, D=d, units=units)
    if "c_impact" in p:
        out.update(c_impact_units=p["c_impact"] / speed, strength_units=p["strength"] / pressure)
    return out


OVERFLOW = ("--density, --size and the speeds together overflow double precision (check their "
            "units: kg/m^3, m, m/s)")


def calibrate(density, sound_speed, spall_speed, size, lattice, law="morse", n=12.0, m=6.0):
    """The parameter set as a dict; raises ValueError when the data admit no potential."""
    for name, value in (("--density", density), ("--sound-speed", sound_speed),
                        ("--spall-speed", spall_speed), ("--size", size)):
        positive(name, value)
    if lattice not in LATTICES:
        raise ValueError(f"--lattice {lattice}: Krivtsov's calibration (--spall-speed) knows "
                         "chain, tri and fcc; bcc and hcp take the metal calibration "
                         "(--hugoniot, --spall-strength)" if lattice in cd_crystal.LATTICES
                         else f"unknown --lattice '{lattice}' (expected chain, tri or fcc)")
    if law == "mie" and not (math.isfinite(n) and n > m > 0):
        raise ValueError(f"Mie exponents need finite --n > --m > 0 (got n = {n}, m = {m})")
    try:
        return finite(krivtsov(density, sound_speed, spall_speed, size, lattice, law, n, m),
                      ("m", "D", "C", "vd", "b"))
    except (OverflowError, ZeroDivisionError, FloatingPointError):
        raise ValueError(OVERFLOW) from None


def krivtsov(density, sound_speed, spall_speed, size, lattice, law, n, m):
    """calibrate()'s relations (Krivtsov & Krivtsova 2002, section 8)."""
    d, lam = LATTICES[lattice]
    mass = density * math.sqrt(5 - d) / 2 * size ** d
    v0 = sound_speed / lam
    kv = v0 / spall_speed
    if kv <= 1.0:
        raise ValueError(f"kv = v0 / v_spall = {kv:.4g} <= 1: a spall speed at or above the "
                         "long-wave sound speed admits no bonded solid")
    c = mass * (v0 / size) ** 2
    depth = c * size ** 2 / (2 * kv ** 2)
    if law == "morse":
        style, shape = "morse/spline", {"name": "morse"}
    elif law == "lj":
        style, shape = "lj/spline", {"name": "lj", "kappa": kv / 6.0}
    elif law == "mie":
        style, shape = "mie/spline", {"name": "mie", "n": n, "m": m, "kappa": kv / math.sqrt(n * m / 2)}
    else:
        raise ValueError(f"unknown --law '{law}' (expected morse, lj or mie)")
    p = {"style": style, "law": shape, "m": mass, "a": size, "r0": size, "D": depth, "C": c,
         "kv": kv, "v0": v0, "vd": math.sqrt(2 * depth / mass), "density": density}
    p.update(predictions(shape, kv, size))
    return in_units(p, "si")


SHAPE_RANGE = {"morse": (1.0, 60.0), "lj": (0.05, 20.0), "mie": (0.05, 20.0)}
# the unit of a stress (force per area, per length, force) in 3, 2 and 1 dimensions
STRESS_UNIT = {1: "N", 2: "N/m", 3: "Pa"}


def positive(name, value):
    """value, when a finite number > 0; else a ValueError naming the argument."""
    if not (isinstance(value, (int, float)) and value > 0 and math.isfinite(value)):
        raise ValueError(f"{name} must be a finite number > 0 (got {value})")
    return value


def finite(p, keys=("m", "D", "C", "rc", "vd", "ideal", "strength", "us")):
    """The set p, when every number in it is finite (extreme inputs overflow)."""
    bad = [k for k in keys if not math.isfinite(p[k]) or p[k] <= 0]
    if bad:
        raise ValueError(f"{OVERFLOW}: they give a non-finite or zero {', '.join(bad)}")
    return p


def calibrate_metal(density, c0, s, strength, size, lattice="fcc", orientation="100",
                    law="morse", n=12.0, m=6.0, up=None, sound_speed=None):
    """A set matched to a metal's density, Hugoniot us = c0 + s up and spall strength on the
    lattice strained along orientation: the law's shape gives s, D gives c0 (the lattice's
    longitudinal speed along the impact), the cut Rc the ideal tensile strength
    (cd_uniaxial.py).  Returns the set (SI) with its predictions; raises ValueError when the
    data admit no set."""
    for name, value in (("--density", density), ("--hugoniot C0", c0), ("--hugoniot S", s),
                        ("--spall-strength", strength), ("--size", size)):
        positive(name, value)
    up = positive("--up", up) if up is not None else 0.04 * c0
    if sound_speed is not None:
        positive("--sound-speed", sound_speed)
    if law not in SHAPE_RANGE:
        raise ValueError(f"unknown --law '{law}' (expected morse, lj or mie)")
    if law == "mie" and not (math.isfinite(n) and n > m > 0):
        raise ValueError(f"Mie exponents need finite --n > --m > 0 (got n = {n}, m = {m})")
    if lattice not in cd_crystal.LATTICES:
        raise ValueError(f"unknown --lattice '{lattice}' (expected "
                         f"{', '.join(cd_crystal.LATTICES)})")
    try:
        cd_crystal.crystal(lattice).direction(orientation)
    except ValueError as err:
        raise ValueError(f"--orientation: {err}") from None
    n, m = (12.0, 6.0) if law == "lj" else (n, m)
    base = cd_uniaxial.Law(law, 1.0, n, m)
    try:
        return finite(fit(density, c0, s, strength, size, lattice, orientation, base, up,
                          sound_speed))
    except (OverflowError, ZeroDivisionError, FloatingPointError):
        raise ValueError(OVERFLOW) from None


def bisect(f, lo, hi, target, steps):
    """x in [lo, hi] with f(x) = target, f increasing (a step function too)."""
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < target else (lo, mid)
    return 0.5 * (lo + hi)


def stable_shapes(lattice, orientation, base):
    """(lo, hi, limited): the law's shapes on which the balanced lattice is Born-stable, limited
    when hi is the stability limit (bcc: where C11 falls to C12); a ValueError when none is."""
    lo, hi = SHAPE_RANGE[base.name]
    why = lambda k: cd_uniaxial.Uniaxial.balanced(lattice, orientation,
                                                  base.with_shape(k)).unstable()
    first = why(lo)
    if first:
        raise ValueError(f"--lattice {lattice}: {base.name} is unstable on it even at shape "
                         f"{lo:g}: {first}")
    if not why(hi):
        return lo, hi, False
    return lo, bisect(lambda k: 1.0 if why(k) else 0.0, lo, hi, 0.5, 40) * (1 - 1e-9), True


def fit(density, c0, s, strength, size, lattice, orientation, base, up, sound_speed):
    """calibrate_metal's solution: shape for s (r0 at zero pressure), D for c0, Rc for the
    strength, on a Born-stable lattice."""
    law, where = base.name, f"{lattice} [{orientation}]"
    lo, hi, limited = stable_shapes(lattice, orientation, base)
    model = lambda k: cd_uniaxial.Uniaxial.balanced(lattice, orientation, base.with_shape(k))
    slope = lambda k: model(k).slope()
    if not max(slope(lo), 0.0) < s < slope(hi):
        limit = (f"; beyond {hi:.4g} the lattice is not Born-stable" if limited else "")
        raise ValueError(f"--hugoniot S = {s} is outside what {law} on {where} gives "
                         f"({max(slope(lo), 0.0):.3g} to {slope(hi):.3g}, shape {lo:g} to "
                         f"{hi:.4g}{limit})")
    shape = cd_uniaxial.solve(slope, lo, hi, s)
    if abs(slope(shape) - s) > 1e-6 * s:
        raise ValueError(f"--hugoniot S = {s}: {law} on {where} reaches only "
                         f"{slope(shape):.6g}")
    smooth = model(shape)
    why = smooth.unstable()
    if why:
        raise ValueError(f"--hugoniot S = {s} needs a {law} law on which {lattice} is "
                         f"unstable: {why}")
    r0 = smooth.law.r0
    crystal = smooth.crystal
    dim = crystal.dim
    mass = density * crystal.volume * size ** dim
    depth = mass * (c0 / smooth.speed()) ** 2
    unit_stress = depth / size ** dim
    if not all(0 < x < math.inf for x in (mass, depth, unit_stress)):
        raise OverflowError
    lattice_law = lambda rc: cd_uniaxial.Uniaxial(lattice, orientation,
                                                  base.with_shape(shape, rc, r0))
    cut = lambda rc: lattice_law(rc).strength() * unit_stress
    # the cut between the model's last shell and the next one, in units of r0; with two
    # shells bonded (bcc) at least SURFACE_MARGIN beyond the second: a free face relaxes them
    margin = SURFACE_MARGIN if crystal.model_shells > 1 else 1e-6
    rc_min = crystal.model_radius() / r0 * (1 + margin)
    rc_max = crystal.next_shell() / r0 * (1 - 1e-9)
    unit = STRESS_UNIT[dim]
    if not (rc_min < rc_max and cut(rc_min) < strength < cut(rc_max)):
        shells = ("the nearest and the second neighbours" if crystal.model_shells == 1 else
                  f"{100 * SURFACE_MARGIN:g} % beyond the second neighbours (a free face "
                  "relaxes them: closer, they cross the cut and the lattice falls apart at "
                  "rest) and the third")
        raise ValueError(f"--spall-strength {strength:.4g} is outside what a cut between "
                         f"{shells} gives on {where} ({cut(rc_min):.4g} to "
                         f"{cut(rc_max):.4g} {unit}: Rc = {rc_min:.4g} to {rc_max:.4g} r0)")
    rc = cd_uniaxial.solve(cut, rc_min, rc_max, strength, 1e-13)
    matched = lattice_law(rc)
    vunit = math.sqrt(depth / mass)
    shape_dict = ({"name": "morse"} if law == "morse" else
                  {"name": law, "n": base.n, "m": base.m, "kappa": shape})
    kv = shape if law == "morse" else shape * math.sqrt(base.n * base.m / 2)
    v0 = kv * math.sqrt(2 * depth / mass)          # the chain's long-wave speed r0 sqrt(C/m)
    try:
        us = matched.hugoniot(up / vunit) * vunit
    except ValueError:
        raise ValueError(f"--up {up:g} m/s compresses the lattice beyond half its length "
                         "(no cold Hugoniot there)") from None
    p = {"style": shape_dict["name"] + "/spline", "law": shape_dict, "m": mass, "a": size,
         "r0": r0 * size, "D": depth, "C": mass * (v0 / (r0 * size)) ** 2, "kv": kv, "v0": v0,
         "density": density, "vd": math.sqrt(2 * depth / mass), "rc": rc,
         "orientation": orientation, "lattice": lattice, "dim": dim,
         "c_impact": smooth.speed() * vunit, "s": smooth.slope(),
         "ideal": smooth.strength() * unit_stress, "strength": cut(rc), "up": up,
         "us": us, "us_metal": c0 + s * up, "constants": {
             k: v * unit_stress for k, v in smooth.constants().items()},
         "ucr": 1.35 * (rc * r0 / crystal.model_radius() - 1) * v0,
         "usp": strength / (density * c0),
         "sound_speed": sound_speed, "inputs": (density, c0, s, strength)}
    p.update(predictions(shape_dict, kv, r0 * size))
    return in_units(p, "si")


# the least distance of a bcc cut beyond the second shell, as a share of it: a free face
# relaxes the bonded shells outwards; free blocks at rest fall apart with the cut 2.1 % (iron
# [111]), 2.3 % (tantalum [111]) and 4.0 % (tantalum [100]) beyond the shell, and hold from
# 3.5 %, 2.8 % and 4.9 % (unittest/python/test_metal_lattices.py holds sets at this margin)
SURFACE_MARGIN = 0.06

# the papers' sets: Morse alpha a = 3.76 (the aluminium clusters) and 6 (matched to LJ)
KV_RANGE = (2.5, 8.0)


def predictions(shape, kv, r0):
    """What the set implies beyond its inputs (chain values, doc/compute_pair_params.rst):
    the Grueneisen coefficient -r0 Pi'''(r0) / (2 Pi''(r0)) and the inflection (break)
    distance b, with r0 the law's minimum."""
    if shape["name"] == "morse":
        return {"gamma": 1.5 * kv, "b": r0 * (1.0 + math.log(2.0) / kv)}
    n, m = (12.0, 6.0) if shape["name"] == "lj" else (shape["n"], shape["m"])
    b0 = r0 * ((n + 1) / (m + 1)) ** (1 / (n - m))
    return {"gamma": shape["kappa"] * (n + m + 3) / 2, "b": r0 + (b0 - r0) / shape["kappa"]}


def warnings(p):
    """Plain-language warnings for a set far from the papers' range."""
    out = []
    if not KV_RANGE[0] <= p["kv"] <= KV_RANGE[1]:
        out.append(f"kv = v0 / v_spall = {p['kv']:.3g} is far from the papers' sets (Morse alpha a "
                   f"3.76 and 6): the chain's Grueneisen coefficient is {p['gamma']:.3g} (metals: "
                   "about 1.5 to 2.5) and the bond breaks at b = "
                   f"{p['b'] / p['a']:.3g} a.  The spall speed is the lowest impact speed that "
                   "spalls a target twice the flyer's thickness (about 1.2-1.3 vd on fcc [100], "
                   "examples/spall), not a free-surface pull-back; such a set neither holds a "
                   "metal's Hugoniot nor its spall strength (doc/plate_impact.rst)")
    return out


def include_file(p, name, inputs):
    implied = (f"# implied: cluster (lattice) density {p['density']:.6g} (the density given, on "
               f"this lattice of a), Grueneisen (chain) {p['gamma']:.4g}, break (inflection) "
               f"distance b = {p['b'] / p['a']:.4g} a")
    if "rc" not in p:        # the metal calibration prints its onset at its own cut below
        implied += (f", dusting onset u_cr = 1.35 (Rc - 1) v0: {0.135 * p['v0']:.4g} m/s at "
                    f"Rc = 1.1, {0.27 * p['v0']:.4g} m/s at Rc = 1.2 (v0: the chain's speed "
                    "a sqrt(C/m))")
    lines = [
        f"# {name}: calibrated by tools/cd_calibrate.py from {inputs} (SI)",
        f"# SI: C = {p['C']:.6g} N/m, kv = {p['kv']:.6g}, v0 = {p['v0']:.6g} m/s, "
        f"vd = {p['vd']:.6g} m/s; the variables below are in units {p['units']} (pot_rc in "
        "units of r0, the law's minimum, the a of pot_coeff: r0 = a but on bcc), these comments "
        "in SI", implied]
    if "rc" in p:
        lines += report(p) + [f"variable pot_rc    equal  {p['rc']!r}",
                              f"variable pot_lattice string {p['lattice']}",
                              f"variable pot_orient string {p['orientation']}",
                              f"variable pot_c0    equal  {p['c_impact_units']!r}"]
        if p["dim"] == 3:
            scale, orient = cd_crystal.LAMMPS_LATTICE[(p["lattice"], p["orientation"])]
            period = scale * cd_crystal.SPACINGS[(p["lattice"], p["orientation"])][0]
            atoms, volume = cd_crystal.LAMMPS_CELL[p["lattice"]]
            cell = (scale * p["a"] if p["units"] != "lj" else        # lj: a number density
                    atoms / (volume * (scale * p["a"]) ** 3))
            lines += [f"variable pot_strength equal {p['strength_units']!r}",
                      f"variable pot_cell  equal  {cell!r}",
                      f'variable pot_lattice_orient string "{orient}"',
                      f"variable pot_xperiod equal {period * p['a']!r}"]
    lines += [
        f"variable pot_units string {p['units']}",
        f"variable pot_style string {p['style']}",
        f'variable pot_coeff string "{p["coeff"]}"',
        f"variable pot_m     equal  {p['m']!r}",
        f"variable pot_a     equal  {p['a']!r}", ""]
    return "\n".join(lines)


def report(p):
    """The metal calibration's matches, predictions and misses, as comment lines (SI)."""
    unit = STRESS_UNIT[p["dim"]]
    r0 = p["r0"] / p["a"]
    law_a = ("" if abs(r0 - 1) < 1e-12 else
             f"; the law's minimum r0 = {r0:.6g} a puts the lattice at zero pressure, "
             f"Rc r0 = {p['rc'] * r0:.6g} a")
    constants = ", ".join(f"{k} = {v:.4g}" for k, v in p["constants"].items())
    out = [f"# matched on {p['lattice']} [{p['orientation']}] along the impact: density, the "
           f"Hugoniot's c0 = {p['c_impact']:.5g} m/s and s = {p['s']:.4g} (weak shocks), the "
           f"spall strength as the ideal tensile strength {p['strength']:.4g} {unit} by the cut "
           f"Rc = {p['rc']:.6g} r0 (pair_style {p['style']} cut ${{pot_rc}}){law_a}",
           f"# predicted: us = {p['us']:.5g} m/s at up = {p['up']:.4g} m/s (cold lattice "
           f"Hugoniot; the metal's {p['us_metal']:.5g}); ideal strength without the cut "
           f"{p['ideal']:.4g} {unit}; vd = {p['vd']:.5g} m/s; elastic constants (Born-stable) "
           f"{constants} {unit}",
           f"# dusting onset u_cr = 1.35 (Rc r0 / d_last - 1) v0 = {p['ucr']:.4g} m/s (d_last: "
           "the last bonded shell) against the particle "
           f"speed that loads the spall strength, sigma / (rho c0) = {p['usp']:.4g} m/s"]
    if p.get("sound_speed") and abs(p["sound_speed"] - p["c_impact"]) > 1e-9 * p["c_impact"]:
        out.append(f"# not matched: the longitudinal speed {p['sound_speed']:.5g} m/s (the "
                   "lattice has no plastic flow: its elastic and shock waves are one, at c0)")
    return out


def metal_warnings(p):
    """Warnings for a metal calibration whose lattice cannot show its strength."""
    out = []
    if p["ucr"] < p["usp"]:
        out.append(f"the cut Rc = {p['rc']:.5g} r0 that matches the spall strength dusts the "
                   f"lattice from u_cr = {p['ucr']:.3g} m/s, below the particle speed "
                   f"{p['usp']:.3g} m/s that loads that strength: its ringing breaks bonds "
                   "before the mean tension reaches it: plate impacts of aluminium and copper "
                   "read 0.1-0.2 of the strength undamped, 0.55-0.6 with fix viscous/relative "
                   "J = 10 (measured: doc/plate_impact.rst)")
    if p["rc"] < 1.05:
        out.append(f"Rc = {p['rc']:.5g} r0 is far below the papers' 1.05-1.3")
    if p["law"]["name"] == "morse" and not KV_RANGE[0] <= p["kv"] <= KV_RANGE[1]:
        out.append(f"Morse alpha r0 = {p['kv']:.3g} is far from the papers' sets (3.76 and 6)")
    return out


HELP_LATTICE = """lattices (--lattice; --orientation along the impact, the first the default):
  chain  row                        density kg/m,   strength N
  tri    row, across                density kg/m^2, strength N/m
  fcc    100, 110, 111              density kg/m^3, strength Pa
  bcc    100, 110, 111              kg/m^3, Pa; the first two shells bonded, the cut 6 % beyond
                                    the second (or a free face falls apart) and below
                                    the third; the law's r0 > a (zero pressure)
  hcp    0001 (along c), 2-1-10 (the basal a axis), 01-10 (basal, across a)
                                    kg/m^3, Pa; c/a = sqrt(8/3); the second site relaxed
Krivtsov's calibration (--spall-speed) takes chain, tri and fcc; the metal calibration all.
--size is the nearest-neighbour distance a; pot_rc is in units of the law's r0 (= a but on
bcc); doc/compute_pair_params.rst, doc/plate_impact.rst."""


def main(argv=None):
    ap = numbers_take_values(argparse.ArgumentParser(
        description=__doc__, epilog=HELP_LATTICE,
        formatter_class=argparse.RawDescriptionHelpFormatter))
    ap.add_argument("--density", type=float, required=True,
                    help="mass per volume, kg/m^3 (per area kg/m^2 for tri, per length kg/m for chain)")
    ap.add_argument("--sound-speed", type=float,
                    help="longitudinal sound speed v_l, m/s (metal calibration: reported, not "
                         "matched)")
    ap.add_argument("--spall-speed", type=float,
                    help="Krivtsov's spall (minimum impactor) speed, m/s (with --sound-speed)")
    ap.add_argument("--hugoniot", type=float, nargs=2, metavar=("C0", "S"),
                    help="the Hugoniot us = C0 + S up (m/s): the metal calibration")
    ap.add_argument("--grueneisen", type=float,
                    help="instead of --hugoniot S: S = (G + 1)/2, with --bulk-speed C0")
    ap.add_argument("--bulk-speed", type=float,
                    help="with --grueneisen: the Hugoniot's C0 (the bulk sound speed), m/s")
    ap.add_argument("--spall-strength", type=float,
                    help="spall strength, Pa (N/m on tri, N on chain): the metal calibration")
    ap.add_argument("--orientation", help="lattice direction along the impact (see below)")
    ap.add_argument("--up", type=float,
                    help="particle speed of the predicted shock speed, m/s (default 0.04 C0)")
    ap.add_argument("--size", type=float, required=True,
                    help="cluster size = the lattice's nearest-neighbour distance a, m")
    ap.add_argument("--lattice", required=True, help="chain, tri, fcc, bcc or hcp (see below)")
    ap.add_argument("--law", default="morse", help="morse (default), lj or mie")
    ap.add_argument("--n", type=float, help="Mie repulsive exponent (default 12)")
    ap.add_argument("--m", type=float, help="Mie attractive exponent (default 6)")
    ap.add_argument("--units", default="si",
                    help="LAMMPS unit style of the numbers written (default si; lj: reduced by a, m, D)")
    ap.add_argument("--name", default="calibrated", help="name for the header")
    args = ap.parse_args(argv)
    metal = any(x is not None for x in (args.hugoniot, args.grueneisen, args.bulk_speed,
                                        args.spall_strength))
    try:
        check_arguments(args, metal)
        n = 12.0 if args.n is None else args.n
        m = 6.0 if args.m is None else args.m
        if metal:
            c0, s = hugoniot_of(args)
            p = calibrate_metal(args.density, c0, s, args.spall_strength, args.size,
                                args.lattice, cd_crystal.DEFAULT_ORIENTATION[args.lattice]
                                if args.orientation is None else args.orientation, args.law,
                                n, m, args.up,
                                args.sound_speed)
            given = (f"--hugoniot {c0:g} {s:g}" if args.hugoniot is not None else
                     f"--grueneisen {args.grueneisen:g} --bulk-speed {c0:g}")
            inputs = (f"density {args.density:g}, {given}, spall strength "
                      f"{args.spall_strength:g}, a {args.size:g}, lattice {args.lattice} "
                      f"[{p['orientation']}], law {args.law}")
            texts = metal_warnings(p)
        else:
            p = calibrate(args.density, args.sound_speed, args.spall_speed, args.size,
                          args.lattice, args.law, n, m)
            inputs = (f"density {args.density}, v_l {args.sound_speed}, v_spall "
                      f"{args.spall_speed}, a {args.size}, lattice {args.lattice}, law {args.law}")
            texts = warnings(p)
        p = in_units(p, args.units)
    except ValueError as err:
        sys.exit(f"cd_calibrate: {err}")
    for text in texts:
        sys.stderr.write(f"cd_calibrate: warning: {text}\n")
    sys.stdout.write(include_file(p, args.name, inputs))


def check_arguments(args, metal):
    """Errors for arguments that do not belong together (nothing is ignored silently)."""
    if args.lattice not in cd_crystal.LATTICES:
        raise ValueError(f"unknown --lattice '{args.lattice}' (expected "
                         f"{', '.join(cd_crystal.LATTICES)})")
    if "\n" in args.name or "\r" in args.name:
        raise ValueError("--name must be one line")
    if args.law != "mie" and (args.n is not None or args.m is not None):
        raise ValueError(f"--n and --m belong to --law mie (got --law {args.law})")
    if metal:
        if args.spall_speed is not None:
            raise ValueError("--spall-speed is Krivtsov's calibration: give it or the metal's "
                             "--hugoniot/--grueneisen and --spall-strength, not both")
        if args.spall_strength is None:
            raise ValueError("the metal calibration needs --spall-strength (Pa) beside "
                             "--hugoniot or --grueneisen")
        return
    for name, value in (("--orientation", args.orientation), ("--up", args.up)):
        if value is not None:
            raise ValueError(f"{name} belongs to the metal calibration (--hugoniot, "
                             "--spall-strength)")
    if args.sound_speed is None or args.spall_speed is None:
        raise ValueError("give --sound-speed and --spall-speed (Krivtsov's calibration) "
                         "or --hugoniot C0 S and --spall-strength (a metal's)")


def hugoniot_of(args):
    """(c0, s) from --hugoniot, or --grueneisen with --bulk-speed."""
    if args.hugoniot is not None:
        if args.grueneisen is not None or args.bulk_speed is not None:
            raise ValueError("give --hugoniot C0 S or --grueneisen G --bulk-speed C0, not both")
        return tuple(args.hugoniot)
    if args.grueneisen is None or args.bulk_speed is None:
        raise ValueError("the metal calibration needs --hugoniot C0 S (or --grueneisen G with "
                         "--bulk-speed C0) and --spall-strength")
    positive("--grueneisen", args.grueneisen)
    return positive("--bulk-speed", args.bulk_speed), (args.grueneisen + 1) / 2


if __name__ == "__main__":
    main()
