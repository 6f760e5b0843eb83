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


# the plugin's split into a core file and an /omp file (doc/Build.rst)

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
