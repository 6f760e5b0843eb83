#!/usr/bin/python3
"""Calibrate a cluster-dynamics pair law from macroscopic data (Krivtsov, section 8; spec
potentials.md section 6) and write a potentials/ parameter set (*.cd include file).

    tools/cd_calibrate.py --density 2700 --sound-speed 6420 --spall-speed 1500 \
        --size 1e-5 --lattice fcc --law morse --name al-10um > potentials/al-10um.cd

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
        style, coeff = "morse/spline", f"{depth!r} {kv / size!r} {size!r} kappa 1"
    elif law == "lj":
        style, coeff = "lj/spline", f"{depth!r} {size!r} kappa {kv / 6.0!r}"
    elif law == "mie":
        style, coeff = "mie/spline", f"{depth!r} {size!r} {n!r} {m!r} kappa {kv / math.sqrt(n * m / 2)!r}"
    else:
        raise ValueError(f"unknown law '{law}' (expected morse, lj or mie)")
    return {"style": style, "coeff": coeff, "m": mass, "a": size, "D": depth, "C": c,
            "kv": kv, "v0": v0, "vd": math.sqrt(2 * depth / mass)}


def include_file(p, name, units, inputs):
    return "\n".join([
        f"# {name}: calibrated by tools/cd_calibrate.py from {inputs}",
        f"# C = {p['C']:.6g}, kv = {p['kv']:.6g}, v0 = {p['v0']:.6g}, vd = {p['vd']:.6g}",
        f"variable pot_units string {units}",
        f"variable pot_style string {p['style']}",
        f'variable pot_coeff string "{p["coeff"]}"',
        f"variable pot_m     equal  {p['m']!r}",
        f"variable pot_a     equal  {p['a']!r}", ""])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--density", type=float, required=True, help="mass per volume (area, length)")
    ap.add_argument("--sound-speed", type=float, required=True, help="longitudinal sound speed v_l")
    ap.add_argument("--spall-speed", type=float, required=True, help="spall (minimum impactor) speed")
    ap.add_argument("--size", type=float, required=True, help="cluster size = equilibrium distance a")
    ap.add_argument("--lattice", required=True, help="chain, tri or fcc")
    ap.add_argument("--law", default="morse", help="morse (default), lj or mie")
    ap.add_argument("--n", type=float, default=12.0, help="Mie repulsive exponent")
    ap.add_argument("--m", type=float, default=6.0, help="Mie attractive exponent")
    ap.add_argument("--units", default="si", help="LAMMPS units of the numbers (default si)")
    ap.add_argument("--name", default="calibrated", help="name for the header")
    args = ap.parse_args(argv)
    try:
        p = calibrate(args.density, args.sound_speed, args.spall_speed, args.size, args.lattice,
                      args.law, args.n, args.m)
    except ValueError as err:
        sys.exit(f"cd_calibrate: {err}")
    inputs = (f"density {args.density}, v_l {args.sound_speed}, v_spall {args.spall_speed}, "
              f"a {args.size}, lattice {args.lattice}, law {args.law}")
    sys.stdout.write(include_file(p, args.name, args.units, inputs))


if __name__ == "__main__":
    main()
