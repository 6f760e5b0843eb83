"""Every quantity with a dimension in all eight LAMMPS unit styles, against closed forms written
with LAMMPS's own conversion constants (force->ftm2v, force->mvv2e, read from the running
instance): the pair force through LAMMPS's integrator (a harmonic dimer, whose velocity-Verlet
orbit is known exactly), compute pair/params (frequencies, speeds, damping, the shock table),
fix viscous/relative (gamma: exp(-2 G t) and the energy tally; J: a damped oscillator), the
time-step warning's threshold, and tools/cd_calibrate.py --units.

The law is the same set of numbers in every style (a = 1 distance unit, D = 1 energy unit,
m = 2 mass units); what differs between styles is how LAMMPS turns forces into motion."""
import math
import os
import subprocess
import sys

import pytest
from conftest import session

UNITS = ["lj", "real", "metal", "si", "cgs", "electron", "micro", "nano"]
NAMES = ["a", "b", "sigma", "D", "fstar", "C", "eps", "kstar", "kv", "k2", "Gamma", "omega0",
         "T0", "v0", "vd", "Bstar", "Rc", "ucr", "ucr1d", "vl"]
TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CALIBRATE = os.path.join(TOP, "tools", "cd_calibrate.py")
MASS, ALPHA, DEPTH = 2.0, 6.0, 1.0    # Morse alpha a = 6, C = 2 alpha^2 D = 72


def constants(lmp):
    return lmp.extract_global("ftm2v"), lmp.extract_global("mvv2e")


def dimer(lmp, units, r, pair, extra=()):
    """Two atoms of mass MASS at x = 0 and r (a = 1), in a box of 8 x 4 x 4."""
    lmp.commands_list([f"units {units}", "atom_modify map array", "boundary f f f",
                       "region box block -2 6 -2 2 -2 2", "create_box 1 box",
                       f"mass 1 {MASS}", "neighbor 0.3 bin", "create_atoms 1 single 0 0 0",
                       f"create_atoms 1 single {r!r} 0 0", *pair, *extra])


def morse_pi2(r):
    e = math.exp(-ALPHA * (r - 1.0))
    return 2 * ALPHA ** 2 * DEPTH * (2 * e * e - e)


@pytest.mark.parametrize("units", UNITS)
def test_harmonic_dimer_follows_the_exact_verlet_orbit(units):
    """Relative coordinate x: x'' = -w^2 x with w^2 = 2 ftm2v C / m; velocity Verlet from rest
    gives x_n = A cos(n theta), cos(theta) = 1 - (w h)^2 / 2, exactly."""
    amp, steps = 0.05, 300
    with session() as lmp:
        dimer(lmp, units, 1.0 + amp, ["pair_style harmonic/spline cut 1.2",
                                      f"pair_coeff 1 1 {DEPTH} {ALPHA} 1.0"])
        ftm2v, mvv2e = constants(lmp)
        w = math.sqrt(2 * ftm2v * 2 * ALPHA ** 2 * DEPTH / MASS)
        h = 2 * math.pi / w / 100
        lmp.commands_list([f"timestep {h!r}", "fix nve all nve", "thermo_modify norm no",
                           "run 0 post no"])
        assert lmp.get_thermo("pe") == pytest.approx(ALPHA ** 2 * DEPTH * amp ** 2 - DEPTH,
                                                     rel=1e-12)    # energy units: the law's
        lmp.command(f"run {steps} post no")
        x = lmp.numpy.extract_atom("x")[:2, 0].copy()
        ke = lmp.get_thermo("ke")
        v = lmp.numpy.extract_atom("v")[:2, 0].copy()
    theta = math.acos(1 - (w * h) ** 2 / 2)
    assert x[1] - x[0] - 1.0 == pytest.approx(amp * math.cos(steps * theta), abs=1e-9 * amp)
    assert ke == pytest.approx(0.5 * MASS * mvv2e * (v[0] ** 2 + v[1] ** 2), rel=1e-12)


def solve_y(u, c0):
    """y + (u/c0) / sqrt(Pi''(y a)/C) = 1, the first root below 1, Morse closed form."""
    g = lambda y: y + (u / c0) / math.sqrt(morse_pi2(y) / morse_pi2(1.0)) - 1
    hi = 1.0
    while g(hi - 0.005) > 0:
        hi -= 0.005
    lo = hi - 0.005
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if g(mid) > 0 else (mid, hi)
    return 0.5 * (lo + hi)


@pytest.mark.parametrize("units", UNITS)
def test_pair_params_every_dimensioned_value(units):
    with session() as lmp:
        dimer(lmp, units, 1.0, ["pair_style morse/spline cut 1.2",
                                f"pair_coeff 1 1 {DEPTH} {ALPHA} 1.0",
                                "compute p all pair/params 1 1 lattice fcc u 1 2",
                                "thermo_style custom step c_p[1]", "run 0 post no"])
        ftm2v, mvv2e = constants(lmp)
        v0 = lmp.numpy.extract_compute("p", 0, 1)[13]
        lmp.commands_list(["uncompute p", f"compute p all pair/params 1 1 lattice fcc "
                           f"u {0.3 * v0!r} {1.2 * v0!r}", "run 0 post no"])
        got = dict(zip(NAMES, lmp.numpy.extract_compute("p", 0, 1)[:20].copy()))
        table = lmp.numpy.extract_compute("p", 0, 2).copy()
    c = 2 * ALPHA ** 2 * DEPTH
    omega0 = math.sqrt(ftm2v * c / MASS)
    want = {"a": 1.0, "D": DEPTH, "C": c, "b": 1 + math.log(2) / ALPHA,
            "fstar": ALPHA * DEPTH / 2, "omega0": omega0, "T0": 2 * math.pi / omega0,
            "v0": omega0, "vd": math.sqrt(2 * DEPTH / (MASS * mvv2e)),
            "Bstar": 2 * math.sqrt(MASS * c / ftm2v), "ucr": 1.35 * 0.2 * omega0,
            "ucr1d": 0.2 * omega0 / (2 * math.sqrt(2)), "vl": 1.10 * omega0}
    for key, value in want.items():
        assert got[key] == pytest.approx(value, rel=1e-12), key
    for row, u in zip(table, (0.3 * v0, 1.2 * v0)):
        y = solve_y(u, omega0)
        cu = u / (1 - y)
        assert row[1] == pytest.approx(y, rel=1e-9)
        assert row[3] == pytest.approx(cu, rel=1e-8)
        assert row[4] == pytest.approx(math.pi / cu, rel=1e-8)
        assert row[5] == pytest.approx(math.pi / cu / 20, rel=1e-8)


def test_copper_like_morse_in_metal_units():
    """The review's case: Cu Morse (D = 0.3429 eV, alpha = 1.3588 1/A, r0 = 2.866 A, 63.546
    g/mol) has omega0 = sqrt(2 alpha^2 D / m) = 13.87 1/ps (0.141 before the fix)."""
    with session() as lmp:
        lmp.commands_list(["units metal", "region box block 0 20 0 20 0 20", "create_box 1 box",
                           "mass 1 63.546", "pair_style morse/spline cut 1.5",
                           "pair_coeff 1 1 0.3429 1.3588 2.866", "compute p all pair/params 1 1",
                           "thermo_style custom step c_p[1]", "run 0 post no"])
        omega0 = lmp.numpy.extract_compute("p", 0, 1)[11]
    si = math.sqrt(2 * 1.3588e10 ** 2 * 0.3429 * 1.602176634e-19 / (63.546e-3 / 6.02214076e23))
    assert omega0 == pytest.approx(si * 1e-12, rel=1e-6) and omega0 == pytest.approx(13.87, abs=0.005)


@pytest.mark.parametrize("units", UNITS)
def test_fix_gamma_decays_relative_velocity_as_exp_minus_2gt(units):
    """No other force: w = v1 - v2 decays as exp(-2 G t) for any masses; the energy removed
    is the kinetic energy lost (the tally is exact per half kick)."""
    with session() as lmp:
        lmp.commands_list([f"units {units}", "atom_modify map array",
                           "boundary f f f", "region box block -2 6 -2 2 -2 2", "create_box 2 box",
                           "mass 1 1.0", "mass 2 3.0", "neighbor 0.3 bin",
                           "create_atoms 1 single 0 0 0", "create_atoms 2 single 1 0 0",
                           "pair_style zero 2.0", "pair_coeff * *",
                           "velocity all set 0 0 0", "set atom 1 vx 0.75", "set atom 2 vx -0.25"])
        ftm2v, mvv2e = constants(lmp)
        gamma, h, steps = 1.0, 5e-4, 1000    # G in 1/time: 2 G t = 1
        lmp.commands_list([f"timestep {h}", "fix nve all nve",
                           f"fix d all viscous/relative gamma {gamma}", "thermo_modify norm no",
                           "run 0 post no"])
        ke0 = lmp.get_thermo("ke")
        assert ke0 == pytest.approx(0.5 * mvv2e * (0.75 ** 2 + 3 * 0.25 ** 2), rel=1e-12)
        lmp.command(f"run {steps} post no")
        v = lmp.numpy.extract_atom("v")[:2, 0].copy()
        removed = lmp.numpy.extract_fix("d", 0, 0)
        ke = lmp.get_thermo("ke")
    assert v[0] - v[1] == pytest.approx(math.exp(-2 * gamma * h * steps), rel=2e-3)
    assert v[0] + 3 * v[1] == pytest.approx(0.0, abs=1e-12)    # momentum
    assert ke0 - ke == pytest.approx(removed, rel=1e-7)          # energy units


@pytest.mark.parametrize("units", UNITS)
def test_fix_j_damps_a_harmonic_dimer_as_the_damped_oscillator(units):
    """J: G = sqrt(ftm2v C / m_ij) / J; x'' + 2 G x' + w^2 x = 0 with w^2 = 2 ftm2v C / m."""
    amp, J = 0.05, 5.0
    with session() as lmp:
        dimer(lmp, units, 1.0 + amp, ["pair_style harmonic/spline cut 1.2",
                                      f"pair_coeff 1 1 {DEPTH} {ALPHA} 1.0"])
        ftm2v, mvv2e = constants(lmp)
        c = 2 * ALPHA ** 2 * DEPTH
        w, g = math.sqrt(2 * ftm2v * c / MASS), math.sqrt(ftm2v * c / MASS) / J
        h = 2 * math.pi / w / 2000
        lmp.commands_list([f"timestep {h!r}", "fix nve all nve",
                           f"fix d all viscous/relative J {J}", "run 2000 post no"])
        x = lmp.numpy.extract_atom("x")[:2, 0].copy()
    t, wd = 2000 * h, math.sqrt(w * w - g * g)
    exact = amp * math.exp(-g * t) * (math.cos(wd * t) + g / wd * math.sin(wd * t))
    assert x[1] - x[0] - 1.0 == pytest.approx(exact, abs=2e-3 * amp)


@pytest.mark.parametrize("units", UNITS)
def test_time_step_warning_threshold(units, tmp_path):
    """Warn iff dt > pi / (20 sqrt(ftm2v Pi''(r)/m)) at the closest pair (r = 0.9 a here)."""
    logs = {}
    for factor in (0.99, 1.01):
        log = tmp_path / f"log.{factor}"
        with session("-log", str(log)) as lmp:
            dimer(lmp, units, 0.9, ["pair_style morse/spline cut 1.2",
                                    f"pair_coeff 1 1 {DEPTH} {ALPHA} 1.0"])
            ftm2v, _ = constants(lmp)
            dt = math.pi / (20 * math.sqrt(ftm2v * morse_pi2(0.9) / MASS))
            lmp.commands_list([f"timestep {factor * dt!r}", "run 1 post no"])   # run 0 takes no step
        logs[factor] = log.read_text()
    assert "time step" not in logs[0.99]
    assert "WARNING: Pair morse/spline: time step" in logs[1.01]
    assert "(closest pair at 0.9 a)" in logs[1.01]


# the velocity unit of each style in m/s (LAMMPS's units doc; electron: Bohr/fs, as its
# ftm2v and mvv2e constants have it)
VELOCITY = {"real": 1e5, "metal": 100.0, "si": 1.0, "cgs": 0.01, "electron": 5.29177210903e4,
            "micro": 1.0, "nano": 1.0}


@pytest.mark.parametrize("units", UNITS)
def test_calibration_writes_the_units_it_names(units):
    v_l, v_spall = 6420.0, 1500.0
    out = subprocess.run([sys.executable, CALIBRATE, "--density", "2700", "--sound-speed",
                          str(v_l), "--spall-speed", str(v_spall), "--size", "1e-5",
                          "--lattice", "fcc", "--units", units], capture_output=True, text=True,
                         check=True).stdout
    with session() as lmp:
        for line in out.splitlines():
            if line.startswith("variable"):
                lmp.command(line)
        assert lmp.extract_variable("pot_units") == units
        lmp.commands_list([f"units {units}", "region box block 0 $(10*v_pot_a) 0 $(10*v_pot_a) "
                           "0 $(10*v_pot_a) units box", "create_box 1 box", "mass 1 ${pot_m}",
                           "neighbor $(0.2*v_pot_a) bin", "pair_style ${pot_style} cut 1.2",
                           "pair_coeff 1 1 ${pot_coeff}", "compute p all pair/params 1 1 lattice fcc",
                           "thermo_style custom step c_p[1]", "run 0 post no"])
        got = dict(zip(NAMES, lmp.numpy.extract_compute("p", 0, 1)[:20].copy()))
    if units == "lj":    # reduced by a, m, D: vd = sqrt(2) and the speeds keep their ratio
        assert got["a"] == 1.0 and got["D"] == pytest.approx(1.0, rel=1e-12)
        assert got["vd"] == pytest.approx(math.sqrt(2), rel=1e-12)
        assert got["vl"] / got["vd"] == pytest.approx(v_l / v_spall, rel=1e-12)
    else:
        assert got["vl"] == pytest.approx(v_l / VELOCITY[units], rel=1e-6)
        assert got["vd"] == pytest.approx(v_spall / VELOCITY[units], rel=1e-6)
