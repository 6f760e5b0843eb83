"""pair_style mca in dimension 2 (discs of unit thickness, plane strain or plane stress).

Oracles: the closed forms of isotropic plane elasticity on the triangular packing (exact
there, as on fcc in 3d: Love's identity sum S R n n = Omega I): in plane strain C11 = lambda +
2G, C12 = lambda, E' = E / (1 - nu^2), nu' = nu / (1 - nu); in plane stress E and nu
themselves; the wave speeds sqrt((lambda + 2G)/rho), sqrt(E / ((1 - nu^2) rho)) and
sqrt(G/rho) from the period of a standing wave; an unlinked pair's compression through the
hexagon's side 2 R / sqrt(3); the dt^2 scaling of velocity Verlet's energy error; serial
against 2 ranks, newton on and off; a straight run against a restarted one.  Units lj and si."""
import math

import numpy as np
import pytest
from conftest import (PLUGIN, assert_falls_as_dt2, energy_error_spread, run_lmp, session,
                      thermo_rows)
from test_pair_mca import positions

TRIANGULAR = math.pi / math.sqrt(12.0)
# an element radius and Young's modulus of each unit style's order
SCALE = {"lj": (0.5, 1.0), "si": (1.0e-3, 1.0e9)}


def moduli(e, nu):
    """K, G and Lame's lambda of the 3d material."""
    g = e / (2.0 * (1.0 + nu))
    k = e / (3.0 * (1.0 - 2.0 * nu))
    return k, g, k - 2.0 * g / 3.0


def in_plane(e, nu, plane):
    """C11, C12 of the plane's isotropic stiffness (plane stress: lambda* = 2 G lambda /
    (lambda + 2 G))."""
    _, g, lam = moduli(e, nu)
    if plane == "stress":
        lam = 2.0 * g * lam / (lam + 2.0 * g)
    return lam + 2.0 * g, lam


def triangular_block(units, plane, nu, nx=6, ny=4, newton="on", extra=()):
    """A periodic triangular packing of touching discs (density 1/F: element density 1 in
    reduced units, rho in kg/m^3 of 1 in si)."""
    r, e = SCALE[units]
    k, g, _ = moduli(e, nu)
    a = 2.0 * r
    lattice = (f"lattice hex {2.0 / (math.sqrt(3.0) * a * a)!r}" if units == "lj" else
               f"lattice hex {a!r}") + " origin 0.25 0.25 0"    # no element on a box face
    return [f"units {units}", "dimension 2", "atom_style sphere", "boundary p p p",
            "comm_modify vel yes", f"newton {newton}", lattice,
            f"region box block 0 {nx} 0 {ny} -0.5 0.5", "create_box 1 box",
            "create_atoms 1 box", f"set group all diameter {a!r}",
            f"set group all density/disc {1.0 / TRIANGULAR!r}", f"neighbor {0.2 * r!r} bin",
            f"pair_style mca fraction {TRIANGULAR!r} tolerance 0.02 plane {plane}",
            f"pair_coeff 1 1 bulk {k!r} shear {g!r}", *extra]


@pytest.mark.parametrize("units", ["lj", "si"])
@pytest.mark.parametrize("plane", ["strain", "stress"])
@pytest.mark.parametrize("nu", [0.1, 0.3, 0.45])
def test_triangular_packing_moduli(units, plane, nu):
    """Strains of 1e-4 along x and y in turn: the virial stresses give C11 and C12 of plane
    strain or plane stress within 1e-3 (the issue asks 3 % for E and 0.02 for nu), and the
    plane's E and nu from them."""
    r, e = SCALE[units]
    eps = 1.0e-4
    c = []
    with session() as lmp:
        lmp.commands_list(triangular_block(units, plane, nu) + [
            "compute p all pressure NULL virial", "thermo_style custom step c_p[1]", "run 0"])
        for axis in "xy":
            lmp.command(f"change_box all {axis} scale {1.0 + eps!r} remap")
            lmp.command("run 0")
            p = lmp.numpy.extract_compute("p", 0, 1)
            c.append([-p[0] / eps, -p[1] / eps])
            lmp.command(f"change_box all {axis} scale {1.0 / (1.0 + eps)!r} remap")
        nktv2p = lmp.extract_global("nktv2p")
    c = np.array(c) / nktv2p
    c11, c12 = in_plane(e, nu, plane)
    assert np.allclose(np.diag(c), c11, rtol=1e-3) and np.allclose(c[0, 1], c12, rtol=1e-3), c
    e2 = (c[0, 0] ** 2 - c[0, 1] ** 2) / c[0, 0]
    nu2 = c[0, 1] / c[0, 0]
    want_e, want_nu = (e / (1.0 - nu ** 2), nu / (1.0 - nu)) if plane == "strain" else (e, nu)
    assert e2 == pytest.approx(want_e, rel=1e-3) and nu2 == pytest.approx(want_nu, abs=1e-3)


def standing_wave_speed(units, plane, nu, polarisation, nx=40):
    """A standing wave u = A sin(2 pi x / L) along a periodic strip of nx elements, started
    from rest after the links are made: its amplitude goes as cos(c k t), first zero at a
    quarter period; returns c and the strip's density rho = m / Omega."""
    r, e = SCALE[units]
    amp = 1.0e-4 * r
    with session() as lmp:
        lmp.commands_list(triangular_block(units, plane, nu, nx=nx, ny=2) + [
            "fix move all nve/sphere disc", "run 0"])
        n = lmp.extract_global("nlocal")
        lx = lmp.extract_global("boxhi")[0] - lmp.extract_global("boxlo")[0]
        x0 = np.array(lmp.numpy.extract_atom("x")[:n])
        k = 2.0 * math.pi / lx
        rho = lmp.numpy.extract_atom("rmass")[0] / (math.pi * r * r / TRIANGULAR)
        axis = 0 if polarisation == "longitudinal" else 1
        lmp.command(f"variable u atom {amp!r}*sin({k!r}*x)")
        lmp.command("displace_atoms all move v_u 0 0" if axis == 0 else
                    "displace_atoms all move 0 v_u 0")
        c11, _ = in_plane(e, nu, plane)
        dt = 0.05 * 2.0 * r / math.sqrt(c11 / rho)    # a twentieth of an element's crossing
        lmp.command(f"timestep {dt!r}")
        lmp.command("run 0")
        history = []
        t = 0.0
        while True:
            x = np.array(lmp.numpy.extract_atom("x")[:n])
            a = np.sum((x[:, axis] - x0[:, axis]) * np.sin(k * x0[:, 0]))
            history.append((t, a))
            if a < 0.0:
                break
            lmp.command("run 1 pre no post no")
            t += dt
    (t0, a0), (t1, a1) = history[-2:]
    quarter = t0 + (t1 - t0) * a0 / (a0 - a1)
    return lx / (4.0 * quarter), rho


@pytest.mark.parametrize("units", ["lj", "si"])
@pytest.mark.parametrize("plane", ["strain", "stress"])
@pytest.mark.parametrize("polarisation", ["longitudinal", "transverse"])
def test_wave_speeds(units, plane, polarisation):
    """The period of the longest standing wave of a 40-element strip: sqrt(C11/rho)
    (plane strain: (lambda + 2G)/rho; plane stress: E/((1 - nu^2) rho)) and sqrt(G/rho),
    within 2 %."""
    r, e = SCALE[units]
    nu = 0.3
    c, rho = standing_wave_speed(units, plane, nu, polarisation)
    _, g, lam = moduli(e, nu)
    if polarisation == "transverse":
        want = math.sqrt(g / rho)
    elif plane == "strain":
        want = math.sqrt((lam + 2.0 * g) / rho)
    else:
        want = math.sqrt(e / ((1.0 - nu * nu) * rho))
    assert rho == pytest.approx(1.0, rel=1e-12)
    assert c == pytest.approx(want, rel=0.02)


BLOCK_2D = """
plugin load {plugin}
units lj
dimension 2
atom_style sphere
boundary p p p
comm_modify vel yes
newton {newton}
lattice hex $(2.0/sqrt(3.0))
region box block 0 8 0 5 -0.5 0.5
create_box 1 box
create_atoms 1 box
reset_atoms id sort yes
set group all diameter 1.0
variable phi equal PI/sqrt(12.0)
set group all density/disc $(1.0/v_phi)
pair_style mca fraction ${{phi}} tolerance 0.02 plane strain
pair_coeff 1 1 young 1.0 poisson 0.3 yield 0.004 strength 0.006 friction 0.3
displace_atoms all random 0.01 0.01 0 4711 units box
velocity all create {temp} 4712 loop geom
neighbor 0.2 bin
fix move all nve/sphere disc
fix plane all enforce2d
compute rot all erotate/sphere
variable etot equal pe+ke+c_rot
timestep {dt}
thermo_style custom step pe ke c_rot v_etot
thermo_modify norm no format float %.15g
"""


def test_energy_conservation_dt2():
    """A hot elastic 2d block: translational + rotational + elastic energy, its error falls
    as dt^2."""
    def script(dt):
        text = BLOCK_2D.format(plugin=PLUGIN, newton="on", dt=dt, temp=1.0e-4)
        text = text.replace(" yield 0.004 strength 0.006 friction 0.3", "")
        # the spheres' inertia 2/5 m R^2, which compute erotate/sphere counts
        text = text.replace("nve/sphere disc", "nve/sphere")
        return text.replace(f"plugin load {PLUGIN}\n", "")
    assert_falls_as_dt2(energy_error_spread(script))


# hot enough that links yield, break and rub (pvector: broken links, plastic and friction work);
# 3e-3 ran away (energy 12 times the initial by step 800, a known defect: see
# test_yield_with_strength_keeps_its_budget) and stops near step 200 with links beyond the list;
# 1.5e-3 stops before step 800 since plane strain's sigma_zz follows the plastic strain along z
HOT_TEMP = 0.75e-3
HOT = "compute pw all pair mca\nthermo 100\nthermo_style custom step pe c_pw[1] c_pw[5] c_pw[6]\n"
DUMP = ("write_dump all custom final.txt id xu yu zu omegaz modify sort id "
        "format float %.17g\n")


@pytest.mark.parametrize("newton", ["on", "off"])
def test_two_ranks_give_the_serial_run(tmp_path, newton):
    """A hot block whose links yield, break and rub: 2 ranks give the positions and spins of
    the serial newton-on run to 1e-10."""
    ref, par = tmp_path / "ref", tmp_path / "par"
    ref.mkdir()
    par.mkdir()
    out = run_lmp(ref, BLOCK_2D.format(plugin=PLUGIN, newton="on", dt=0.02, temp=HOT_TEMP) + HOT +
                  "run 800\n" + DUMP)
    run_lmp(par, BLOCK_2D.format(plugin=PLUGIN, newton=newton, dt=0.02, temp=HOT_TEMP) + HOT +
            "run 800\n" + DUMP, nprocs=2)
    broken, plastic, friction = thermo_rows(out)[-1][2:]
    assert broken > 1 and plastic > 0.0 and friction > 0.0
    a, b = positions(ref), positions(par)
    assert np.abs(a[:, 3]).max() == 0.0    # in the plane
    assert np.abs(a[:, 1:3] - b[:, 1:3]).max() < 1e-10
    assert np.abs(a[:, 4] - b[:, 4]).max() <= 1e-10 * np.abs(a[:, 4]).max()


def test_yield_with_strength_keeps_its_budget(tmp_path):
    """The hot 2d block with yield 0.004 E and strength 0.006 E: kinetic + rotational + pe +
    the pair's columns 3 to 6 stay at the initial energy within 1 % (measured 0.15 % over 600
    steps).  Before a broken link's contact kept its stress-free separation (28 Nov 2026) the
    contact measured from R_i + R_j pushed the elements of links shortened by plastic flow
    apart: +71 % by step 400, 2.5 times the initial energy by step 800."""
    out = run_lmp(tmp_path, BLOCK_2D.format(plugin=PLUGIN, newton="on", dt=0.02, temp=HOT_TEMP)
                  + "compute pw all pair mca\nthermo 100\nthermo_style custom step ke c_rot pe "
                  "c_pw[3] c_pw[4] c_pw[5] c_pw[6]\nthermo_modify norm no\nrun 400\n")
    rows = thermo_rows(out)
    total = rows[:, 1:].sum(axis=1)
    assert np.abs(total - total[0]).max() < 0.01 * total[0], total


def test_restart_continues_bit_identically(tmp_path):
    """write_restart after 400 steps, read_restart, 400 more: the same bits as one session
    (the plane and every pair's state travel)."""
    head = BLOCK_2D.format(plugin=PLUGIN, newton="on", dt=0.02, temp=HOT_TEMP)
    run_lmp(tmp_path, head + "run 400\nrun 400\n" + DUMP, name="in.straight")
    straight = positions(tmp_path)
    run_lmp(tmp_path, head + "run 400\nwrite_restart half.rst\n", name="in.first")
    run_lmp(tmp_path, f"plugin load {PLUGIN}\nread_restart half.rst\ncomm_modify vel yes\n"
            "neighbor 0.2 bin\nfix move all nve/sphere disc\nfix plane all enforce2d\n"
            "timestep 0.02\nrun 400\n" + DUMP, name="in.second")
    assert np.array_equal(straight, positions(tmp_path))


# two unit discs 0.1 apart (unlinked at the setup)
TWO_DISCS = ["units lj", "dimension 2", "atom_style sphere", "boundary p p p",
             "comm_modify vel yes", "region box block -5 5 -5 5 -0.5 0.5", "create_box 1 box",
             "create_atoms 1 single 0 0 0", "create_atoms 1 single 1.1 0 0",
             "set group all diameter 1.0", "neighbor 0.2 bin"]


def test_unlinked_pair_pushes_through_the_hexagon_side():
    """Two discs apart at the setup: no link; pushed together by 0.05 they repel with
    S_u a (r - 2R), S_u = 2 R / sqrt(3) (times the unit thickness), a = G / R."""
    r, g = 0.5, 0.4
    with session() as lmp:
        lmp.commands_list(TWO_DISCS + [
            "pair_style mca fraction 0.9 plane stress", f"pair_coeff 1 1 bulk 1.0 shear {g}",
            "run 0", "group two id 2", "displace_atoms two move -0.15 0 0 units box",
            "run 0"])
        f = lmp.numpy.extract_atom("f")[:2]
        assert f[0, 0] == pytest.approx(2.0 * r / math.sqrt(3.0) * (g / r) * (-0.05), rel=1e-9)
        assert f[0, 0] == pytest.approx(-f[1, 0], rel=1e-12) and f[0, 1] == 0.0


BOX_2D = ["units lj", "dimension 2", "atom_style sphere", "boundary p p p", "comm_modify vel yes",
          "region box block -5 5 -5 5 -0.5 0.5", "create_box 1 box", "create_atoms 1 single 0 0 0",
          "set group all diameter 1.0"]


@pytest.mark.parametrize("dim,style,coeff,message", [
    (2, "pair_style mca fraction 0.9", "pair_coeff 1 1 bulk 1 shear 1",
     "dimension 2 needs 'plane strain' or 'plane stress'"),
    (3, "pair_style mca fraction 0.7 plane strain", "pair_coeff 1 1 bulk 1 shear 1",
     "plane strain|stress is for dimension 2"),
    (2, "pair_style mca fraction 0.9 plane stress", "pair_coeff 1 1 shock 2.7 5.3 1.3 2 shear 1",
     "shock equation of state (pair_coeff ... shock) is three-dimensional"),
])
def test_dimension_errors(dim, style, coeff, message):
    with session() as lmp:
        cmds = list(BOX_2D) if dim == 2 else [c for c in BOX_2D if c != "dimension 2"]
        if dim == 3:
            cmds = [c.replace("-0.5 0.5", "-5 5") for c in cmds]
        lmp.commands_list(cmds + [style, coeff])
        with pytest.raises(Exception, match=message.replace("(", r"\(").replace(")", r"\)")
                           .replace("|", r"\|").replace(".", r"\.")):
            lmp.command("run 0")


@pytest.mark.parametrize("args,message", [
    ("fraction 0.9 plane flat", "plane must be strain or stress (got 'flat')"),
    ("fraction 0.9 plane", "plane needs a value"),
])
def test_plane_keyword_errors(args, message):
    with session() as lmp:
        lmp.commands_list(BOX_2D[:7])
        with pytest.raises(Exception, match=message.replace("(", r"\(").replace(")", r"\)")):
            lmp.command(f"pair_style mca {args}")


@pytest.mark.parametrize("units", ["lj", "si"])
@pytest.mark.parametrize("plane", ["strain", "stress"])
def test_element_stresses_are_plane_hooke(units, plane):
    """compute mca/atom on the strained triangular block: every element's sigma_xx, sigma_yy,
    sigma_xy are the plane's Hooke's law, sigma_zz is lambda tr(eps) = nu (sigma_xx +
    sigma_yy) in plane strain and 0 in plane stress, the volume column the disc's area / F."""
    r, e = SCALE[units]
    nu = 0.3
    eps = (1.0e-4, -5.0e-5)
    c11, c12 = in_plane(e, nu, plane)
    _, g, lam = moduli(e, nu)
    with session() as lmp:
        lmp.commands_list(triangular_block(units, plane, nu) + [
            "compute s all mca/atom", "run 0",
            f"change_box all x scale {1 + eps[0]!r} y scale {1 + eps[1]!r} remap", "run 0"])
        n = lmp.extract_global("nlocal")
        s = np.array(lmp.numpy.extract_compute("s", 1, 2)[:n])
        nktv2p = lmp.extract_global("nktv2p")
    sxx, syy = c11 * eps[0] + c12 * eps[1], c12 * eps[0] + c11 * eps[1]
    tol = 3e-4 * abs(sxx)    # the strain's second order
    assert np.allclose(s[:, 0] / nktv2p, sxx, rtol=0, atol=tol)
    assert np.allclose(s[:, 1] / nktv2p, syy, rtol=0, atol=tol)
    assert np.abs(s[:, 3]).max() < 1e-9 * e * nktv2p
    zz = lam * (eps[0] + eps[1]) if plane == "strain" else 0.0
    assert np.allclose(s[:, 2] / nktv2p, zz, rtol=0, atol=tol)
    if plane == "strain":
        assert np.allclose(s[:, 2], nu * (s[:, 0] + s[:, 1]), rtol=1e-12)
    assert np.allclose(s[:, 9], math.pi * r * r / TRIANGULAR, rtol=1e-12)


@pytest.mark.parametrize("plane", ["stress", "strain"])
def test_uniaxial_yield_plateau(plane):
    """A strip pulled slowly along x (free faces in y, damped) past yield Y: its interior's
    sigma_xx levels off at Y in plane stress (von Mises in uniaxial stress: exact), and in plane
    strain at J2 flow theory's incompressible limit, sigma_xx - sigma_yy = 2 Y / sqrt(3) with
    sigma_zz = (sigma_xx + sigma_yy) / 2 (sigma_zz = nu (sigma_xx + sigma_yy) - E eps_p,zz, the
    plastic strain along z by the flow rule; measured 1.1547 Y and 0.5 within 1e-4; the elastic
    estimate nu (sigma_xx + sigma_yy) of before read 1.130 Y).  Every interior element's
    equivalent stress is Y."""
    nu, y = 0.3, 0.002
    cmds = [c.replace("boundary p p p", "boundary p s p")
            for c in triangular_block("lj", plane, nu, nx=12, ny=6)]
    cmds[-1] += f" yield {y}"
    with session() as lmp:
        lmp.commands_list(cmds + [
            "compute s all mca/atom", "fix move all nve/sphere disc", "fix 2d all enforce2d",
            "fix damp all viscous/relative gamma 0.5", "timestep 0.05",
            "fix pull all deform 1 x erate 2e-5 remap x", "run 10000"])
        n = lmp.extract_global("nlocal")
        s = np.array(lmp.numpy.extract_compute("s", 1, 2)[:n])
        height = np.array(lmp.numpy.extract_atom("x")[:n])[:, 1]
    inner = (height > height.min() + 1.5) & (height < height.max() - 1.5)
    sxx, syy, szz = (s[inner, k].mean() for k in range(3))
    if plane == "stress":
        assert sxx == pytest.approx(y, rel=0.01)
    else:
        assert sxx - syy == pytest.approx(2.0 * y / math.sqrt(3.0), rel=1e-3)
        assert szz == pytest.approx(0.5 * (sxx + syy), rel=0.01)
    assert abs(syy) < 0.01 * y
    assert np.allclose(s[inner, 7], y, rtol=5e-3)


def test_two_discs_weld_and_then_hold_in_tension():
    """Two unlinked discs pushed together until the contact's stress reaches the weld
    pressure (overlap 0.06: 0.048) link where they are (pvector 2 counts one), and pulled back
    apart they pull on each other (a link), where before they did not."""
    with session() as lmp:
        lmp.commands_list(TWO_DISCS + [
            "pair_style mca fraction 0.9 plane strain",
            "pair_coeff 1 1 bulk 1.0 shear 0.4 weld 0.03", "compute pw all pair mca",
            "run 0", "group two id 2",
            "displace_atoms two move -0.13 0 0 units box", "run 0"])
        # overlap 0.03: the contact's stress a 0.03 = 0.024 (a = G / R = 0.8) is below 0.03
        assert lmp.extract_compute("pw", 0, 1)[1] == 0.0
        lmp.commands_list(["displace_atoms two move -0.03 0 0 units box", "run 0"])
        formed = lmp.extract_compute("pw", 0, 1)[1]
        lmp.commands_list(["displace_atoms two move 0.2 0 0 units box", "run 0"])
        f = np.array(lmp.numpy.extract_atom("f")[:2])
    assert formed == 1.0
    assert f[0, 0] > 0.0 and f[1, 0] < 0.0    # pulled towards each other


@pytest.mark.parametrize("units", ["lj", "si"])
def test_dimer_damages_and_unloads_along_the_secant(units):
    """A linked pair of discs (Z = 1: its contact S = 2 Omega / R, Omega = pi R^2 / F; many-
    body term off) pulled past sigma_d carries S g(a e) (the response's parabola g, type b),
    and brought back to a smaller elongation S (g(kappa) / kappa) a e (the secant)."""
    r, e_mod = SCALE[units]
    g_mod = e_mod / 2.6
    sc, sd = 0.01 * e_mod, 0.005 * e_mod
    fraction = 0.9
    s_area = 2.0 * (math.pi * r * r / fraction) / r
    a = g_mod / r    # the halves 2G/R in series
    with session() as lmp:
        lmp.commands_list([
            f"units {units}", "dimension 2", "atom_style sphere", "boundary f f p",
            "comm_modify vel yes", f"region box block {-5 * r!r} {5 * r!r} {-5 * r!r} {5 * r!r} "
            f"{-0.5 * r!r} {0.5 * r!r}", "create_box 1 box",
            "create_atoms 1 single 0 0 0 units box",
            f"create_atoms 1 single {2 * r!r} 0 0 units box", f"set group all diameter {2 * r!r}",
            f"neighbor {0.2 * r!r} bin",
            f"pair_style mca fraction {fraction} manybody no plane stress",
            f"pair_coeff 1 1 young {e_mod!r} poisson 0.3 strength {sc!r} damage {sd!r}",
            "run 0", "group two id 2"])
        nktv2p = lmp.extract_global("nktv2p")

        def pull_to(elong):
            x = lmp.numpy.extract_atom("x")
            lmp.command(f"displace_atoms two move {2 * r + elong - x[1, 0] + x[0, 0]!r} 0 0 "
                        "units box")
            # steps without an integrator: a setup only re-evaluates (it changes no state); the
            # first step damages, the second transmits the damaged stress
            lmp.command("run 2")
            return float(lmp.numpy.extract_atom("f")[0, 0])

        e1 = 1.5 * sd / a
        f1 = pull_to(e1)
        e2 = 0.5 * e1
        f2 = pull_to(e2)
    kappa = a * e1
    u = 1.0 - (kappa - sd) / (2.0 * (sc - sd))
    g = sc - (sc - sd) * u * u
    assert f1 == pytest.approx(s_area * g / nktv2p, rel=1e-9)
    assert f2 == pytest.approx(s_area * g / kappa * a * e2 / nktv2p, rel=1e-9)
