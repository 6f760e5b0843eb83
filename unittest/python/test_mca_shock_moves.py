"""The shock law under LAMMPS's own box commands: a change of the box or a displacement between
runs (change_box ... remap, displace_atoms) compresses the elements as a run's step would
(doc/pair_mca.rst "Shock equation of state", the volume), so the pressure after change_box is
the pressure after the same strain by fix deform, and the pole 1 - 1/s is an error wherever the
volume crosses it; under fix deform stretching and shearing the box at once, every element's
volume is the box's.  Aluminium (test_mca_shock.py), a periodic 6 x 3 x 3 fcc block, strains
of 2 %, units si and metal."""
import re

import numpy as np
import pytest

from conftest import session
from test_mca_shock import CELL, UNITS, plate_setup

STRAIN = 0.98


def block(lmp, units):
    lmp.commands_list(plate_setup(units, 6, boundary="p p p")
                      + ["fix 1 all nve/sphere", "thermo_style custom step pxx pyy pe",
                         "run 0 post no", "compute J all property/atom d_mca_dvolume"])


def volume_ratios(lmp):
    lmp.command("run 0 post no")
    n = lmp.extract_global("nlocal")
    dv = lmp.numpy.extract_compute("J", 1, 1)[:n]
    return 1.0 + dv


@pytest.mark.parametrize("units", ["si", "metal"])
def test_change_box_compresses_as_fix_deform_does(units):
    with session() as lmp:
        block(lmp, units)
        lmp.command(f"change_box all x scale {STRAIN} remap")
        J = volume_ratios(lmp)
        jumped = (lmp.get_thermo("pxx"), lmp.get_thermo("pyy"))
    assert J == pytest.approx(STRAIN, abs=1e-12)       # det(I + H'): exact for a homogeneous move
    with session() as lmp:
        block(lmp, units)
        lmp.commands_list([f"fix 2 all deform 1 x scale {STRAIN} remap x", "run 2000 post no",
                           "unfix 2", "velocity all set 0 0 0"])
        J = volume_ratios(lmp)
        deformed = (lmp.get_thermo("pxx"), lmp.get_thermo("pyy"))
    # the step's midpoint exp((tr H' + tr H) / 2) follows a homogeneous compression to its third
    # order: exact to 1e-10 over 2000 steps (exp(tr H) alone drifts by 1e-7)
    assert J == pytest.approx(STRAIN, abs=1e-10)
    P = UNITS[units][3]
    assert jumped[0] == pytest.approx(deformed[0], rel=0.01)
    assert jumped[1] == pytest.approx(deformed[1], rel=0.01)
    assert jumped[0] > 1.5e9 * P      # compressed: 1.8 GPa with the yield, not the deviator's 0.2


@pytest.mark.parametrize("units", ["si", "metal"])
def test_a_box_stretched_and_sheared_by_fix_deform_gives_each_element_its_volume(units):
    """fix deform stretching the periodic block along z by 2 % while shearing it in y-z (tilt
    yz 0.2 Lz): every element's volume ratio is the box's, det F = 1.02, as in the uniaxial
    compression above.  The shear gives the pairs' motions y and z parts at once, so every
    column of the velocity sums (dv dv^T, yz included) enters the last step's shape."""
    L = UNITS[units][0]
    setup = [c.replace("region box block 0 6 0 3 0 3", "region box prism 0 6 0 3 0 3 0 0 0")
             for c in plate_setup(units, 6, boundary="p p p")]
    assert any("region box prism" in c for c in setup)
    with session() as lmp:
        lmp.commands_list(setup + [
            "fix 1 all nve/sphere", "run 0 post no", "compute J all property/atom d_mca_dvolume",
            f"fix 2 all deform 1 z scale 1.02 yz delta {0.2 * 3 * CELL * L} remap x units box",
            "run 2000 post no", "unfix 2", "velocity all set 0 0 0"])
        J = volume_ratios(lmp)
        assert lmp.extract_box()[3] == pytest.approx(0.2 * 3 * CELL * L)    # the tilt yz
    assert J == pytest.approx(1.02, abs=1e-10)    # 3e-13 off; a velocity sum left out: 1e-8


@pytest.mark.parametrize("units", ["si", "metal"])
def test_displace_atoms_between_runs_compresses_the_elements(units):
    L = UNITS[units][0]
    with session() as lmp:
        block(lmp, units)
        lo, hi = 0.0, 6 * CELL * L
        # x -> x - 0.02 x: a homogeneous 2 % compression of every element along x, the box kept
        lmp.command(f"displace_atoms all ramp x 0.0 {-(1 - STRAIN) * hi} x {lo} {hi} units box")
        J = volume_ratios(lmp)
    inner = J[(J > 0.9) & (J < 0.999)]
    assert len(inner) > 0.5 * len(J)
    assert inner.mean() == pytest.approx(STRAIN, abs=0.002)


@pytest.mark.parametrize("units", ["si", "metal"])
def test_a_box_change_past_the_pole_is_an_error(units):
    with session() as lmp:
        lmp.commands_list(plate_setup(units, 30, boundary="p p p")
                          + ["fix 1 all nve/sphere", "run 0 post no"])
        lmp.command("change_box all x scale 0.24 remap")
        with pytest.raises(Exception, match=r"beyond the limit 1 - 1/s"):
            lmp.command("run 0 post no")


def test_a_setup_that_moves_nothing_changes_nothing():
    """No move between runs: a setup leaves every element's volume and energy as they were."""
    with session() as lmp:
        block(lmp, "si")
        lmp.commands_list(["compute u all property/atom d_mca_energy",
                           "displace_atoms all random 2e-8 2e-8 2e-8 7 units box",
                           "run 30 post no"])
        n = lmp.extract_global("nlocal")
        before = volume_ratios(lmp).copy(), lmp.numpy.extract_compute("u", 1, 1)[:n].copy()
        lmp.command("run 0 post no")
        after = volume_ratios(lmp).copy(), lmp.numpy.extract_compute("u", 1, 1)[:n].copy()
    assert abs(before[0] - 1.0).max() > 1e-4 and abs(before[1]).max() > 0.0   # it moved in the run
    assert (after[0] == before[0]).all() and (after[1] == before[1]).all()


def dimer(units, law, yield_stress=0.0):
    """Two linked elements 1 d apart along x, the second given 200 m/s towards the first."""
    L, V, R, P, _ = UNITS[units]
    from test_mca_shock import C0, D, G, GAMMA0, PHI, RHO0, S
    coeff = (f"shock {RHO0 * R} {C0 * V} {S} {GAMMA0}" if law == "shock"
             else f"bulk {RHO0 * C0 ** 2 * P}") + f" shear {G * P}"
    if yield_stress:
        coeff += f" yield {yield_stress * P}"
    return [f"units {units}", "atom_style sphere", "atom_modify map array",
            "comm_modify vel yes", "boundary f f f",
            f"region box block {-3 * D * L} {4 * D * L} {-3 * D * L} {3 * D * L} {-3 * D * L} "
            f"{3 * D * L}", "create_box 1 box", "create_atoms 1 single 0 0 0 units box",
            f"create_atoms 1 single {D * L} 0 0 units box", f"set group all diameter {D * L}",
            f"neighbor {0.25 * D * L} bin", f"pair_style mca fraction {PHI}",
            f"pair_coeff 1 1 {coeff}", f"set group all density {RHO0 * R / PHI}",
            "group second id 2", f"velocity second set {-200.0 * V} 0 0 units box",
            "fix 1 all nve/sphere", f"timestep {0.02 * D * L / (C0 * V)}",
            "variable gap equal x[2]-x[1]", "variable closing equal vx[2]-vx[1]",
            "thermo_style custom step v_gap v_closing pe", "run 0 post no"]


@pytest.mark.parametrize("units", ["si", "metal"])
def test_two_linked_shock_elements_push_back_as_the_linear_law(units):
    """A pair of elements has no volume: its shock law falls back to the linear law's
    volumetric response (lambda = K - 2G/3, K = rho0 c0^2), the same pair to round-off."""
    L, V = UNITS[units][:2]
    from test_mca_shock import D
    paths = {}
    for law in ("shock", "linear"):
        with session() as lmp:
            lmp.commands_list(dimer(units, law))
            path = []
            for _ in range(30):
                lmp.command("run 20 post no")
                path.append((lmp.extract_variable("gap"), lmp.extract_variable("closing")))
            paths[law] = path
    gaps = [g for g, _ in paths["shock"]]
    assert min(gaps) < 0.999 * D * L and min(gaps) > 0.9 * D * L    # pressed, not through
    assert paths["shock"][-1][1] > 0.0                                # and pushed back
    shock, linear = np.array(paths["shock"]), np.array(paths["linear"])
    # to round-off in si; in metal the test's K = rho0 c0^2 in bar (CODATA) differs from
    # pair_coeff's rho0 c0^2 mvv2e nktv2p (LAMMPS's constants) by 1e-7
    assert np.abs(shock[:, 0] - linear[:, 0]).max() < 1e-6 * D * L
    assert np.abs(shock[:, 1] - linear[:, 1]).max() < 1e-4 * 200.0 * V


@pytest.mark.parametrize("units", ["si", "metal"])
def test_two_linked_yielding_shock_elements_do_not_pass_through(units):
    from test_mca_shock import D, Y
    L = UNITS[units][0]
    with session() as lmp:
        lmp.commands_list(dimer(units, "shock", Y))
        gaps = []
        for _ in range(30):
            lmp.command("run 20 post no")
            gaps.append(lmp.extract_variable("gap"))
    assert min(gaps) > 0.8 * D * L


@pytest.mark.parametrize("units", ["si", "metal"])
def test_uniaxial_compression_past_the_lattice_limit_names_it(tmp_path, units):
    """fix deform halving a periodic block along x: near V/V0 = 0.64 the lattice buckles and
    links leave the list; the error says the elements were compressed that far, not only that
    the skin is short."""
    from conftest import lmp_error
    lines = plate_setup(units, 6, boundary="p p p") + [
        "fix 1 all nve/sphere", "fix 2 all deform 1 x scale 0.5 remap x", "run 10000"]
    out = lmp_error(tmp_path, lines)
    m = re.search(r"links left the neighbour list unbroken \(fix \S+\): the shock-law elements "
                  r"are compressed to V/V0 = ([\d.]+) at the least: a lattice of elements", out)
    assert m, out[-1500:]
    assert 0.55 < float(m.group(1)) < 0.8
