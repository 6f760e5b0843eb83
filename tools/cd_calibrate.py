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
"""
import argparse
import math
import sys

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


def in_units(p, units):
    """The parameter set p (SI, from calibrate()) with its numbers in the LAMMPS unit style
    units; lj: a, m and D are the units of length, mass and energy."""
    if units == "lj":
        mass, length, energy = p["m"], p["a"], p["D"]
    elif units in UNITS:
        mass, length, energy = UNITS[units]
    else:
        raise ValueError(f"unknown units '{units}' (expected {', '.join(UNITS)} or lj)")
    d, a, m = p["D"] / energy, p["a"] / length, p["m"] / mass
    law = p["law"]
    if law["name"] == "morse":
        coeff = f"{d!r} {p['kv'] / a!r} {a!r} kappa 1"
    elif law["name"] == "lj":
        coeff = f"{d!r} {a!r} kappa {law['kappa']!r}"
    else:
        coeff = f"{d!r} {a!r} {law['n']!r} {law['m']!r} kappa {law['kappa']!r}"
    return dict(p, coeff=coeff, m=m, a=a, D=d, units=units)


def calibrate(density, sound_speed, spall_speed, size, lattice, law="morse", n=12.0, m=6.0):
    """The parameter set as a dict; raises ValueError when the data admit no potential."""
    for name, value in (("density", density), ("sound speed", sound_speed),
                        ("spall speed", spall_speed), ("size", size)):
        if not value > 0:
            raise ValueError(f"{name} must be > 0 (got {value})")
    if lattice not in LATTICES:
        raise ValueError(f"unknown lattice '{lattice}' (expected chain, tri or fcc)")
    if law == "mie" and not n > m > 0:
        raise ValueError(f"Mie exponents need n > m > 0 (got n = {n}, m = {m})")
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
        raise ValueError(f"unknown law '{law}' (expected morse, lj or mie)")
    p = {"style": style, "law": shape, "m": mass, "a": size, "D": depth, "C": c, "kv": kv,
         "v0": v0, "vd": math.sqrt(2 * depth / mass), "density": density}
    p.update(predictions(shape, kv, size))
    return in_units(p, "si")


# the papers' sets: Morse alpha a = 3.76 (the aluminium clusters) and 6 (matched to LJ)
KV_RANGE = (2.5, 8.0)


def predictions(shape, kv, size):
    """What the set implies beyond its inputs (chain values, doc/compute_pair_params.rst):
    the Grueneisen coefficient -a Pi'''(a) / (2 Pi''(a)) and the inflection (break) distance b."""
    if shape["name"] == "morse":
        return {"gamma": 1.5 * kv, "b": size * (1.0 + math.log(2.0) / kv)}
    n, m = (12.0, 6.0) if shape["name"] == "lj" else (shape["n"], shape["m"])
    b0 = size * ((n + 1) / (m + 1)) ** (1 / (n - m))
    return {"gamma": shape["kappa"] * (n + m + 3) / 2, "b": size + (b0 - size) / shape["kappa"]}


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
    return "\n".join([
        f"# {name}: calibrated by tools/cd_calibrate.py from {inputs} (SI)",
        f"# SI: C = {p['C']:.6g} N/m, kv = {p['kv']:.6g}, v0 = {p['v0']:.6g} m/s, "
        f"vd = {p['vd']:.6g} m/s; the numbers below are in units {p['units']}",
        f"# implied: cluster (lattice) density {p['density']:.6g} (the density given, on this "
        f"lattice of a), Grueneisen (chain) {p['gamma']:.4g}, break (inflection) distance "
        f"b = {p['b'] / p['a']:.4g} a, dusting onset u_cr = 1.35 (Rc - 1) v0 = "
        f"{0.135 * p['v0']:.4g} m/s per 0.1 of Rc - 1",
        f"variable pot_units string {p['units']}",
        f"variable pot_style string {p['style']}",
        f'variable pot_coeff string "{p["coeff"]}"',
        f"variable pot_m     equal  {p['m']!r}",
        f"variable pot_a     equal  {p['a']!r}", ""])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--density", type=float, required=True,
                    help="mass per volume, kg/m^3 (per area kg/m^2 for tri, per length kg/m for chain)")
    ap.add_argument("--sound-speed", type=float, required=True, help="longitudinal sound speed v_l, m/s")
    ap.add_argument("--spall-speed", type=float, required=True, help="spall (minimum impactor) speed, m/s")
    ap.add_argument("--size", type=float, required=True, help="cluster size = equilibrium distance a, m")
    ap.add_argument("--lattice", required=True, help="chain, tri or fcc")
    ap.add_argument("--law", default="morse", help="morse (default), lj or mie")
    ap.add_argument("--n", type=float, default=12.0, help="Mie repulsive exponent")
    ap.add_argument("--m", type=float, default=6.0, help="Mie attractive exponent")
    ap.add_argument("--units", default="si",
                    help="LAMMPS unit style of the numbers written (default si; lj: reduced by a, m, D)")
    ap.add_argument("--name", default="calibrated", help="name for the header")
    args = ap.parse_args(argv)
    try:
        p = in_units(calibrate(args.density, args.sound_speed, args.spall_speed, args.size,
                               args.lattice, args.law, args.n, args.m), args.units)
    except ValueError as err:
        sys.exit(f"cd_calibrate: {err}")
    inputs = (f"density {args.density}, v_l {args.sound_speed}, v_spall {args.spall_speed}, "
              f"a {args.size}, lattice {args.lattice}, law {args.law}")
    for text in warnings(p):
        sys.stderr.write(f"cd_calibrate: warning: {text}\n")
    sys.stdout.write(include_file(p, args.name, inputs))


if __name__ == "__main__":
    main()
