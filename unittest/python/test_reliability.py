"""The defects of the reliability review, one test each: errors inside OpenMP regions, chain N
and periodic self-images, fix viscous/relative with coincident atoms and under respa,
per-pair rc/rs across pair_style commands, compute pair/params rows without a steady state,
the time-step warning, the neighbor-skin check, compute dust without an atom map (in
test_compute_dust.py) and the plugin's split into a core file and an /omp file."""
import os
import shutil
import subprocess

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp, session

HERE = os.path.dirname(os.path.abspath(__file__))
CHAIN_EXAMPLE = os.path.join(HERE, "..", "..", "examples", "chain-1d")


def box(lmp, commands=(), threads=0):
    lmp.commands_list(["units lj", *([f"package omp {threads}", "suffix omp"] if threads else []),
                       "region box block 0 4 0 4 0 4", "create_box 1 box", "mass 1 1.0",
                       "neighbor 0.3 bin", *commands])


# 1. /omp: an error inside the OpenMP region is the serial style's clean, catchable error

@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("law,coeff,where,message", [
    ("morse", "1.0 6.0 1.0", 1.0, "atoms 1 and 2 are 0 apart"),
    ("lj", "1.0 1.0 kappa 2.0", 1.2, "atoms 1 and 2 are 0.2 apart"),
])
def test_omp_error_is_catchable_and_the_host_survives(threads, law, coeff, where, message):
    with session() as lmp:
        box(lmp, ["create_atoms 1 single 1.0 1.0 1.0", f"create_atoms 1 single {where} 1.0 1.0",
                  f"pair_style {law}/spline cut 1.3", f"pair_coeff 1 1 {coeff}"], threads)
        assert lmp.has_style("pair", f"{law}/spline/omp")
        with pytest.raises(Exception, match=message):
            lmp.command("run 0")
        lmp.command("delete_atoms group all")    # the instance still takes commands
        lmp.command("run 0 post no")
        assert lmp.get_natoms() == 0


# 2. chain N: periodic self-images are skipped; N is bounded (test_pair_spline_errors.py)

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


# 3. fix viscous/relative mode normal: coincident atoms have no normal and are skipped

def test_normal_mode_skips_coincident_atoms_without_nan():
    with session() as lmp:
        box(lmp, ["create_atoms 1 single 1.0 1.0 1.0", "create_atoms 1 single 1.0 1.0 1.0",
                  "create_atoms 1 single 1.5 1.0 1.0", "pair_style zero 1.0", "pair_coeff * *",
                  "set atom 1 vx 1.0", "set atom 2 vx -1.0", "set atom 3 vx 0.5",
                  "fix nve all nve", "fix d all viscous/relative gamma 0.5 mode normal",
                  "timestep 0.001", "run 10 post no"])
        v = np.array(lmp.gather_atoms("v", 1, 3)).reshape(-1, 3)
        removed = lmp.numpy.extract_fix("d", 0, 0)
    assert np.all(np.isfinite(v)) and np.isfinite(removed)
    assert v.sum(axis=0) == pytest.approx([0.5, 0, 0], abs=1e-14)    # momentum conserved
    assert v[2, 0] < 0.5 and removed > 0    # the pairs with a normal are damped


# 4. fix viscous/relative refuses run_style respa (it could not damp there)

def test_respa_is_refused():
    # with a stock pair style: the spline styles refuse respa themselves (test_reliability_review)
    with session() as lmp:
        box(lmp, ["create_atoms 1 single 1.0 1.0 1.0", "pair_style morse 1.2",
                  "pair_coeff 1 1 1.0 6.0 1.0", "fix nve all nve",
                  "fix d all viscous/relative gamma 0.5", "run_style respa 2 2"])
        with pytest.raises(Exception, match="does not support run_style respa"):
            lmp.command("run 1")


# 6. a new pair_style resets per-pair rc and rs (documented)

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


# 10. the time-step warning (its threshold in every unit style: test_units.py)

# a row of 21 aluminium clusters of the dusting paper (units si)
AL_ROW = ["units si", "boundary f p p", "lattice sc 1e-5", "region box block -2 40 0 1 0 1",
          "create_box 1 box", "region b block 0 20 0 1 0 1", "create_atoms 1 region b",
          "mass 1 2.338e-12", "neighbor 2e-6 bin", "pair_style morse/spline cut 1.2",
          "pair_coeff 1 1 2.46e-6 3.76e5 1e-5"]


def test_strong_shock_far_past_the_suggested_step_warns(tmp_path):
    """A 20 km/s collision of Al clusters (ten on eleven at rest) at 2.7 x the step compute
    pair/params suggests for it: warned once, at the first check that sees the compression
    (not at the run 0 that read the compute, which takes no step)."""
    log = tmp_path / "log.lammps"
    with session("-log", str(log)) as lmp:
        lmp.commands_list(AL_ROW + [
            "compute p all pair/params 1 1 u 20000", "run 0 post no", "variable dt equal 2.7*c_p[1][6]", "timestep ${dt}",
            "group hit id <= 10", "velocity hit set 20000 0 0 units box", "fix nve all nve",
            "run 60 post no"])
    text = log.read_text()
    assert text.count("WARNING: Pair morse/spline: time step") == 1    # once
    assert "exceeds" in text and "reduce the time step" in text


def test_run_0_takes_no_step_and_does_not_warn(tmp_path):
    """run 0, the way to read compute pair/params before choosing the step, runs under
    LAMMPS's default step (1e-8 s in units si, 35 times the suggested one here) without a
    time-step warning: it takes no step.  The first real run checks."""
    log = tmp_path / "log.lammps"
    with session("-log", str(log)) as lmp:
        lmp.commands_list(AL_ROW + ["compute p all pair/params 1 1",
                                    "thermo_style custom step c_p[13]", "run 0 post no"])
        assert "time step" not in log.read_text()
        lmp.commands_list(["fix nve all nve", "run 1 post no"])
    assert log.read_text().count("WARNING: Pair morse/spline: time step") == 1


# friction: the neighbor skin; the plugin without the OPENMP package

def test_default_si_skin_at_cluster_scale_is_a_clear_error(tmp_path):
    log = tmp_path / "log.lammps"
    with session("-log", str(log)) as lmp:
        lmp.commands_list(["units si", "lattice sc 1e-5", "region box block 0 4 0 4 0 4",
                           "create_box 1 box", "create_atoms 1 box", "mass 1 2.338e-12",
                           "pair_style morse/spline cut 1.2", "pair_coeff 1 1 2.46e-6 3.76e5 1e-5"])
        with pytest.raises(Exception, match=r"neighbor skin 0.001 is 83.3 x the interaction range"):
            lmp.command("run 0")
        lmp.commands_list(["neighbor 3e-6 bin", "run 0 post no"])
        assert lmp.get_thermo("pe") < 0
    # the whole message (the Python exception keeps its first 100 characters)
    assert ("range 1.2e-05: set it, e.g. neighbor 3e-06 bin (the default skin of units si suits "
            "atoms, not clusters)") in log.read_text()


@pytest.mark.parametrize("style,message", [
    ("fix d all viscous/relative gamma 1e6 cutoff 1.2e-5", "Fix viscous/relative: neighbor skin"),
    ("compute d all dust cutoff 1.2e-5", "Compute dust: neighbor skin"),
])
def test_fix_and_compute_with_their_own_cutoff_check_the_skin(style, message):
    with session() as lmp:
        lmp.commands_list(["units si", "lattice sc 1e-5", "region box block 0 4 0 4 0 4",
                           "create_box 1 box", "create_atoms 1 box", "mass 1 2.338e-12",
                           "pair_style zero 1.2e-5", "pair_coeff * *", "neighbor 1e-3 bin",
                           style, "fix nve all nve", "thermo_style custom step c_d[1]"
                           if "compute" in style else "fix nve2 all nve"])
        with pytest.raises(Exception, match=message):
            lmp.command("run 0")


def undefined_symbols(path):
    out = subprocess.run(["nm", "-D", "--undefined-only", "-C", path], capture_output=True,
                         text=True, check=True).stdout
    return out


def test_core_plugin_needs_no_openmp_package_symbols():
    omp = os.path.join(os.path.dirname(PLUGIN), "clusterdyn_omp.so")
    assert "ThrOMP" not in undefined_symbols(PLUGIN)
    assert "FixOMP" not in undefined_symbols(PLUGIN)
    assert "ThrOMP" in undefined_symbols(omp)    # the /omp styles live there


def test_core_plugin_alone_loads_its_styles(tmp_path):
    alone = tmp_path / "clusterdynplugin.so"
    shutil.copy(PLUGIN, alone)
    log = tmp_path / "log.lammps"
    with session("-log", str(log), plugin=False) as lmp:
        lmp.command(f"plugin load {alone}")
        assert lmp.has_style("pair", "morse/spline") and lmp.has_style("compute", "dust")
        assert not lmp.has_style("pair", "morse/spline/omp")
    assert "clusterdyn_omp.so not found; the /omp pair styles are not loaded" in log.read_text()
