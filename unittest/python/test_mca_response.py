"""pair_style mca beyond elasticity (issue 27): damage, breaking, von Mises plasticity,
friction and welding of unlinked contacts, and the energy budget.

Oracles: the closed form of a damaged linked dimer (the parabolic envelope and the secant
unloading of mca_response.h, written with nktv2p in two unit styles); a viscous contact's
force eta S v_t; a block on an incline, a = g (sin theta - mu cos theta); the yield stress of a
von Mises solid under uniaxial stress (LAMMPS's own pressure tensor); the conservation of
kinetic + potential + dissipated energy; serial against MPI runs; a straight run against a
restarted one."""
import math

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp, session
from lammps import LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR
from test_pair_mca import SCALE, Dimer, dimer, forces


def tally(lmp, name="pp"):
    return np.array([lmp.extract_compute(name, LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR)[k]
                     for k in range(6)])


# ---------------------------------------------------------------- damage (type b)

def envelope(s, sc, sd):
    """the transmitted equivalent stress at effective stress s (mca_response.h)"""
    if s <= sd:
        return s
    u = 1.0 - (s - sd) / (2.0 * (sc - sd))
    return sc - (sc - sd) * u * u


@pytest.mark.parametrize("units", ["lj", "si"])
def test_damaged_dimer_follows_the_envelope_and_unloads_on_the_secant(units):
    """A linked dimer (no volumetric term) pulled beyond sigma_d: its force is S g(a delta)
    (the parabola from sigma_d to the peak sigma_c); pulled back it unloads along the secant
    S g(a delta_max) / delta_max (the damaged modulus at the strain reached); pulled past
    2 sigma_c - sigma_d it breaks, with the energy it held tallied."""
    radius, g = SCALE[units]
    k = 2.5 * g
    sc, sd = 1.0e-3 * g, 0.6e-3 * g
    with session() as lmp:
        dimer(lmp, units, radius, (k, g), manybody="no",
              extra=[f"pair_coeff 1 1 bulk {k} shear {g} strength {sc} damage {sd}",
                     "compute pp all pair mca", "group two id 2"])
        nktv2p = lmp.extract_global("nktv2p")
        ref = Dimer(radius, k, g, nktv2p, manybody=False)
        per_delta = ref.a * nktv2p             # effective stress per unit elongation (pressure)

        def pull_to(delta, at):
            lmp.commands_list([f"displace_atoms two move {delta - at} 0 0 units box",
                               "run 0", "run 0"])   # the second sees the damage of the first
            return forces(lmp)[0][0, 0]

        at = 0.0
        for s_eff in (0.5 * sd, 1.2 * sd, 0.9 * sc, 1.1 * sc):
            delta = s_eff / per_delta
            force = pull_to(delta, at)
            at = delta
            assert force == pytest.approx(ref.S * envelope(s_eff, sc, sd) / nktv2p, rel=1e-9)
        secant = ref.S * envelope(1.1 * sc, sc, sd) / nktv2p / at
        delta_max = at
        force = pull_to(0.5 * delta_max, at)
        assert force / (0.5 * delta_max) == pytest.approx(secant, rel=1e-9)
        assert secant < ref.S * ref.a                          # softer than intact
        assert tally(lmp)[3] > 0.0                             # damage dissipated
        force = pull_to(1.01 * (2 * sc - sd) / per_delta, 0.5 * delta_max)
        assert force == 0.0 and tally(lmp)[0] == 1


# ---------------------------------------------------------------- friction

@pytest.mark.parametrize("units", ["lj", "si"])
def test_viscous_contact_force(units):
    """Two unlinked elements pressed together, one sliding past the other at v_t (no spin):
    the tangential force is eta S_u v_t (S_u = sqrt(2) R^2 for equal radii), in pressure x
    area units of each style; its power is tallied as friction."""
    radius, g = SCALE[units]
    eta = 0.37 * g                          # pressure / velocity (velocity units of the style)
    with session() as lmp:
        dimer(lmp, units, radius, (2.5 * g, g), gap=-1.0e-3 * radius,
              extra=["pair_coeff 1 1 link no", f"pair_coeff 1 1 bulk {2.5 * g} shear {g} "
                     f"viscous {eta}", "compute pp all pair mca", "group two id 2",
                     "velocity two set 0 1.0 0 units box"])
        lmp.command("run 0")
        f, _ = forces(lmp)
        nktv2p = lmp.extract_global("nktv2p")
        vy = np.array(lmp.gather_atoms("v", 1, 3)).reshape(-1, 3)
        vt = vy[1, 1] - vy[0, 1]
        expect = eta / nktv2p * math.sqrt(2.0) * radius ** 2 * vt
        assert f[0, 1] == pytest.approx(expect, rel=1e-6)
        assert f[1, 1] == pytest.approx(-expect, rel=1e-6)


INCLINE = """
units lj
atom_style sphere
boundary f f f
comm_modify vel yes
region box block -30 30 -30 30 -1.02e4 20
create_box 2 box
lattice fcc $(sqrt(2.0))
region blk block 0 2 0 2 0 2
create_atoms 1 region blk
set type 1 diameter 1.0
variable zb equal bound(all,zmin)
displace_atoms all move 0 0 $(-v_zb+0.5) units box
create_atoms 2 single $(xcm(all,x)) $(xcm(all,y)) -1.0e4 units box
set type 2 diameter 2.0e4
variable phi equal PI/sqrt(18.0)
pair_style mca fraction ${{phi}}
pair_coeff 1 1 young 1.0 poisson 0.3 friction {mu}
pair_coeff 2 2 young 1.0e4 poisson 0.3 friction {mu}
pair_coeff 1 2 link no
set type 1 density $(1.0/v_phi)
neighbor 0.2 nsq
neigh_modify one 10000 page 200000
group block type 1
timestep 0.02
fix move block nve/sphere
fix down block gravity 5.0e-4 vector 0 0 -1
fix settle block viscous 0.2
compute pp all pair mca
variable vx equal vcm(block,x)
variable x equal xcm(block,x)
run 3000
unfix settle
unfix down
variable th equal {theta}*PI/180
"""


def incline(theta, mu, hold):
    """a 2 x 2 x 2 fcc cell block resting on a nearly flat (R = 1e4) rigid element, gravity
    tilted by theta; returns (times, velocities) of the block's hold phase"""
    with session() as lmp:
        lmp.commands_list(INCLINE.format(mu=mu, theta=theta).strip().splitlines())
        # tilt within 2000 steps (a sudden tilt overshoots the static friction)
        lmp.commands_list([
            "variable ramp equal ramp(0,1)",
            "variable gx equal sin(v_th*v_ramp)", "variable gz equal -cos(v_th*v_ramp)",
            "fix tilt block gravity 5.0e-4 vector v_gx 0 v_gz", "run 2000",
            "unfix tilt", "fix tilt block gravity 5.0e-4 vector $(sin(v_th)) 0 $(-cos(v_th))"])
        x0 = lmp.extract_variable("x")
        t, v = [], []
        for step in range(hold // 100):
            lmp.command("run 100")
            t.append(0.02 * 100 * (step + 1))
            v.append(lmp.extract_variable("vx"))
        return np.array(t), np.array(v), lmp.extract_variable("x") - x0, tally(lmp)


def test_block_on_an_incline_stays_below_mu():
    """tan(theta) = 0.8 mu: the block stays (its centre moves less than 1e-3 element
    diameters in 4000 steps, against 0.3 diameters slid at tan(theta) = 1.5 mu)."""
    mu = 0.3
    _, v, moved, _ = incline(math.degrees(math.atan(0.8 * mu)), mu, 4000)
    assert abs(moved) < 1.0e-3 and np.abs(v).max() < 1.0e-4


def test_block_on_an_incline_slides_at_g_sin_minus_mu_cos():
    """tan(theta) = 1.5 mu: the block slides with a = g (sin theta - mu cos theta) within 2 %
    (the slope of its velocity history); the friction work is tallied."""
    mu = 0.3
    theta = math.degrees(math.atan(1.5 * mu))
    t, v, moved, work = incline(theta, mu, 3000)
    slope = np.polyfit(t[5:], v[5:], 1)[0]
    th = math.radians(theta)
    expect = 5.0e-4 * (math.sin(th) - mu * math.cos(th))
    assert slope == pytest.approx(expect, rel=0.02), (slope, expect)
    assert moved > 0.1 and work[5] > 0.0


# ---------------------------------------------------------------- plasticity

# the periodic blocks of the plasticity tests: units, element diameter d, modulus E, time scale
BLOCK_HEAD = """
units {units}
atom_style sphere
boundary p p p
comm_modify vel yes
variable d equal {d}
variable E equal {E}
variable tau equal {tau}
"""
PLASTIC_BLOCK = BLOCK_HEAD + """variable M equal {rho}*v_d^3
{lattice}
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
set group all diameter ${{d}}
variable phi equal PI/sqrt(18.0)
pair_style mca fraction ${{phi}}
pair_coeff 1 1 young ${{E}} poisson 0.3 yield $({Y}*v_E) hardening $({H}*v_E)
set group all density $({rho}/v_phi)
neighbor $(0.2*v_d) bin
timestep $(0.02*v_tau)
fix move all nve/sphere
fix damp all viscous $(0.5*v_M/v_tau)
compute pp all pair mca
run 0
variable lx0 equal $(lx)
variable ly0 equal $(ly)
variable ex equal ln(lx/v_lx0)
variable ey equal ln(ly/v_ly0)
variable sxx equal pxx/v_E
variable syy equal pyy/v_E
fix lat all press/berendsen y 0 0 $(0.5*v_tau) z 0 0 $(0.5*v_tau) couple none modulus ${{E}} dilate all
fix squeeze all deform 1 x erate $(-1.0e-4/v_tau) remap x
"""
# units lj: diameter, E and density 1; units si: aluminium-like elements of 10 um (time
# scale d sqrt(rho / E)); the yield stress and hardening modulus are given in units of E
BLOCK_UNITS = {
    "lj": dict(units="lj", d=1.0, E=1.0, rho=1.0, tau=1.0, lattice="lattice fcc $(sqrt(2.0))"),
    "si": dict(units="si", d=1.0e-5, E=7.0e10, rho=2700.0, tau=1.0e-5 * math.sqrt(2700.0 / 7.0e10),
               lattice="lattice fcc $(sqrt(2.0)*v_d)"),
}


# a periodic block of 3 x 3 x 3 fcc cells of a material (response: its words after young and
# poisson)
SMALL_BLOCK = BLOCK_HEAD + """{lattice}
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
set group all diameter ${{d}}
variable phi equal PI/sqrt(18.0)
pair_style mca fraction ${{phi}} tolerance 0.02
pair_coeff 1 1 young ${{E}} poisson 0.3 {response}
set group all density $({rho}/v_phi)
"""
# the block hot (velocities of 0.08 sqrt(E / rho) per component), its thermal stresses passing a
# yield stress of 0.01 E many times over: its elements flow at random, in tension and in
# compression, next to elements that do not
HOT_BLOCK = SMALL_BLOCK + """variable vs equal 0.08*v_d/v_tau
variable vx atom normal(0,${{vs}},4711)
variable vy atom normal(0,${{vs}},4712)
variable vz atom normal(0,${{vs}},4713)
velocity all set v_vx v_vy v_vz units box
velocity all zero linear
neighbor $(0.2*v_d) bin
timestep $({dt}*v_tau)
fix move all nve/sphere
compute pp all pair mca
compute rot all erotate/sphere
variable etot equal ke+c_rot+pe+c_pp[5]
thermo_modify norm no
"""


@pytest.mark.parametrize("units", ["lj", "si"])
def test_hot_block_yielding_at_random_keeps_its_energy_budget(units):
    """The hot block at yield 0.01 E over 10 time units (d sqrt(rho / E)): 96 % of its energy
    flows into plastic work, which never falls, and kinetic + potential + plastic work stays at
    the initial energy within 1 % of the work (measured 0.0040 % at dt 0.02, 0.00019 % at 0.01,
    0.00078 % at 0.005; 0.20 %, 0.10 %, 0.05 % before the many-body lag's share).  Before the return about the pairs' own weighted mean and the trapezoid rule of the
    plastic work (28 Nov 2026) the plastic work fell to -3.7e3 and the run stopped."""
    errors = []
    for dt in (0.02, 0.01):
        with session() as lmp:
            lmp.commands_list(HOT_BLOCK.format(response="yield $(0.01*v_E)", dt=dt,
                                               **BLOCK_UNITS[units])
                              .strip().splitlines())
            lmp.command("run 0")
            e0 = lmp.extract_variable("etot")
            works = []
            for _ in range(50):
                lmp.command(f"run {round(0.2 / dt)} pre no post no")
                works.append(tally(lmp)[4])
            e1 = lmp.extract_variable("etot")
        assert works[-1] > 0.9 * e0                       # most of the energy flowed away
        assert np.all(np.diff(works) >= 0.0), works
        errors.append(abs(e1 - e0) / works[-1])
    assert errors[0] < 0.01, errors
    assert errors[1] < 0.7 * errors[0], errors


@pytest.mark.parametrize("units", ["lj", "si"])
def test_hot_block_yielding_and_breaking_keeps_its_energy_budget(units):
    """The hot block at yield 0.01 E with a strength of 0.015 E, over 6 time units: links flow
    and break (most of its energy goes into plastic work and broken links); kinetic + potential
    + plastic work + the broken links' energy (column 3) stays at the initial energy within 1 %
    and closer at half the step (the breaks' one-step lag: first order; measured 0.48 %, 0.21 %,
    0.11 % at dt 0.02, 0.01, 0.005 in lj and si).  Before a broken link's contact kept its
    stress-free separation (28 Nov 2026) the contact measured from R_i + R_j pushed the
    elements of links shortened by plastic flow apart: the block gained 30 % of its energy at
    dt 0.02 and 32 % at 0.01."""
    errors = []
    for dt in (0.02, 0.01):
        with session() as lmp:
            lmp.commands_list(HOT_BLOCK.format(response="yield $(0.01*v_E) strength $(0.015*v_E)",
                                               dt=dt, **BLOCK_UNITS[units])
                              .strip().splitlines())
            lmp.command("neighbor $(0.6*v_d) bin")    # links flow beyond 0.2 d before they break
            lmp.command("variable books equal v_etot+c_pp[3]")
            lmp.command("run 0")
            e0 = lmp.extract_variable("books")
            lmp.command(f"run {round(6.0 / dt)} pre no post no")
            e1 = lmp.extract_variable("books")
            broken, work = tally(lmp)[0], tally(lmp)[4]
        assert broken > 50 and work > 0.3 * e0, (broken, work, e0)
        errors.append(abs(e1 - e0) / e0)
    assert errors[0] < 0.01, errors
    assert errors[1] < 0.7 * errors[0], errors


@pytest.mark.parametrize("units", ["lj", "si"])
def test_plastic_work_never_falls_from_one_step_to_the_next(units):
    """The hot block at yield 0.01 E, step by step over its first 200 steps (where the flow
    starts, in tension and in compression at once): the pair's plastic-work column never falls
    (each pair's return does work S sigma dp >= 0 about its elements' weighted mean)."""
    with session() as lmp:
        lmp.commands_list(HOT_BLOCK.format(response="yield $(0.01*v_E)", dt=0.02,
                                           **BLOCK_UNITS[units]).strip().splitlines())
        lmp.command("run 0")
        works = []
        for _ in range(200):
            lmp.command("run 1 pre no post no")
            works.append(tally(lmp)[4])
    works = np.array(works)
    assert works[-1] > 0.0
    assert np.diff(works).min() >= 0.0, np.diff(works).min()


@pytest.mark.parametrize("units", ["lj", "si"])
def test_plastic_work_never_falls_between_two_materials(units):
    """The hot block of two materials at random (the second three times as stiff, a_j = 3 a_i
    in its pairs with the first), both yielding at 0.01 E, step by step over 200 steps: the
    plastic-work column never falls, and kinetic + potential + plastic work stays within 1 %
    of the work (the mean each element's pairs return about weighs a pair by its partner's
    share of the stiffness, a_j / (a_i + a_j), so that one phi keeps theta)."""
    text = HOT_BLOCK.format(response="yield $(0.01*v_E)", dt=0.02, **BLOCK_UNITS[units])
    text = text.replace("create_box 1 box", "create_box 2 box").replace(
        "create_atoms 1 box", "create_atoms 1 box\nset type 1 type/fraction 2 0.5 4714")
    text = text.replace("pair_coeff 1 1 young ${E} poisson 0.3 yield $(0.01*v_E)",
                        "pair_coeff 1 1 young ${E} poisson 0.3 yield $(0.01*v_E)\n"
                        "pair_coeff 2 2 young $(3*v_E) poisson 0.3 yield $(0.01*v_E)")
    assert "pair_coeff 2 2" in text and "type/fraction" in text
    with session() as lmp:
        lmp.commands_list(text.strip().splitlines())
        lmp.command("run 0")
        e0 = lmp.extract_variable("etot")
        works = []
        for _ in range(200):
            lmp.command("run 1 pre no post no")
            works.append(tally(lmp)[4])
        e1 = lmp.extract_variable("etot")
    works = np.array(works)
    assert works[-1] > 0.5 * e0
    assert np.diff(works).min() >= 0.0, np.diff(works).min()
    assert abs(e1 - e0) < 0.01 * works[-1], (e0, e1, works[-1])


TWO_MATERIAL_SQUEEZE = BLOCK_HEAD + """variable M equal {rho}*v_d^3
{lattice}
region box block 0 3 0 3 0 3
create_box 2 box
create_atoms 1 box
set type 1 type/fraction 2 0.5 4714
set group all diameter ${{d}}
variable phi equal PI/sqrt(18.0)
pair_style mca fraction ${{phi}} tolerance 0.02
pair_coeff 1 1 young ${{E}} poisson 0.3 {response}
pair_coeff 2 2 young $(3*v_E) poisson 0.3 {response}
set group all density $({rho}/v_phi)
neighbor $(0.3*v_d) bin
timestep $(0.02*v_tau)
fix move all nve/sphere
fix damp all viscous $(0.5*v_M/v_tau)
fix squeeze all deform 1 x erate $(-1.0e-4/v_tau) remap x
thermo_style custom step press
"""


@pytest.mark.parametrize("units", ["lj", "si"])
def test_plastic_flow_between_two_materials_keeps_the_pressure(units):
    """A block of two materials at random (the second three times as stiff) squeezed along x in
    uniaxial strain to 4 %, far past yield (0.01 E): its pressure stays within 6 % of the same
    block's without yield at 1, 2, 3, 4 % (measured 2.6-4.1 % below), since a return about each
    element's mean weighted by the partner's share of the stiffness, a_j / (a_i + a_j), keeps
    the element's volumetric strain theta (with each element's own share, a_i / (a_i + a_j),
    the flow compacts: 4.8-8.9 % below)."""
    press = {}
    for response in ("", "yield $(0.01*v_E)"):
        with session() as lmp:
            lmp.commands_list(TWO_MATERIAL_SQUEEZE.format(response=response, **BLOCK_UNITS[units])
                              .strip().splitlines())
            press[response] = []
            for _ in range(4):
                lmp.command("run 5000")
                press[response].append(lmp.get_thermo("press"))
    ratio = np.array(press["yield $(0.01*v_E)"]) / np.array(press[""])
    assert len(ratio) == 4 and np.all(ratio > 0.94) and np.all(ratio < 1.0), ratio


def locked_lateral(ex, elastic):
    """The lateral log strain ey of an fcc block (x along [100]) stretched by ex whose pairs'
    relative elongations sum to `elastic` (their elastic part): the return keeps the plastic
    elongations' sum at zero, and a lattice whose links persist deforms affinely, so its 8
    pairs at 45 degrees to x and its 4 across change their lengths by
    sqrt((lx^2 + ly^2) / 2) - 1 and ly - 1 (bisection)."""
    def total(ey):
        lx, ly = math.exp(ex), math.exp(ey)
        return 8.0 * (math.sqrt(0.5 * (lx * lx + ly * ly)) - 1.0) + 4.0 * (ly - 1.0) - elastic
    lo, hi = -0.5, 0.5
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if total(mid) < 0.0 else (lo, mid)
    return 0.5 * (lo + hi)


@pytest.mark.parametrize("units,hardening", [("lj", 0.0), ("lj", 0.1), ("si", 0.0)])
def test_plastic_block_yields_at_sigma_y(units, hardening):
    """A periodic fcc block (E 1, nu 0.3, yield 0.005) compressed along x at a strain rate of
    1e-4, its sides held stress free (fix press/berendsen; in lj and in si units with the
    stresses in units of E): the flow stress by LAMMPS's
    pressure tensor is the yield stress within 3 % (perfectly plastic) or Y + H' eps_p with
    the hardening; plastic work is tallied.  The incremental Poisson ratio in the plateau is
    that of the linked lattice's kinematics (locked_lateral, 0.44 at 5 % strain; with the
    elastic strains of a hardening flow stress), not the 0.5 of an isochoric flow:
    doc/pair_mca.rst, plasticity."""
    y = 0.005
    with session() as lmp:
        lmp.commands_list(PLASTIC_BLOCK.format(Y=y, H=hardening, **BLOCK_UNITS[units])
                          .strip().splitlines())
        rows = []
        for _ in range(12):
            lmp.command("run 2000")
            rows.append([lmp.extract_variable(n) for n in ("ex", "ey", "sxx", "syy")])
        work = tally(lmp)
        lmp.commands_list(["compute ep all property/atom d_mca_plastic_strain",
                           "compute epm all reduce ave c_ep", "run 0"])
        eps_p = lmp.extract_compute("epm", LMP_STYLE_GLOBAL, 0)
    ex, ey, sxx, syy = np.array(rows).T
    flow = sxx - syy            # compression positive: the von Mises stress of (sxx, syy, syy)
    if hardening == 0.0:
        assert np.abs(flow[3:] / y - 1.0).max() < 0.03, flow
        assert np.abs(sxx[3:] / y - 1.0).max() < 0.03, sxx
    else:
        assert np.all(np.diff(flow[3:]) > 0.0)           # it hardens
    nu_inc = -(ey[-1] - ey[-5]) / (ex[-1] - ex[-5])
    # the pairs' elongations sum to their elastic part: 4 times the elastic volumetric strain
    # -(1 - 2 nu) sxx of the flow stress (sxx in units of E, compression positive; nu 0.3),
    # which changes only with hardening
    lateral = [locked_lateral(ex[k], -4.0 * 0.4 * sxx[k]) for k in (-5, -1)]
    predicted = -(lateral[1] - lateral[0]) / (ex[-1] - ex[-5])
    assert nu_inc == pytest.approx(predicted, abs=0.01), (nu_inc, predicted)
    assert work[4] > 0.0
    # the elements' equivalent plastic strain (per-atom property): for a uniaxial isochoric
    # flow it equals the axial plastic strain
    assert 0.5 * abs(ex[-1]) < eps_p < 1.5 * abs(ex[-1]), (eps_p, ex[-1])


# a perfect periodic block, linked unstrained, then stretched along x at once (all its elements
# alike): one radial return of each element's stress
RETURN_BLOCK = SMALL_BLOCK + """neighbor $(0.2*v_d) bin
timestep $(1.0e-6*v_tau)
fix move all nve/sphere
compute s all mca/atom
compute seq all reduce ave c_s[8]
thermo_style custom step c_seq
run 0
change_box all x scale 1.003 remap
run 1
"""


@pytest.mark.parametrize("units", ["lj", "si"])
def test_one_return_reaches_the_hardened_yield_surface(units):
    """A block stretched at once past its yield stress Y with hardening H = E: the return map
    of doc/pair_mca.rst, d eps_p = (sigma_int - Y) / (3G + H) from the elastic trial stress
    (the same block without yield), read by the per-element property, and the stress intensity
    after it, Y + H d eps_p, read by compute mca/atom."""
    u = BLOCK_UNITS[units]
    e_mod, y, h = u["E"], 0.001 * u["E"], 1.0 * u["E"]
    g = e_mod / 2.6
    with session() as lmp:
        lmp.commands_list(RETURN_BLOCK.format(response="", **u).strip().splitlines())
        trial = lmp.extract_compute("seq", LMP_STYLE_GLOBAL, 0)
    with session() as lmp:
        lmp.commands_list(RETURN_BLOCK.format(response=f"yield {y} hardening {h}", **u)
                          .strip().splitlines())
        after = lmp.extract_compute("seq", LMP_STYLE_GLOBAL, 0)
        lmp.commands_list(["compute ep all property/atom d_mca_plastic_strain",
                           "compute epm all reduce ave c_ep", "run 0"])
        eps_p = lmp.extract_compute("epm", LMP_STYLE_GLOBAL, 0)
    deps = (trial - y) / (3.0 * g + h)
    assert trial > 1.5 * y
    # within 1 %: the areas make sum_j q S n n = Omega I on the unstrained lattice, so that the
    # mean stress's part of Love's sum is isotropic there only; stretched by 0.3 %, it is not
    # to O(strain) (measured 0.3 and 0.5 %: the returned stress lies that far off the surface,
    # and the next evaluation returns it the rest of the way); without the hardening of the
    # step the intensity would read Y, 36 % less
    assert eps_p == pytest.approx(deps, rel=0.01), (eps_p, deps)
    assert after == pytest.approx(y + h * deps, rel=0.01), (after, y, h * deps)


# ---------------------------------------------------------------- welding, bad input

def weld_dimer(lmp, units):
    """An unlinked dimer (0.05 R apart at the first setup) of a material that welds at 0.01 G;
    the overlap at which its contact's stress a |overlap| (a = G / R for equal elements)
    reaches the weld stress.  Group two: the second element."""
    radius, g = SCALE[units]
    k = 2.5 * g
    weld = 0.01 * g
    dimer(lmp, units, radius, (k, g), gap=0.05 * radius,
          extra=[f"pair_coeff 1 1 bulk {k} shear {g} weld {weld}", "compute pp all pair mca",
                 "group two id 2"])
    return weld / g * radius


@pytest.mark.parametrize("units", ["lj", "si"])
def test_pressed_contact_welds_and_then_holds_tension(units):
    """An unlinked dimer (apart at the first setup) pushed together until its pressure passes
    the weld stress (pressure units of each style) links (one link formed); short of it, it
    does not; welded, it holds in tension."""
    radius, _ = SCALE[units]
    with session() as lmp:
        overlap = weld_dimer(lmp, units)
        lmp.commands_list([f"displace_atoms two move {-0.05 * radius - 0.9 * overlap} 0 0 "
                           "units box", "run 0"])
        assert tally(lmp)[1] == 0
        lmp.commands_list([f"displace_atoms two move {-0.2 * overlap} 0 0 units box", "run 0"])
        assert tally(lmp)[1] == 1
        lmp.commands_list([f"displace_atoms two move {0.05 * radius + 1.1 * overlap} 0 0 "
                           "units box", "run 0"])
        f, _ = forces(lmp)
        assert f[0, 0] > 0.0                     # pulled towards the partner: linked


@pytest.mark.parametrize("units", ["lj", "si"])
def test_a_weld_tallies_the_many_body_energy_it_makes(units):
    """A dimer of a material that only welds (no strength, no yield) pressed past its weld
    stress: the weld links the pair where it is, so the pair's energy does not jump, but the
    link's volumetric strain gives its elements lambda Omega theta^2 / 2 each; that jump of pe
    is tallied as the energy of the changes (pvector[3], released: minus the jump)."""
    radius, _ = SCALE[units]
    with session() as lmp:
        overlap = 1.2 * weld_dimer(lmp, units)
        lmp.commands_list([f"displace_atoms two move {-0.05 * radius - overlap} 0 0 units box",
                           "run 0"])
        pe_contact = lmp.get_thermo("pe")
        assert tally(lmp)[1] == 1                # welded in this evaluation
        lmp.command("run 0")
        jump = lmp.get_thermo("pe") - pe_contact
        released = tally(lmp)[2]
    assert jump > 0.0
    assert -released == pytest.approx(jump, rel=1e-9), (released, jump)


@pytest.mark.parametrize("coeff,message", [
    ("bulk 1 shear 1 damage 0.5", "damage"),
    ("bulk 1 shear 1 strength 0.4 damage 0.5", "damage"),
    ("bulk 1 shear 1 hardening 0.1", "hardening needs yield"),
    ("bulk 1 shear 1 friction -0.1", "friction"),
    ("bulk 1 shear 1 viscous abc", "viscous"),
    ("bulk 1 shear 1 weld 0", "weld"),
    ("bulk 1 shear 1 yield", "yield needs a value"),
    ("link maybe", "link must be yes or no"),
])
def test_bad_response_input(coeff, message):
    with session() as lmp:
        lmp.commands_list(["units lj", "atom_style sphere", "region b block 0 4 0 4 0 4",
                           "create_box 1 b", "pair_style mca fraction 0.7"])
        with pytest.raises(Exception, match=message):
            lmp.command(f"pair_coeff 1 1 {coeff}")


def test_the_plastic_strains_fix_id_is_reserved():
    """A fix of the user's own on the ID the style keeps its per-element plastic strain in:
    an error naming it at the run, not a crash."""
    with session() as lmp:
        lmp.commands_list(["units lj", "atom_style sphere", "region b block 0 4 0 4 0 4",
                           "create_box 1 b", "create_atoms 1 single 1 1 1",
                           "set group all diameter 1.0", "comm_modify vel yes",
                           "fix MCA_PLASTIC_STRAIN all property/atom i_mine",
                           "pair_style mca fraction 0.7",
                           "pair_coeff 1 1 bulk 1 shear 1 yield 0.01"])
        with pytest.raises(Exception, match="MCA_PLASTIC_STRAIN is not the per-element plastic"):
            lmp.command("run 0")


@pytest.mark.parametrize("units", ["lj", "si"])
def test_a_material_that_no_longer_yields_flows_no_more(units):
    """pair_coeff given again without yield replaces the material: the block stretched past
    the old yield stress returns nothing (its plastic strain stays 0; the plastic pass is off)
    and reads the elastic block's stress to round-off."""
    u = BLOCK_UNITS[units]
    y = 0.001 * u["E"]
    with session() as lmp:
        lmp.commands_list(RETURN_BLOCK.format(response="", **u).strip().splitlines())
        elastic = lmp.extract_compute("seq", LMP_STYLE_GLOBAL, 0)
    with session() as lmp:
        script = RETURN_BLOCK.format(response=f"yield {y}", **u).strip().splitlines()
        stretch = script.index("change_box all x scale 1.003 remap")
        lmp.commands_list(script[:stretch])
        lmp.command(f"pair_coeff 1 1 young {u['E']} poisson 0.3")
        lmp.commands_list(script[stretch:] + ["compute ep all property/atom d_mca_plastic_strain",
                                              "compute epm all reduce max c_ep", "run 0"])
        again = lmp.extract_compute("seq", LMP_STYLE_GLOBAL, 0)
        eps_p = lmp.extract_compute("epm", LMP_STYLE_GLOBAL, 0)
    assert elastic > 1.5 * y
    assert eps_p == 0.0
    assert again == pytest.approx(elastic, rel=1e-12)


# ---------------------------------------------------------------- fracture runs

FRACTURE = """
units lj
atom_style sphere
boundary s s s
comm_modify vel yes
newton {newton}
lattice fcc $(sqrt(2.0))
region box block 0 {length} 0 4 0 4
create_box 1 box
create_atoms 1 box
reset_atoms id sort yes
set group all diameter 1.0
variable phi equal PI/sqrt(18.0)
pair_style mca fraction ${{phi}} tolerance 0.02
pair_coeff 1 1 young 1.0 poisson 0.3 strength 0.01 damage 0.006 friction 0.3 viscous 0.05
set group all density $(1.0/v_phi)
neighbor 0.2 bin
timestep 0.02
fix move all nve/sphere
compute pp all pair mca
compute rot all erotate/sphere
variable etot equal ke+c_rot+pe+c_pp[3]+c_pp[4]+c_pp[5]+c_pp[6]
thermo_style custom step ke c_rot pe c_pp[1] c_pp[3] c_pp[4] c_pp[6] v_etot
thermo_modify norm no
velocity all ramp vx -0.03 0.03 x $(xlo) $(xhi) sum yes units box
velocity all create 1.0e-6 4711 loop geom sum yes
thermo 250
"""
DUMP = ("write_dump all custom final.txt id x y z omegax omegay omegaz modify sort id "
        "format float %.17g\n")


def final_state(out_dir):
    data = np.loadtxt(out_dir / "final.txt", skiprows=9)
    return data[np.argsort(data[:, 0])]


def test_energy_budget_closes_over_a_fracture_run():
    """A bar (16 x 4 x 4 fcc cells; damage, strength, dry and viscous friction) torn apart by
    an initial velocity ramp: kinetic (translation and rotation) + potential + the energy of
    broken links + damage + friction stays at the initial kinetic energy within 1 % over 4000
    steps while some 2000 links break."""
    with session() as lmp:
        lmp.commands_list(FRACTURE.format(newton="on", length=16).strip().splitlines())
        lmp.command("run 0")
        e0 = lmp.extract_variable("etot")
        lmp.command("run 4000")
        e1 = lmp.extract_variable("etot")
        work = tally(lmp)
    assert work[0] > 1000 and work[3] > 0.0 and work[5] > 0.0
    assert e1 == pytest.approx(e0, rel=0.01), (e0, e1, work)


@pytest.mark.parametrize("nprocs,newton", [(2, "on"), (4, "on"), (2, "off")])
def test_fracture_mpi_same_cracks(tmp_path, nprocs, newton):
    """The same fracture run (10 x 4 x 4 cells, 1500 steps, some 1600 links broken) on 1 and
    on 2 or 4 ranks: the same broken-link count and the same positions and spins within
    1e-10 (summation order only)."""
    script = (f"plugin load {PLUGIN}\n" + FRACTURE.format(newton=newton, length=10) +
              "run 1500\n" + DUMP)
    ref_dir, run_dir = tmp_path / "ref", tmp_path / "run"
    ref_dir.mkdir()
    run_dir.mkdir()
    ref = run_lmp(ref_dir, script.replace(f"newton {newton}", "newton on"))
    out = run_lmp(run_dir, script, nprocs=nprocs)
    broken = [float(s.splitlines()[[i for i, l in enumerate(s.splitlines())
                                    if l.split()[:1] == ["1500"]][-1]].split()[4])
              for s in (ref, out)]
    assert broken[0] == broken[1] and broken[0] > 1000
    a, b = final_state(ref_dir), final_state(run_dir)
    assert np.abs(a[:, 1:4] - b[:, 1:4]).max() < 1e-10
    assert np.abs(a[:, 4:] - b[:, 4:]).max() < 1e-10


def test_fracture_restart_continues_bit_identically(tmp_path):
    """write_restart in the middle of the fracture run (broken links, damaged links, sliding
    contacts with their friction stress), read_restart, go on: the same bits and the same
    tallies as the run split at the same step in one session (a split run is not the straight
    one: the next test)."""
    head = f"plugin load {PLUGIN}\n" + FRACTURE.format(newton="on", length=10)
    straight = run_lmp(tmp_path, head + "run 750\nrun 750\n" + DUMP, name="in.straight")
    a = final_state(tmp_path)
    run_lmp(tmp_path, head + "run 750\nwrite_restart half.rst\n", name="in.first")
    second = run_lmp(tmp_path, f"plugin load {PLUGIN}\nread_restart half.rst\n"
                     "comm_modify vel yes\nneighbor 0.2 bin\nfix move all nve/sphere\n"
                     "timestep 0.02\ncompute pp all pair mca\n"
                     "thermo_style custom step c_pp[1] c_pp[3] c_pp[4] c_pp[6]\n"
                     "thermo_modify norm no\nrun 750\n" + DUMP,
                     name="in.second")
    assert np.array_equal(a, final_state(tmp_path))
    last = [l.split() for l in straight.splitlines() if l.split()[:1] == ["1500"]][-1]
    again = [l.split() for l in second.splitlines() if l.split()[:1] == ["1500"]][-1]
    assert [float(v) for v in again[1:]] == [float(last[k]) for k in (4, 5, 6, 7)]


MATERIAL = "young 1.0 poisson 0.3 strength 0.01 damage 0.006 friction 0.3 viscous 0.05"


@pytest.mark.parametrize("material", [
    "young 1.0 poisson 0.3",
    pytest.param(MATERIAL, marks=pytest.mark.xfail(strict=True, reason=(
        "known (doc/pair_mca.rst): theta is summed before a step's changes of state, a setup "
        "after them: a split run parts from the straight one")))])
def test_a_run_split_in_two_equals_the_straight_run(tmp_path, material):
    """The bar torn apart (6 x 4 x 4 cells), run 600 against run 300 + run 300: elastic, the
    same bits; breaking and damaging, not (a known limitation, measured in the doc)."""
    head = f"plugin load {PLUGIN}\n" + FRACTURE.format(newton="on", length=6).replace(
        MATERIAL, material)
    run_lmp(tmp_path, head + "run 600\n" + DUMP, name="in.straight")
    straight = final_state(tmp_path)
    run_lmp(tmp_path, head + "run 300\nrun 300\n" + DUMP, name="in.split")
    assert np.abs(final_state(tmp_path) - straight).max() <= 1e-12
