"""What a LAMMPS user expects of a pair style: newton on/off, /omp variants, restart,
write_data round trip (a new pair_style resets per-pair rc), extract(), no mixing, MPI runs
equal to serial, and chain N (periodic self-images skipped, the shipped example's narrow box)."""
import os

import numpy as np
import pytest
from conftest import (PLUGIN, assert_same_state, fcc_block, last_thermo, run_lmp, session, state)
from spec_laws import Law

HERE = os.path.dirname(os.path.abspath(__file__))
CHAIN_EXAMPLE = os.path.join(HERE, "..", "..", "examples", "chain-1d")

STYLES = [  # pair_style, pair_coeff for two types
    ("morse/spline cut 1.25", ["1 1 1.3 6.0 1.0", "1 2 1.1 5.0 1.02 kappa 1.2 rc 1.3",
                               "2 2 1.0 6.5 0.98"]),
    ("lj/spline wagner", ["1 1 1.3 1.0", "1 2 1.1 1.02 kappa 0.9", "2 2 1.0 0.98"]),
    ("mie/spline lagunov 1.5", ["1 1 1.3 1.0 10 5", "1 2 1.1 1.02 9 6 rs 1.12",
                                "2 2 1.0 0.98 12 6 kappa 1.1"]),
    ("harmonic/spline lagunov 1.35 start 1.1", ["1 1 1.3 5.5 1.0", "1 2 1.1 5.0 1.02",
                                                "2 2 1.0 6.0 0.98 kappa 1.2 rc 1.3"]),
    ("lj/spline cut 1.3 chain 2", ["1 1 1.3 1.0", "1 2 1.1 1.02 kappa 0.9", "2 2 1.0 0.98"]),
]
IDS = [s[0].split()[0] + ("-chain" if "chain" in s[0] else "") for s in STYLES]


def build(lmp, pair_style, coeffs, newton="on", suffix=None):
    lmp.command(f"newton {newton}")
    if suffix:
        lmp.commands_list(["package omp 2", f"suffix {suffix}"])
    fcc_block(lmp, ntypes=2, noise=0.05)
    lmp.command(f"pair_style {pair_style}")
    lmp.commands_list([f"pair_coeff {c}" for c in coeffs] + ["pair_modify shift yes"])


@pytest.mark.parametrize("pair_style,coeffs", STYLES, ids=IDS)
def test_newton_off_equals_newton_on(pair_style, coeffs):
    results = []
    for newton in ("on", "off"):
        with session() as lmp:
            build(lmp, pair_style, coeffs, newton)
            results.append(state(lmp))
    assert_same_state(*results)


@pytest.mark.parametrize("pair_style,coeffs", STYLES, ids=IDS)
def test_omp_variant_equals_plain_style(pair_style, coeffs):
    results = []
    for suffix in (None, "omp"):
        with session() as lmp:
            build(lmp, pair_style, coeffs, suffix=suffix)
            results.append(state(lmp))
            assert lmp.extract_pair_dimension("D") == 2
            assert lmp.has_style("pair", pair_style.split()[0] + "/omp")
    assert_same_state(*results)


@pytest.mark.parametrize("pair_style,coeffs", STYLES, ids=IDS)
def test_restart_restores_style_and_coefficients(pair_style, coeffs, tmp_path):
    restart = tmp_path / "restart.bin"
    with session() as lmp:
        build(lmp, pair_style, coeffs)
        before = state(lmp)
        lmp.command(f"write_restart {restart}")
    with session() as lmp:
        lmp.command(f"read_restart {restart}")
        after = state(lmp)
    assert_same_state(before, after, rtol=1e-14)


@pytest.mark.parametrize("pair_style,coeffs", STYLES, ids=IDS)
@pytest.mark.parametrize("which", ["ii", "ij"])
def test_write_data_round_trip(pair_style, coeffs, which, tmp_path):
    data = tmp_path / "data.txt"
    with session() as lmp:
        build(lmp, pair_style, coeffs)
        before = state(lmp)
        lmp.command(f"write_data {data} pair {which}")
    if which == "ii":  # pair ii writes the i i coefficients only: the rest is re-issued
        extra = [f"pair_coeff {c}" for c in coeffs if c.split()[0] != c.split()[1]]
    else:
        extra = []
    with session() as lmp:
        lmp.commands_list(["units lj", f"pair_style {pair_style}", "pair_modify shift yes",
                           f"read_data {data}", *extra, "neighbor 0.3 bin"])
        after = state(lmp)
    assert_same_state(before, after, rtol=1e-14)


def test_extract_returns_per_type_pair_coefficients():
    with session() as lmp:
        build(lmp, *STYLES[2])
        lmp.command("run 0 post no")
        assert lmp.extract_pair("D")[1][2] == 1.1
        assert lmp.extract_pair("a")[2][1] == 1.02
        assert lmp.extract_pair("n")[1][2] == 9.0
        assert lmp.extract_pair("m")[1][1] == 5.0
        assert lmp.extract_pair("kappa")[2][2] == 1.1
        assert lmp.extract_pair("alpha") is None
    with session() as lmp:
        build(lmp, *STYLES[0])
        lmp.command("run 0 post no")
        assert lmp.extract_pair("alpha")[1][2] == 5.0
        assert lmp.extract_pair("kappa")[1][2] == 1.2


def test_fix_adapt_changes_depth_through_extract():
    """fix adapt scales D through extract(): energy scales with it (cut tail, no shift)."""
    with session() as lmp:
        fcc_block(lmp)
        lmp.commands_list(["pair_style morse/spline cut 1.3", "pair_coeff 1 1 1.0 6.0 1.0"])
        pe1 = state(lmp)[0]
        lmp.commands_list(["variable d equal 2.5",
                           "fix ad all adapt 1 pair morse/spline D 1 1 v_d reset no"])
        pe2 = state(lmp)[0]
    assert pe2 == pytest.approx(2.5 * pe1, rel=1e-12)


@pytest.mark.parametrize("style,coeff,tail,kappa", [
    ("lj/spline", "1.0 1.0", "cut 1.6", "0.8"),
    ("mie/spline", "1.0 1.0 12 6", "lagunov 1.6 start 1.2", "0.8"),
    ("morse/spline", "1.0 6.0 1.0", "wagner", "1.25")])    # wagner's end moves in with kappa > 1
def test_fix_adapt_of_kappa_equals_pair_coeff_kappa(style, coeff, tail, kappa):
    """kappa adapted from 1 gives the forces, energy and pressure of pair_coeff kappa: the
    kappa kernel follows (lj and mie have a kernel of their own for kappa)."""
    states = []
    for given, adapt in [(kappa, []), ("1.0", [f"variable k equal {kappa}",
                                                f"fix ad all adapt 1 pair {style} kappa * * v_k"])]:
        with session() as lmp:
            fcc_block(lmp, noise=0.05)
            lmp.commands_list([f"pair_style {style} {tail}",
                               f"pair_coeff * * {coeff} kappa {given}"] + adapt)
            states.append(state(lmp))
    assert_same_state(states[0], states[1])


def test_missing_pair_is_an_error_naming_it():
    with session() as lmp:
        fcc_block(lmp, ntypes=2)
        lmp.commands_list(["pair_style morse/spline cut 1.2", "pair_coeff 1 1 1.0 6.0 1.0",
                           "pair_coeff 2 2 1.0 6.0 1.0"])
        with pytest.raises(Exception, match="types 1 2 are not set"):
            lmp.command("run 0")


@pytest.mark.parametrize("nprocs", [2, 4])
@pytest.mark.parametrize("pair_style,coeffs", STYLES[:2], ids=IDS[:2])
def test_mpi_run_equals_serial(tmp_path, nprocs, pair_style, coeffs):
    script = "\n".join([
        f"plugin load {PLUGIN}", "units lj", "lattice fcc 1.4142135623730951",
        "region box block 0 5 0 5 0 5", "create_box 2 box", "create_atoms 1 box",
        "mass * 1.0", "reset_atoms id sort yes", "set type 1 type/fraction 2 0.5 77",
        "displace_atoms all random 0.05 0.05 0.05 4711", "velocity all create 0.1 1 loop geom",
        f"pair_style {pair_style}", *[f"pair_coeff {c}" for c in coeffs],
        "neighbor 0.3 bin", "fix 1 all nve", "timestep 0.002",
        "thermo_style custom step pe ke press", "thermo_modify format float %.15g", "run 200"])
    serial = last_thermo(run_lmp(tmp_path, script), ["PotEng", "KinEng", "Press"])
    parallel = last_thermo(run_lmp(tmp_path, script, nprocs), ["PotEng", "KinEng", "Press"])
    assert parallel == pytest.approx(serial, rel=1e-9)


@pytest.mark.parametrize("neighbours", [1, 2, 3])
def test_chain_keyword_n_th_neighbour_feels_pi_of_r_over_n(neighbours):
    """Three atoms in ID order along x: with chain N the pair (1,3) interacts through
    Pi(r/2), cut at 2 Rc a, when N >= 2; the energy against the spec's Morse."""
    law = Law("morse", 1.3, 1.0, alpha=4.0)
    x = [0.0, 1.05, 2.2]
    with session() as lmp:
        lmp.commands_list(["units lj", "atom_modify map array", "region box block -5 10 -5 5 -5 5",
                           "create_box 1 box", "mass 1 1.0",
                           *[f"create_atoms 1 single {xi} 0 0 units box" for xi in x],
                           f"pair_style morse/spline cut 1.2 chain {neighbours}",
                           f"pair_coeff 1 1 {law.coeff()}", "thermo_modify norm no", "run 0 post no"])
        pe = lmp.get_thermo("pe")
    expected = law.pi(x[1] - x[0]) + law.pi(x[2] - x[1])
    if neighbours >= 2:
        expected += law.pi((x[2] - x[0]) / 2)  # 2.2/2 = 1.1 < 1.2: inside
    assert pe == pytest.approx(expected, rel=1e-13)


def test_chain_keyword_restricts_to_chain_neighbours():
    """Atoms 1 and 3 close in space but 2 apart in ID: no interaction with chain 1."""
    law = Law("morse", 1.3, 1.0, alpha=4.0)
    with session() as lmp:
        lmp.commands_list(["units lj", "atom_modify map array", "region box block -5 10 -5 5 -5 5",
                           "create_box 1 box", "mass 1 1.0", "create_atoms 1 single 0 0 0",
                           "create_atoms 1 single 1.0 0 0", "create_atoms 1 single 0 1.0 0",
                           "pair_style morse/spline cut 1.2 chain 1", f"pair_coeff 1 1 {law.coeff()}",
                           "thermo_modify norm no", "run 0 post no"])
        pe = lmp.get_thermo("pe")
    assert pe == pytest.approx(law.pi(1.0) + 0.0, rel=1e-13)  # (1,2) only; (2,3), (1,3) not

def box(lmp, commands=()):
    lmp.commands_list(["units lj", "region box block 0 4 0 4 0 4", "create_box 1 box",
                       "mass 1 1.0", "neighbor 0.3 bin", *commands])


def dimer_pe(lmp, r):
    lmp.commands_list(["delete_atoms group all", "create_atoms 1 single 1.0 1.0 1.0",
                       f"create_atoms 1 single {1.0 + r} 1.0 1.0", "run 0 post no"])
    return lmp.get_thermo("pe")


def test_new_pair_style_resets_per_pair_rc(tmp_path):
    with session() as lmp:
        box(lmp, ["pair_style morse/spline lagunov 1.6", "pair_coeff 1 1 1.0 6.0 1.0 rc 1.5"])
        assert dimer_pe(lmp, 1.4) != 0.0    # inside the per-pair rc 1.5
        lmp.command("pair_style morse/spline cut 1.2")
        assert dimer_pe(lmp, 1.4) == 0.0    # the new global Rc 1.2, not the old rc 1.5
        assert dimer_pe(lmp, 1.1) < 0.0


def test_cut_rc_then_wagner_writes_a_data_file_that_reads_back(tmp_path):
    data = tmp_path / "wagner.data"
    with session() as lmp:
        box(lmp, ["pair_style morse/spline cut 1.2", "pair_coeff 1 1 1.0 6.0 1.0 rc 1.3",
                  "pair_style morse/spline wagner", "create_atoms 1 single 1.0 1.0 1.0",
                  "create_atoms 1 single 2.1 1.0 1.0", "run 0 post no"])
        pe = lmp.get_thermo("pe")
        lmp.command(f"write_data {data} pair ij")
    assert " rc " not in data.read_text()
    with session() as lmp:
        lmp.commands_list(["units lj", "pair_style morse/spline wagner", f"read_data {data}",
                           "neighbor 0.3 bin", "run 0 post no"])
        assert lmp.get_thermo("pe") == pytest.approx(pe, rel=1e-14)


# chain N: periodic self-images are skipped (N is bounded: test_pair_spline_errors.py)

def chain_state(width, neighbours=3, suffix=None):
    """pe and forces of a 6-atom chain along x in a box periodic in y and z of the given width
    (in a): narrower than the cutoff N Rc a, every atom sees its own images."""
    with session() as lmp:
        lmp.commands_list(["units lj", *(["package omp 2", f"suffix {suffix}"] if suffix else []),
                           "boundary f p p",
                           f"region box block -1 7 0 {width} 0 {width}", "create_box 1 box",
                           "mass 1 1.0", "neighbor 0.3 bin"])
        for k in range(6):
            lmp.command(f"create_atoms 1 single {k * 0.98 + 0.01 * k * k} 0.5 0.5 units box")
        lmp.commands_list([f"pair_style morse/spline cut 1.2 chain {neighbours}",
                           "pair_coeff 1 1 1.0 6.0 1.0", "run 0 post no"])
        return lmp.get_thermo("pe"), np.array(lmp.gather_atoms("f", 1, 3))


@pytest.mark.parametrize("suffix", [None, "omp"])
def test_chain_atom_seeing_its_own_image_is_not_singular(suffix):
    narrow = chain_state(width=3.0, suffix=suffix)    # self-image at 3 a < cutoff 3.6 a
    wide = chain_state(width=12.0, suffix=suffix)
    assert narrow[0] == pytest.approx(wide[0], rel=1e-13) and narrow[0] < 0
    assert np.allclose(narrow[1], wide[1], rtol=0, atol=1e-12 * np.abs(wide[1]).max())


def test_chain_example_with_nine_neighbours_in_its_narrow_box(tmp_path):
    # the shipped example: a box 10 a wide, cutoff 9 x 1.2 a: it stopped with "atoms 1 and 1"
    out = run_lmp(tmp_path, open(os.path.join(CHAIN_EXAMPLE, "in.chain")).read(),
                  args=["-var", "neighbours", "9", "-var", "n", "30", "-var", "u", "500",
                        "-var", "transits", "0.2"],
                  env={"LAMMPS_PLUGIN_PATH": os.path.dirname(PLUGIN),
                       "LAMMPS_POTENTIALS": os.path.join(HERE, "..", "..", "potentials")})
    assert "9 neighbour(s) per side" in out and "ERROR" not in out
