"""compute mca/atom: the element stresses of pair_style mca (Love's formula over its pairs),
their mean and equivalent stress, linked pairs and element volumes.  Oracles: isotropic Hooke's
law of the input moduli on a uniformly strained fcc block and LAMMPS's virial pressure (eight
unit styles); LAMMPS's pxy after a tilt once the elements have turned (two unit styles); the
group's elements against the whole's; serial against 2 ranks (newton on and off); Love's sum
with each element's own arm to the contact point in a dimer of two sizes and materials.  Stale
values are a clear error; the table of hostile input (conftest.InputTable)."""
import math

import numpy as np
import pytest
from conftest import (MCA_FCC_BLOCK, OK, PLUGIN, InputTable, check_input, run_lmp, scene_mca,
                      session)
from lammps import LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, LMP_VAR_ATOM
from test_pair_mca import SCALE, UNITS, per_atom


def strained_block(newton="on", outputs=()):
    """MCA_FCC_BLOCK with the outputs after 100 steps, then strained: stresses of every sign and
    size."""
    return (MCA_FCC_BLOCK.format(newton=newton, dt=0.02).strip().splitlines() + list(outputs) +
            ["run 100", "change_box all x scale 1.001 y scale 0.999 remap",
             "run 0"])


def test_elements_outside_the_group_get_0():
    with session() as lmp:
        lmp.commands_list(strained_block(outputs=[
            "region left block INF 2 INF INF INF INF", "group left region left",
            "compute s all mca/atom", "compute g left mca/atom",
            "variable inside atom gmask(left)"]))
        whole, part = per_atom(lmp, "s"), per_atom(lmp, "g")
        n = lmp.extract_global("nlocal")
        inside = np.array(lmp.numpy.extract_variable("inside", "all", LMP_VAR_ATOM)[:n]) == 1
    assert 0 < inside.sum() < len(inside) and np.abs(whole).max() > 0
    assert np.array_equal(part[inside], whole[inside]) and np.all(part[~inside] == 0)


@pytest.mark.parametrize("nprocs,newton", [(2, "on"), (2, "off")])
def test_two_ranks_give_the_serial_stresses(tmp_path, nprocs, newton):
    """Stresses summed over pairs with ghost atoms (newton on: sent back to their owners): by
    element ID the serial ones, to the summation order (1e-9 of the largest)."""
    def stresses(nprocs, newton, folder):
        folder.mkdir()
        cols = " ".join(f"c_s[{k}]" for k in range(1, 11))
        run_lmp(folder, "\n".join([f"plugin load {PLUGIN}",
                                   *strained_block(newton, ["compute s all mca/atom"]),
                                   f"write_dump all custom s.txt id {cols} modify sort id "
                                   "format float %.17g", ""]), nprocs)
        return np.loadtxt(folder / "s.txt", skiprows=9)
    serial = stresses(1, "on", tmp_path / "serial")
    ranks = stresses(nprocs, newton, tmp_path / "ranks")
    scale = np.abs(serial[:, 1:9]).max()
    assert scale > 0 and np.array_equal(ranks[:, [0, 9, 10]], serial[:, [0, 9, 10]])
    assert np.abs(ranks[:, 1:9] - serial[:, 1:9]).max() <= 1e-9 * scale


def test_compute_follows_the_pair_style_and_the_atoms(tmp_path):
    """compute mca/atom after the pair style changed, or after atoms were added since the last
    force evaluation: a clear error, not stale values."""
    with session() as lmp:
        lmp.commands_string(MCA_FCC_BLOCK.format(newton="on", dt=0.02))
        lmp.commands_list(["compute s all mca/atom", "run 0", "create_atoms 1 single 0.3 0.3 0.3"])
        with pytest.raises(Exception, match="not current"):
            lmp.command(f"write_dump all custom {tmp_path / 'd.txt'} id c_s[1]")
    # one deleted, one created: the same count of atoms, not the same atoms (was: stale values)
    with session() as lmp:
        lmp.commands_string(MCA_FCC_BLOCK.format(newton="on", dt=0.02))
        lmp.commands_list(["compute s all mca/atom", "run 0", "group one id 5",
                           "delete_atoms group one", "create_atoms 1 single 0.3 0.3 0.3"])
        with pytest.raises(Exception, match="not current"):
            lmp.command(f"write_dump all custom {tmp_path / 'd.txt'} id c_s[1]")
    with session() as lmp:
        lmp.commands_string(MCA_FCC_BLOCK.format(newton="on", dt=0.02))
        lmp.commands_list(["compute s all mca/atom", "run 0", "pair_style zero 1.0",
                           "pair_coeff * *"])
        with pytest.raises(Exception, match="needs pair_style mca"):
            lmp.command(f"write_dump all custom {tmp_path / 'd.txt'} id c_s[1]")


@pytest.mark.parametrize("units", UNITS)
def test_element_stress_matches_pressure_and_hooke(units):
    """A periodic fcc block under a uniform strain: every element's stress (compute mca/atom)
    is Hooke's 2 G eps + lambda tr(eps) I of the input moduli, and their volume-weighted sum
    is LAMMPS's virial pressure times the box volume, with the opposite sign (pressure units
    of each unit style)."""
    radius, g = SCALE[units]
    k = 3.0 * g
    lam = k - 2.0 * g / 3.0
    a = 2.0 * math.sqrt(2.0) * radius       # fcc cube edge for touching elements
    lattice = f"lattice fcc {4.0 / a ** 3!r}" if units == "lj" else f"lattice fcc {a!r}"
    eps = (1.0e-4, -2.0e-5, 3.0e-5)
    with session() as lmp:
        lmp.commands_list([
            f"units {units}", "atom_style sphere", "boundary p p p", "comm_modify vel yes",
            lattice, "region box block 0 3 0 3 0 3", "create_box 1 box", "create_atoms 1 box",
            f"set group all diameter {2 * radius}", f"neighbor {0.2 * radius} bin",
            "pair_style mca fraction 0.7404804896930609 tolerance 0.02",
            f"pair_coeff 1 1 bulk {k} shear {g}", "compute mca all mca/atom",
            "compute p all pressure NULL virial",
            "thermo_style custom step c_p[1] c_p[2] c_p[3] c_p[4]", "run 0",
            f"change_box all x scale {1 + eps[0]} y scale {1 + eps[1]} z scale {1 + eps[2]} "
            "remap", "run 0"])
        s = per_atom(lmp)
        p = [lmp.extract_compute("p", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR)[i] for i in range(4)]
        vol = lmp.get_thermo("vol")
    tr = sum(eps)
    for axis in range(3):
        hooke = 2.0 * g * eps[axis] + lam * tr
        assert np.allclose(s[:, axis], hooke, rtol=2e-4, atol=1e-9 * g)
        # the element volumes are reference volumes: -P V = sum of sigma_i Omega_i
        assert -p[axis] * vol == pytest.approx(np.sum(s[:, axis] * s[:, 9]), rel=1e-9)
    assert np.abs(s[:, 3:6]).max() < 1e-9 * g and abs(p[3]) < 1e-9 * g


@pytest.mark.parametrize("units", ["lj", "si"])
def test_shear_modulus_by_tilt_once_the_elements_turn(units):
    """C44 of an fcc block by a tilt (change_box xy ... remap): a simple shear gamma is a pure
    shear plus a rotation by -gamma/2 that the elements have not made.  Right after it (run 0)
    the elements' stress (compute mca/atom, the symmetric part of Love's sum) is already
    sxy = G gamma, but LAMMPS's pxy (the virial's sum of dx f_y, not symmetrized) reads 0: the
    tangential forces of the unmade rotation load the elements with torques, and the energy is
    twice the shear energy.  With the positions held (fix setforce) and the spins damped (fix
    viscous/sphere) the elements turn: pxy = -G gamma, sxy = G gamma and the energy
    G gamma^2 V / 2 (doc/compute_mca_atom.rst)."""
    radius, g = SCALE[units]
    rho = 1.35 * {"lj": 1.0, "si": 1.0e3}[units]
    t0 = 2 * radius * math.sqrt(rho / g)
    a = 2.0 * math.sqrt(2.0) * radius
    lattice = f"lattice fcc {4.0 / a ** 3!r}" if units == "lj" else f"lattice fcc {a!r}"
    gamma = 1.0e-4
    with session() as lmp:
        lmp.commands_list([
            f"units {units}", "atom_style sphere", "boundary p p p", "comm_modify vel yes",
            lattice, "region box prism 0 3 0 3 0 3 0 0 0", "create_box 1 box",
            "create_atoms 1 box", f"set group all diameter {2 * radius}",
            f"set group all density {rho / 0.7404804896930609!r}",
            f"neighbor {0.2 * radius} bin",
            "pair_style mca fraction 0.7404804896930609 tolerance 0.02",
            f"pair_coeff 1 1 bulk {3 * g} shear {g}", "compute mca all mca/atom",
            "compute p all pressure NULL virial", "fix nve all nve/sphere",
            f"timestep {0.005 * t0!r}", "thermo_style custom step pe c_p[4]",
            "thermo_modify norm no", "run 0",
            f"change_box all xy final {gamma * 3 * a!r} remap units box", "run 0"])
        unturned = (lmp.get_thermo("pe"), lmp.extract_compute("p", LMP_STYLE_GLOBAL,
                                                              LMP_TYPE_VECTOR)[3],
                    per_atom(lmp)[:, 3])
        lmp.commands_list(["fix held all setforce 0.0 0.0 0.0",
                           f"fix spin all viscous/sphere {0.7 * g * 8 * radius ** 3 * t0!r}",
                           "run 3000"])
        turned = (lmp.get_thermo("pe"), lmp.extract_compute("p", LMP_STYLE_GLOBAL,
                                                            LMP_TYPE_VECTOR)[3],
                  per_atom(lmp)[:, 3], per_atom(lmp)[:, 7])
        vol = lmp.get_thermo("vol")
        nktv2p = lmp.extract_global("nktv2p")
    energy = 0.5 * g * gamma ** 2 * vol / nktv2p
    assert abs(unturned[1]) < 1e-5 * g * gamma
    assert np.allclose(unturned[2], g * gamma, rtol=1e-5)
    assert unturned[0] == pytest.approx(2 * energy, rel=1e-3)
    assert turned[1] == pytest.approx(-g * gamma, rel=1e-5)
    assert np.allclose(turned[2], g * gamma, rtol=1e-5)
    assert turned[0] == pytest.approx(energy, rel=1e-3)
    # a pure shear's von Mises stress is sqrt(3) tau (each shear term counted twice)
    assert np.allclose(turned[3], math.sqrt(3.0) * g * gamma, rtol=1e-4)


# ---------------------------------------------------------------- hostile input

INPUTS = InputTable()
row = INPUTS.row
MP = "pair_style mca fraction 0.6"
MC = "pair_coeff * * young 1.0 poisson 0.3"
row("mca-compute-args", scene_mca(), [MP, MC, "compute s all mca/atom 1"], "takes no arguments")
row("mca-compute-other-pair", scene_mca(), ["pair_style zero 1.0", "pair_coeff * *",
                                            "compute s all mca/atom"], "needs pair_style mca")
row("mca-ok", scene_mca(), [MP, MC, "compute s all mca/atom", "compute m all reduce max c_s[8]",
                            "thermo_style custom step pe press c_m"], OK)


@pytest.mark.parametrize("setup,cmds,expect,isolate", INPUTS.rows)
def test_hostile_input(setup, cmds, expect, isolate):
    check_input(setup, cmds, expect, isolate)


@pytest.mark.parametrize("units", ["lj", "si"])
def test_two_element_sizes_take_their_own_arm_of_the_link(units):
    """A linked dimer of two materials and two sizes (R1 = 0.5, R2 = 0.8 units, touching, then
    stretched by 1e-3): each element's stress is Love's q_i F n / Omega_i with its own arm
    q_i = r R_i / (R_i + R_j) to the contact point (not r/2, which the sum over both elements
    does not see: q_1 + q_2 = r), F the force on it (LAMMPS's f), Omega_i its volume (column
    10, 4/3 pi R_i^3 / F); uniaxial: the mean stress a third of it, the von Mises stress it,
    one link each."""
    unit, scale = SCALE[units]
    r1, r2 = 0.5 * unit, 0.8 * unit
    fraction, delta = 0.6, 1.0e-3 * unit
    with session() as lmp:
        box = 10 * unit
        lmp.commands_list([
            f"units {units}", "atom_style sphere", "atom_modify map array", "boundary f f f",
            "comm_modify vel yes",
            f"region box block {-box} {box} {-box} {box} {-box} {box} units box",
            "create_box 2 box", f"create_atoms 1 single {-r1} 0 0 units box",
            f"create_atoms 2 single {r2} 0 0 units box", f"set type 1 diameter {2 * r1}",
            f"set type 2 diameter {2 * r2}", "set group all density 1.0",
            f"neighbor {0.1 * unit} bin", f"pair_style mca fraction {fraction} tolerance 0.01",
            f"pair_coeff 1 1 bulk {3.0 * scale} shear {1.0 * scale}",
            f"pair_coeff 2 2 bulk {2.0 * scale} shear {0.4 * scale}", "compute s all mca/atom",
            "thermo_modify norm no", "run 0", "group two id 2",
            f"displace_atoms two move {delta} 0 0 units box", "run 0"])
        f = np.array(lmp.gather_atoms("f", 1, 3)).reshape(-1, 3)
        x = np.array(lmp.gather_atoms("x", 1, 3)).reshape(-1, 3)
        s = np.array(lmp.gather("c_s", 1, 11)).reshape(-1, 11)
    r = x[1, 0] - x[0, 0]
    radius = np.array([r1, r2])
    omega = 4 * math.pi / 3 * radius ** 3 / fraction
    q = r * radius / (r1 + r2)
    n = np.array([1.0, -1.0])    # from each element to its partner, along x
    sxx = q * f[:, 0] * n / omega
    assert np.all(sxx > 0)    # tension
    assert s[:, 9] == pytest.approx(omega, rel=1e-12)
    assert s[:, 0] == pytest.approx(sxx, rel=1e-10)
    assert np.abs(s[:, 1:6]).max() <= 1e-12 * sxx.max()
    assert s[:, 6] == pytest.approx(sxx / 3, rel=1e-10)
    assert s[:, 7] == pytest.approx(sxx, rel=1e-10)
    assert list(s[:, 8]) == [1.0, 1.0]
    # what the arms change: with r/2 each, element 1's stress would be R2/R1 x its q share off
    assert abs(0.5 * r * f[0, 0] / omega[0] - sxx[0]) > 1e-2 * sxx[0]
