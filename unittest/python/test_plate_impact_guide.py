"""doc/plate_impact.rst: its template input runs as printed, spalls the aluminium clusters'
target at 2000 m/s (1.38 vd, above the 1.2-1.3 vd threshold of examples/spall), and
tools/pull_back.py (--rebound 0.1, as the guide says) reads from its record a spall strength
between examples/spall's 8.49 and 10.99 GPa at 1.3 and 1.5 vd (4 x 4 cells; 5 % margins)."""
import os
import re
import subprocess
import sys

from conftest import PLUGIN, run_lmp

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def template():
    """The first LAMMPS code block of the guide, as printed."""
    text = open(os.path.join(ROOT, "doc", "plate_impact.rst")).read()
    block = text.split(".. code-block:: LAMMPS\n\n", 1)[1]
    lines = []
    for line in block.splitlines():
        if line and not line.startswith("   "):
            break
        lines.append(line[3:])
    return "\n".join(lines).strip() + "\n"


def test_template_runs_spalls_and_gives_the_pull_back(tmp_path):
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + template())
    assert "large fragments of the target: 2" in out
    assert "WARNING: Pair morse/spline: time step" not in out
    tool = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "pull_back.py"),
                           str(tmp_path / "plate.visar"), "--rho0", "3306", "--c0", "5454",
                           "--flyer", "1.414e-4", "--rebound", "0.1"], capture_output=True,
                          text=True, check=True)
    sigma = float(re.search(r"1/2 rho0 c0 dU = (\S+)", tool.stdout).group(1))
    assert 0.95 * 8.49e9 < sigma < 1.05 * 10.99e9, tool.stdout
