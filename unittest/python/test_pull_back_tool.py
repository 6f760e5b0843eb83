"""tools/pull_back.py, the spall strength from a free-surface velocity history: a synthetic
record with a known pull-back (flat plateau and minimum, so the running mean leaves them
exact), read from a fix ave/time-like file by the command line and by the module, and its
errors."""
import os
import subprocess
import sys

import numpy as np
import pytest

TOOLS = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "tools"))
TOOL = os.path.join(TOOLS, "pull_back.py")
sys.path.insert(0, TOOLS)
from pull_back import pull_back  # noqa: E402


def record(path, plateau=400.0, drop=139.0):
    """A VISAR record: rest, a rise to the plateau at 10 ns, the plateau for 30 ns, a fall by
    `drop` over 5 ns, 10 ns at the minimum, a rise again; 1 ns per record, the step first."""
    t = np.arange(0.0, 100e-9, 1e-9)
    v = np.interp(t, [0, 10e-9, 12e-9, 42e-9, 47e-9, 57e-9, 62e-9, 100e-9],
                  [0, 0, plateau, plateau, plateau - drop, plateau - drop, plateau, plateau])
    with open(path, "w") as f:
        f.write("# Time-averaged data for fix visar\n# TimeStep v_now v_vfree\n")
        for k, (ti, vi) in enumerate(zip(t, v)):
            f.write(f"{10 * k} {ti!r} {vi!r}\n")
    return t, v


def test_command_line_and_module_read_the_known_pull_back(tmp_path):
    t, v = record(tmp_path / "a.visar")
    out = subprocess.run([sys.executable, TOOL, str(tmp_path / "a.visar"), "--rho0", "2700",
                          "--c0", "6386", "--flyer", "1.41e-4"], capture_output=True, text=True,
                         check=True).stdout
    assert "pull-back dU = 139" in out
    assert f"= {0.5 * 2700 * 6386 * 139.0:.6g}" in out       # 1.19838e+09 Pa
    tp, vp, tm, vm = pull_back(t, v, 2 * 1.41e-4 / 6386)
    assert (vp, vm) == (pytest.approx(400.0), pytest.approx(261.0))
    assert 12e-9 <= tp <= 42e-9 and 47e-9 <= tm <= 57e-9


def test_rebound_takes_the_minimum_before_the_spall_signal(tmp_path):
    """A ringing face: the pull-back's minimum (300 m/s below the plateau), the spall signal's
    rise, then a deeper ring within the pulse duration: the window rule reads the ring, the
    rebound rule the pull-back."""
    t = np.arange(0.0, 100e-9, 1e-9)
    v = np.interp(t, [0, 10e-9, 12e-9, 30e-9, 35e-9, 40e-9, 45e-9, 50e-9, 55e-9, 60e-9],
                  [0, 0, 1000, 1000, 700, 700, 950, 300, 300, 900])
    tp, vp, tm, vm = pull_back(t, v, 50e-9)
    assert vm == pytest.approx(300.0)
    tp, vp, tm, vm = pull_back(t, v, 50e-9, rebound=0.1)
    assert vm == pytest.approx(700.0) and 35e-9 <= tm <= 40e-9


@pytest.mark.parametrize("args,message", [
    (["--rho0", "2700", "--c0", "6386"], "one of the arguments --flyer --pulse is required"),
    (["--rho0", "0", "--c0", "6386", "--pulse", "1e-8"], "--rho0 must be positive"),
    (["--rho0", "2700", "--c0", "-1", "--pulse", "1e-8"], "--c0 must be positive"),
    (["--rho0", "2700", "--c0", "6386", "--pulse", "1e-8", "--velocity-column", "7"],
     "cannot read the time and velocity columns"),
    (["--rho0", "2700", "--c0", "6386", "--pulse", "1e-8", "--smooth", "0"],
     "--smooth must be at least 1"),
    (["--rho0", "2700", "--c0", "6386", "--pulse", "1e-8", "--rebound", "1.5"],
     "--rebound must be in [0, 1)"),
])
def test_bad_arguments(tmp_path, args, message):
    record(tmp_path / "a.visar")
    out = subprocess.run([sys.executable, TOOL, str(tmp_path / "a.visar"), *args],
                         capture_output=True, text=True)
    assert out.returncode == 2 and message in out.stderr


def test_a_record_without_a_shock_is_refused(tmp_path):
    record(tmp_path / "rest.visar", plateau=0.0, drop=0.0)
    out = subprocess.run([sys.executable, TOOL, str(tmp_path / "rest.visar"), "--rho0", "2700",
                          "--c0", "6386", "--pulse", "1e-8"], capture_output=True, text=True)
    assert out.returncode == 2 and "no shock arrived" in out.stderr
