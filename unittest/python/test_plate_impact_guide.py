"""doc/plate_impact.rst: its template is examples/spall/in.plate as printed; it runs, spalls the
aluminium clusters' target at 2000 m/s (1.38 vd, above the 1.2-1.3 vd threshold of
examples/spall), and the pull_back.py command it prints reads a spall strength between
examples/spall's 8.48 and 10.93 GPa at 1.3 and 1.5 vd (4 x 4 cells; 5 % margins).  The copper
set at 400 m/s (the issue's case: a spalled layer split for a few records into pieces below
maxsize, and the old template read the dip as 4.4 GPa): the record is either refused for its
gap, naming the records, or read below half the metal's strength, over an ensemble."""
import os
import re
import shlex
import subprocess
import sys

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TEMPLATE = os.path.join(ROOT, "examples", "spall", "in.plate")
sys.path.insert(0, os.path.join(ROOT, "examples", "spall"))
os.environ["LAMMPS_PLUGIN_PATH"] = os.path.dirname(PLUGIN)
import run_plate_ensembles  # noqa: E402

SIGMA = r"sigma_sp = 1/2 rho0 c_b \(dU \+ delta\) = (\S+)"    # pull_back.py's strength


def printed_template():
    """The first LAMMPS code block of the guide, as printed."""
    text = open(os.path.join(ROOT, "doc", "plate_impact.rst")).read()
    block = text.split(".. code-block:: LAMMPS\n\n", 1)[1]
    lines = []
    for line in block.splitlines():
        if line and not line.startswith("   "):
            break
        lines.append(line[3:])
    return "\n".join(lines).strip() + "\n"


def test_the_printed_template_is_the_example_file():
    assert printed_template() == open(TEMPLATE).read()


def read_printed_command(out, workdir):
    """Run the pull_back.py command line the template prints at its end."""
    words = shlex.split(re.search(r"read it: (.*)", out).group(1))
    assert words[0] == "/usr/bin/python3"
    assert os.path.samefile(words[1], os.path.join(ROOT, "tools", "pull_back.py"))
    return subprocess.run(words, capture_output=True, text=True, cwd=workdir)


def test_template_runs_spalls_and_gives_the_pull_back(tmp_path):
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + printed_template())
    assert "large fragments of the target: 2; the face jumped 0 times" in out
    assert "WARNING: Pair morse/spline: time step" not in out
    tool = read_printed_command(out, tmp_path)
    assert tool.returncode == 0, tool.stderr
    sigma = float(re.search(SIGMA, tool.stdout).group(1))
    assert 0.95 * 8.48e9 < sigma < 1.05 * 10.93e9, tool.stdout
    speeds = re.search(r"c_b = (\S+), c_l = (\S+), dU = \S+, delta = (\S+)\)", tool.stdout)
    assert speeds.group(1) == speeds.group(2) and float(speeds.group(3)) == 0.0  # one speed
    # the printed density is the clusters' lattice's, m / (a^3 / sqrt 2), and c0 (--c-long, the
    # one speed of a lattice) the chain's a sqrt(C/m) = alpha a sqrt(2 D / m) of the set
    # (2.46e-6 J, 3.76e5 /m, 2.338e-12 kg)
    rho0 = float(re.search(r"--rho0 (\S+)", out).group(1))
    c0 = float(re.search(r"--c-long (\S+)", out).group(1))
    assert "--c-bulk" not in out
    assert rho0 == pytest.approx(2.338e-12 / (1e-5 ** 3 / np.sqrt(2)), rel=1e-5)
    assert c0 == pytest.approx(3.76 * np.sqrt(2 * 2.46e-6 / 2.338e-12), rel=1e-5)


# the copper set as the issue's user had it (potentials/cu-hugoniot-10um.cd before the set was
# regenerated, which moved its numbers in the 9th digit)
ISSUE_COPPER = """variable pot_rc    equal  1.0056101769895145
variable pot_units string si
variable pot_style string morse/spline
variable pot_coeff string "1.981543046372229e-06 497333.48267990514 1e-05 kappa 1"
variable pot_m     equal  6.3144635559958705e-12
variable pot_a     equal  1e-05
"""


def test_the_issues_copper_case_is_refused_or_read_low(tmp_path):
    """The issue's case: that copper set at 400 m/s from rest.  On this CPU its spalled layer
    splits into pieces below maxsize: the face jumps 4 times, the template reads nothing (one
    large fragment at the end), and pull_back.py given the record with the template's
    numbers refuses it for its gap, naming the records, where the old template read 4.4 GPa
    (3 times the metal's); a CPU whose round-off keeps the layer whole has no gap, and the
    record then reads below half the metal's 1.5 GPa."""
    (tmp_path / "cu-issue.cd").write_text(ISSUE_COPPER)
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + open(TEMPLATE).read(),
                  env={"LAMMPS_POTENTIALS": str(tmp_path)},
                  args=("-var", "pot", "cu-issue", "-var", "v", "400"))
    jumps = int(float(re.search(r"the face jumped (\S+) times", out).group(1)))
    large = int(re.search(r"large fragments of the target: (\d+)", out).group(1))
    assert ("read it:" in out) == (large >= 2)
    rho0, c0, flyer = re.search(r"rho0 = (\S+), c0 = (\S+) along the impact; flyer (\S+) thick",
                                out).group(1, 2, 3)
    tool = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "pull_back.py"),
                           "plate.visar", "--rho0", rho0, "--c-long", c0, "--flyer", flyer,
                           "--rebound", "0.1", "--jump-column", "5"], capture_output=True,
                          text=True, cwd=tmp_path)
    record = np.loadtxt(tmp_path / "plate.visar")
    if jumps:
        assert tool.returncode == 2 and "the face record has a gap" in tool.stderr
        assert re.search(r"line \d+ \(t = ", tool.stderr)
        # each jump is where the face moved back by more than the layer's depth
        k = np.nonzero(np.diff(record[:, 5]))[0] + 1
        assert np.all(np.abs(np.diff(record[:, 3])[k - 1]) > 2e-5)
    else:
        sigma = float(re.search(SIGMA, tool.stdout).group(1))
        assert 0 < sigma < 0.5 * 1.5e9


def test_copper_ensemble_never_reads_above_the_strength():
    """run_plate_ensembles.py reduced (from rest and 3 seeds at 400 m/s): every record is read
    below half the metal's strength, refused for a gap, or not read for want of a spall (as
    the template: fewer than 2 large fragments); the summary row counts them."""
    runs = run_plate_ensembles.ensemble("cu-hugoniot-10um", 400.0, 3)
    for r in runs:
        if r.get("refused") == "no spall":
            assert len(r["fragments"]) < 2, r
        elif "refused" in r:
            assert "the face record has a gap" in r["refused"] and r["jumps"] > 0, r
        else:
            assert 0 < r["sigma"] < 0.5 * 1.5e9, r
    row = run_plate_ensembles.summary(runs, 1.5e9)
    assert row[0] == 4 and sum(row[1:5]) == 4


CALIBRATE = os.path.join(ROOT, "tools", "cd_calibrate.py")
# handbook data of copper, tantalum and magnesium; tantalum's strength within each bcc
# direction's range (its floor 6 % beyond the second shell), not the metal's 5.1 GPa
METALS = {"fcc": ["--density", "8930", "--hugoniot", "3940", "1.49", "--spall-strength", "1.5e9"],
          "bcc": ["--density", "16650", "--hugoniot", "3414", "1.20", "--spall-strength", "30e9"],
          "hcp": ["--density", "1740", "--hugoniot", "4520", "1.24", "--spall-strength", "1e9"]}


@pytest.mark.parametrize("lattice,orient,units", [
    ("fcc", "110", "si"), ("fcc", "111", "si"), ("bcc", "100", "si"), ("bcc", "111", "si"),
    ("bcc", "110", "lj"), ("hcp", "0001", "si"), ("hcp", "2-1-10", "lj"), ("hcp", "01-10", "si")])
def test_template_builds_every_lattice_of_a_set_periodic(tmp_path, lattice, orient, units):
    """A metal set names its lattice and direction; the template builds the plates in whole
    periods across and along the impact: the target's density from LAMMPS's atom count and box
    is the metal's (exact only if the box is periodic: LAMMPS's own spacings are not on fcc
    [111], bcc [110] and [111]), its c0 the Hugoniot's, the flyer the whole periods nearest
    10 sqrt(2) a, the flyer half the target, atom for atom (the plane at x = 0 inside the box).
    In units lj the set gives the lattice command its number density."""
    args = METALS[lattice][:-1] + [{("bcc", "110"): "20e9"}.get((lattice, orient),
                                                               METALS[lattice][-1])]
    made = {u: subprocess.run([sys.executable, CALIBRATE, *args, "--size", "1e-5", "--lattice",
                               lattice, "--orientation", orient, "--up", "200", "--units", u],
                              capture_output=True, text=True) for u in {"si", units}}
    assert made[units].returncode == 0, made[units].stderr
    (tmp_path / "metal.cd").write_text(made[units].stdout)
    # lj: a, m and D of the set are the units: to SI by the SI set's m and D
    m_si = float(re.search(r"variable pot_m\s+equal\s+(\S+)", made["si"].stdout).group(1))
    d_si = float(re.search(r'pot_coeff string "(\S+)', made["si"].stdout).group(1))
    speed, mass, length = ((1.0, 1.0, 1.0) if units == "si" else
                           (np.sqrt(d_si / m_si), m_si, 1e-5))
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + open(TEMPLATE).read(),
                  env={"LAMMPS_POTENTIALS": str(tmp_path)},
                  args=("-var", "pot", "metal", "-var", "v", f"{300 / speed!r}"))
    got = re.search(r"target: (\w+) \[(\S+)\], rho0 = (\S+), c0 = (\S+) along the impact; "
                    r"flyer (\S+) thick", out)
    assert got.group(1, 2) == (lattice, orient)
    rho0, c0, flyer = (float(got.group(k)) for k in (3, 4, 5))
    rho0, c0, flyer = rho0 * mass / length ** 3, c0 * speed, flyer * length
    assert rho0 == pytest.approx(float(args[1]), rel=1e-5)
    assert c0 == pytest.approx(float(args[3]), rel=1e-5)
    assert abs(flyer - 10 * np.sqrt(2) * 1e-5) < 1.8e-5     # whole periods: at most 3.3 a
    counts = [int(n) for n in re.findall(r"Created (\d+) atoms", out)]
    assert len(counts) == 2 and counts[1] == 2 * counts[0]
    assert ("read it:" in out) == (int(re.search(r"large fragments of the target: (\d+)",
                                                 out).group(1)) >= 2)
