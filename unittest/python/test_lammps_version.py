"""Which LAMMPS the plugin works with (doc/Build.rst, Compatibility): the plugin refuses to
register its styles in a LAMMPS of another version, naming both; the bootstrap builds an
overriding LAMMPS source tree into a fresh cache folder, in an entry named after the version
its src/version.h holds."""
import os
import subprocess

from conftest import LMP, PLUGIN, run_lmp, session

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
MISMATCH = os.path.join(os.path.dirname(PLUGIN), "unittest", "clusterdyn_version_mismatch.so")


def test_plugin_built_for_another_version_registers_nothing_and_names_both(tmp_path):
    with session(plugin=False) as lmp:
        host = lmp.version()
    script = f"""plugin load {MISMATCH}
pair_style morse/spline cut 1.2
"""
    infile = tmp_path / "in.mismatch"
    infile.write_text(script)
    out = subprocess.run([LMP, "-in", str(infile), "-log", "none", "-nocite"], cwd=tmp_path,
                         env={k: v for k, v in os.environ.items() if k != "LAMMPS_PLUGIN_PATH"},
                         capture_output=True, text=True, timeout=120)
    text = out.stdout + out.stderr
    assert (f"clusterdynplugin.so was compiled for LAMMPS 1 Jan 2020 (20200101) but this "
            f"LAMMPS is version {host}: none of its styles are registered") in text
    assert out.returncode != 0 and "Unrecognized pair style 'morse/spline'" in text


def test_plugin_built_for_this_version_loads_without_the_warning(tmp_path):
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\npair_style morse/spline cut 1.2\n")
    assert "was compiled for LAMMPS" not in out and "Loading plugin: cluster-dynamics" in out


def test_version_warning_printed_once_on_two_ranks(tmp_path):
    infile = tmp_path / "in.mismatch"
    infile.write_text(f"plugin load {MISMATCH}\n")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    env.pop("LAMMPS_PLUGIN_PATH", None)
    out = subprocess.run(["mpirun", "-np", "2", "--oversubscribe", LMP, "-in", str(infile),
                          "-log", "none", "-nocite"], cwd=tmp_path, env=env,
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0
    assert (out.stdout + out.stderr).count("was compiled for LAMMPS 1 Jan 2020") == 1


FAKE_LAMMPS_CMAKE = """cmake_minimum_required(VERSION 3.16)
project(fake_lammps C)
file(WRITE ${CMAKE_BINARY_DIR}/lib.c "int fake_lammps(void) { return 0; }\\n")
file(WRITE ${CMAKE_BINARY_DIR}/main.c "int fake_lammps(void);\\nint main(void) { return fake_lammps(); }\\n")
add_library(lammps SHARED ${CMAKE_BINARY_DIR}/lib.c)
set_target_properties(lammps PROPERTIES SOVERSION 0)
add_executable(lmp ${CMAKE_BINARY_DIR}/main.c)
target_link_libraries(lmp lammps)
"""


def test_overrides_work_from_a_fresh_cache_named_by_the_version(tmp_path):
    """A stand-in LAMMPS tree (version 1 Jan 2020, a CMake project that makes liblammps.so.0
    and lmp): the bootstrap must create the missing cache folder, build the tree into
    lammps-20200101-<key> and get as far as configuring the plugin (which then fails: the
    stand-in has no LAMMPS headers)."""
    src = tmp_path / "fake-lammps"
    (src / "src").mkdir(parents=True)
    (src / "cmake").mkdir()
    (src / "src" / "version.h").write_text('#define LAMMPS_VERSION "1 Jan 2020"\n')
    (src / "cmake" / "CMakeLists.txt").write_text(FAKE_LAMMPS_CMAKE)
    cache = tmp_path / "no" / "such" / "cache"
    env = dict(os.environ, CLUSTERDYN_LAMMPS_SOURCE=str(src), CLUSTERDYN_CACHE=str(cache),
               CLUSTERDYN_BUILD_DIR=str(tmp_path / "plugin-build"))
    env.pop("LD_LIBRARY_PATH", None)     # env.sh's: it would load the pinned liblammps
    out = subprocess.run(["bash", os.path.join(TOP, "tools", "bootstrap.sh")], env=env,
                         capture_output=True, text=True, timeout=600)
    text = out.stdout + out.stderr
    assert "No such file or directory" not in text
    entries = [e for e in os.listdir(cache) if os.path.isdir(cache / e)]
    assert len(entries) == 1 and entries[0].startswith("lammps-20200101-"), entries
    assert (cache / entries[0] / ".complete").exists() and (cache / entries[0] / "lmp").exists()
    assert out.returncode != 0 and "Set LAMMPS_ROOT to a LAMMPS source tree" in text
    # the same build given as CLUSTERDYN_LAMMPS_BUILD, with another cache folder that does not
    # exist: the bootstrap needs no cache and gets as far again
    env.update(CLUSTERDYN_LAMMPS_BUILD=str(cache / entries[0]),
               CLUSTERDYN_CACHE=str(tmp_path / "another" / "cache"))
    out = subprocess.run(["bash", os.path.join(TOP, "tools", "bootstrap.sh")], env=env,
                         capture_output=True, text=True, timeout=600)
    text = out.stdout + out.stderr
    assert "No such file or directory" not in text
    assert out.returncode != 0 and "Set LAMMPS_ROOT to a LAMMPS source tree" in text


def test_check_script_refuses_a_tree_without_version(tmp_path):
    out = subprocess.run(["bash", os.path.join(TOP, "tools", "check_lammps_version.sh"),
                          str(tmp_path)], capture_output=True, text=True, timeout=60)
    assert out.returncode != 0 and f"no src/version.h in {tmp_path}" in out.stdout
