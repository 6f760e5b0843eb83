"""Foundation: the plugin loads by path in lmp and in Python, `plugin list` shows every
style, a missing file fails clearly in our harness, auto-loading works, a Morse run
under MPI gives the serial energy, and the core file needs no symbol of LAMMPS's OPENMP
package (it loads alone; the /omp styles live in a second file)."""
import os
import re
import shutil
import subprocess

import pytest
from conftest import (ALL_PAIR_STYLES, COMPUTE_STYLES, FIX_STYLES, PLUGIN, last_thermo,
                      load_plugin, run_lmp, session)

MORSE_BLOCK = """
units lj
lattice fcc 1.0
region box block 0 6 0 6 0 6
create_box 1 box
create_atoms 1 box
mass 1 1.0
displace_atoms all random 0.05 0.05 0.05 4711
velocity all create 0.1 12345 loop geom
pair_style {pair_style}
pair_coeff * * {pair_coeff}
neighbor 0.3 bin
fix 1 all nve
timestep 0.002
thermo_style custom step pe ke etotal press
thermo_modify format float %.15g
run 100
"""


def test_lmp_loads_by_path_and_lists_every_style(tmp_path):
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\nplugin list\n")
    assert set(re.findall(r"pair style plugin (\S+)", out)) == set(ALL_PAIR_STYLES)
    assert set(re.findall(r"fix style plugin (\S+)", out)) == set(FIX_STYLES)
    assert set(re.findall(r"compute style plugin (\S+)", out)) == set(COMPUTE_STYLES)


def test_python_loads_by_path():
    with session() as lmp:
        for style in ALL_PAIR_STYLES:
            assert lmp.has_style("pair", style)
        for style in FIX_STYLES:
            assert lmp.has_style("fix", style)
        assert not lmp.has_style("pair", "no/such/style")


def test_missing_plugin_fails_clearly_in_harness():
    with session(plugin=False) as lmp:
        # LAMMPS itself only logs the failure ...
        lmp.command("plugin load /nonexistent/clusterdynplugin.so")
        assert not lmp.has_style("pair", "morse/spline")
        # ... our harness says what is wrong
        with pytest.raises(FileNotFoundError, match="/nonexistent/clusterdynplugin.so"):
            load_plugin(lmp, "/nonexistent/clusterdynplugin.so")


def test_autoload_from_lammps_plugin_path(tmp_path):
    script = MORSE_BLOCK.format(pair_style="morse/spline cut 1.3", pair_coeff="1.0 5.0 1.1")
    out = run_lmp(tmp_path, script.replace("run 100", "run 0"),
                  env={"LAMMPS_PLUGIN_PATH": os.path.dirname(PLUGIN)})
    assert "Loaded 1 plugins from" in out


@pytest.mark.parametrize("nprocs", [2, 4])
def test_stock_morse_mpi_equals_serial(tmp_path, nprocs):
    script = f"plugin load {PLUGIN}\n" + MORSE_BLOCK.format(
        pair_style="morse 1.8", pair_coeff="1.0 5.0 1.1")
    serial = last_thermo(run_lmp(tmp_path, script), ["PotEng", "TotEng", "Press"])
    parallel = last_thermo(run_lmp(tmp_path, script, nprocs), ["PotEng", "TotEng", "Press"])
    assert serial[0] < 0
    assert parallel == pytest.approx(serial, rel=1e-10)


# the plugin's split into a core file, an /omp file and a /gpu file (doc/Build.rst)

def undefined_symbols(path):
    out = subprocess.run(["nm", "-D", "--undefined-only", "-C", path], capture_output=True,
                         text=True, check=True).stdout
    return out


def test_core_plugin_needs_no_openmp_package_symbols():
    omp = os.path.join(os.path.dirname(PLUGIN), "clusterdyn_omp.so")
    assert "ThrOMP" not in undefined_symbols(PLUGIN)
    assert "FixOMP" not in undefined_symbols(PLUGIN)
    assert "ThrOMP" in undefined_symbols(omp)    # the /omp styles live there


def test_core_plugin_needs_no_gpu_library_symbols():
    gpu = os.path.join(os.path.dirname(PLUGIN), "clusterdyn_gpu.so")
    assert "LAMMPS_AL::" not in undefined_symbols(PLUGIN)
    assert "LAMMPS_AL::BaseAtomic" in undefined_symbols(gpu)    # the /gpu styles live there


def test_core_plugin_alone_loads_its_styles(tmp_path):
    alone = tmp_path / "clusterdynplugin.so"
    shutil.copy(PLUGIN, alone)
    log = tmp_path / "log.lammps"
    with session("-log", str(log), plugin=False) as lmp:
        lmp.command(f"plugin load {alone}")
        assert lmp.has_style("pair", "morse/spline") and lmp.has_style("compute", "dust")
        assert not lmp.has_style("pair", "morse/spline/omp")
        assert not lmp.has_style("pair", "morse/spline/gpu")
    assert "clusterdyn_omp.so not found; the /omp pair styles are not loaded" in log.read_text()
    assert "clusterdyn_gpu.so not found; the /gpu pair styles are not loaded" in log.read_text()


# a free block of smd/tlsph particles (units si: aluminium, simple cubic of 1 mm, h = 2.01
# spacings)
# with the Mie-Grueneisen shock equation of state and linear plasticity, its left half set moving
# at 100 m/s against its right half: the continuum model LAMMPS has for the plate impacts that
# pair mca is compared with (MACHDYN, built with Debian's Eigen)
TLSPH_BLOCK = """
units si
dimension 3
boundary sm sm sm
atom_style smd
atom_modify map array
comm_modify vel yes
newton off
lattice sc 0.001
region box block 0 12 0 4 0 4
create_box 1 box
create_atoms 1 box
group tlsph type 1
set group all volume 1.0e-9
set group all smd/mass/density 2700.0
set group all diameter 0.00201
neighbor 0.00201 bin
region left block EDGE 6 EDGE EDGE EDGE EDGE
group left region left
velocity left set 100.0 0.0 0.0 units box
pair_style smd/tlsph
pair_coeff 1 1 *COMMON 2700.0 70.0e9 0.33 1.0 0.0 10.0 1.0 *EOS_SHOCK 5350.0 1.34 2.0 &
  *STRENGTH_LINEAR_PLASTIC 0.3e9 0.0 *END
fix dt tlsph smd/adjust_dt 0.1
fix integrate tlsph smd/integrate_tlsph
variable px equal mass(all)*vcm(all,x)
thermo_style custom step v_px
run 0
variable p0 equal ${px}
run 200
"""


def test_lammps_carries_the_packages_of_the_comparisons():
    """The LAMMPS that tools/bootstrap.sh builds has the packages the comparisons need (BPM,
    GRANULAR, PERI, OPT, SHOCK, MACHDYN), and smd/tlsph with *EOS_SHOCK and
    *STRENGTH_LINEAR_PLASTIC runs: the moving half strikes the resting half, which starts to
    move, and the block's momentum is kept (pairwise forces)."""
    with session() as lmp:
        for package in ("BPM", "GRANULAR", "PERI", "OPT", "SHOCK", "MACHDYN"):
            assert lmp.has_package(package), package
        lmp.commands_list(TLSPH_BLOCK.strip().replace("&\n", "").splitlines())
        p0, p1 = lmp.extract_variable("p0"), lmp.extract_variable("px")
        n = lmp.get_natoms()
        vx = [v[0] for v in lmp.numpy.extract_atom("v")[:n]]
        x = [r[0] for r in lmp.numpy.extract_atom("x")[:n]]
    assert p0 > 0.0
    assert p1 == pytest.approx(p0, rel=1e-9)
    right_end = max(v for v, xx in zip(vx, x) if xx > 0.0095)
    assert right_end > 1.0                        # the wave has reached the far end
