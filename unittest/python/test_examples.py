"""The examples run as documented (lmp -in ..., plugin auto-loaded from LAMMPS_PLUGIN_PATH)
and print what the papers and the closed forms say."""
import os
import re
import subprocess

import pytest
from conftest import LMP, PLUGIN

EXAMPLES = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "examples"))


def run_example(name, script, *var, args=()):
    env = dict(os.environ, LAMMPS_PLUGIN_PATH=os.path.dirname(PLUGIN))
    cmd = [LMP, "-in", script, "-log", "none", "-nocite", *args]
    for k, v in var:
        cmd += ["-var", k, str(v)]
    out = subprocess.run(cmd, cwd=os.path.join(EXAMPLES, name), env=env, capture_output=True,
                         text=True, timeout=300)
    assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-2000:]
    return out.stdout


def chain(u, damp):
    out = run_example("chain-1d", "in.chain", ("u", u), ("damp", damp))
    surface = int(re.search(r"torn off the free surface: (\d+)", out).group(1))
    vfree = float(re.search(r"free-surface speed: ([-\d.]+)", out).group(1))
    removed = re.search(r"energy removed by the damping: ([-\d.e+]+|not tallied)", out).group(1)
    return surface, vfree, None if removed == "not tallied" else float(removed)


def test_chain_morse_4000_tears_off_at_least_ten_surface_clusters():
    assert chain(4000, "none")[0] >= 10  # paper: at least the last ten


def test_chain_2000_relative_damping_removes_surface_dust_absolute_slows_the_flight():
    none, relative, absolute = chain(2000, "none"), chain(2000, "relative"), chain(2000, "absolute")
    assert none[0] > 0 and none[2] == 0
    assert relative[0] == 0 and relative[2] > 0
    assert relative[1] == pytest.approx(2 * 2000, rel=0.05)  # velocity doubling (paper: ~2u)
    assert absolute[0] == 0 and absolute[1] < 0.6 * 2 * 2000  # fix viscous slows the flight
    assert absolute[2] is None    # stock fix viscous keeps no tally: said, not "0 J"


def test_chain_below_the_1d_onset_has_no_dust():
    assert chain(300, "none")[0] == 0  # u_cr,1D = 386 m/s for Rc = 1.2


def test_params_table_matches_closed_forms():
    out = run_example("params", "in.params")
    rows = {m.group(1).strip(): [float(x) for x in m.group(2).split("|")[:-1]]
            for m in re.finditer(r"^\| ([^|]+) \|((?: [-\d.e+]+ \|)+)$", out, re.M)}
    lj = rows["LJ"]
    assert lj[:5] == pytest.approx([0.1087, 2.909, 6.0, 32.25, 10.5], rel=2e-4)
    assert rows["Morse, alpha a = 6"][4] == pytest.approx(9.0, rel=1e-6)
    assert rows["4000"][0] == pytest.approx(0.76, abs=0.005)  # spec: y = 0.76 at 4 km/s
    assert "c0 = 5454 m/s, vd = 1451 m/s" in out


def shock3d(*var, args=()):
    return run_example("shock-3d", "in.shock3d", ("length", 4e-4), ("time", 3e-8),
                       ("records", 10), ("out", "/tmp/test_examples_shock3d"), *var, args=args)


def test_shock3d_runs_on_the_gpu_package():
    """The example under -sf gpu (morse/spline/gpu on pocl, host lists): the same shock as the
    CPU style, kinetic and potential energy of the last row within mixed precision's 1e-6."""
    def last_row(out):
        rows = re.findall(r"^\s+\d+\s+\S+\s+(\S+)\s+(\S+)\s+\S+\s+\S+\s+\d+\s+\d+\s*$", out, re.M)
        return [float(v) for v in rows[-1]]
    cpu = shock3d()
    gpu = shock3d(args=("-sf", "gpu", "-pk", "gpu", "1", "neigh", "no"))
    assert "Using acceleration for morse/spline:" in gpu
    ke, pe = last_row(cpu)
    assert ke > 0.0 and pe != 0.0    # the piston has moved the sample: numbers to compare
    assert last_row(gpu) == pytest.approx([ke, pe], rel=1e-6)


def test_shock3d_takes_the_sets_cut():
    """A metal's set carries its calibrated cut (pot_rc): in.shock3d runs it unless -var rc is
    given, and then warns; a set without one (the paper's clusters) keeps Rc = 1.2; the line on
    the paper's thresholds is printed for the paper's sets only."""
    rc = float(re.search(r"variable pot_rc\s+equal\s+(\S+)",
                         open(os.path.join(EXAMPLES, "..", "potentials",
                                           "cu-hugoniot-10um.cd")).read()).group(1))
    metal = shock3d(("pot", "cu-hugoniot-10um"), ("u", 200))
    assert float(re.search(r"Rc = (\S+), u =", metal).group(1)) == pytest.approx(rc, rel=1e-12)
    assert "a metal set (cu-hugoniot-10um" in metal and "threshold of its 3D runs" not in metal
    assert "WARNING: Rc" not in metal
    forced = shock3d(("pot", "cu-hugoniot-10um"), ("u", 200), ("rc", 1.2))
    assert "Rc = 1.2, u =" in forced and "WARNING: Rc = 1.2 is not the cut" in forced
    paper = shock3d(("u", 2000))
    assert "Rc = 1.2, u =" in paper and "threshold of its 3D runs 1400 m/s" in paper
    assert "WARNING: Rc" not in paper


def test_shock3d_says_when_the_face_jumped():
    """The copper set at u = 200 m/s, far above its dusting onset (30 m/s): layers leave the
    body's face, and the free-surface speed printed is that of the outermost piece; the run
    says so with compute free/surface's count of jumps (two thermal seeds: at least one has)."""
    said = []
    for seed in (1, 2):
        out = run_example("shock-3d", "in.shock3d", ("pot", "cu-hugoniot-10um"), ("u", 200),
                          ("length", 2e-3), ("time", 8e-7), ("seed", seed), ("records", 20),
                          ("out", "/tmp/test_examples_shock3d"))
        assert int(re.search(r"dust clusters beyond the body: (\d+)", out).group(1)) > 0
        said.append(re.search(r"the face jumped (\d+) times", out))
    assert any(said)
