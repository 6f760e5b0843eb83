"""examples/runner.py, the module every example and study script runs LAMMPS through
(doc/Developer.rst, "The example scripts"): a run's folder name and kept result, the parsing of
LAMMPS's output and logs, the tables; and one input run both ways (in this process and as an
lmp command) with the same thermo output."""
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..",
                                                "examples")))
import runner  # noqa: E402

LOG = """LAMMPS (4 Feb 2025)
  Step          Temp          PotEng
         0   0              -6.7733681
        50   1.2            -5.0
Loop time of 0.25 on 2 procs for 50 steps with 4000 atoms

   Step          Temp          PotEng
        50   1.2            -5.0
       100   1.5            -4.5
Loop time of 0.5 on 2 procs for 50 steps with 4000 atoms
Total wall time: 0:01:05
"""

# a small Lennard-Jones crystal, run 20 steps (stock LAMMPS only)
INPUT = """variable steps index 10
units lj
lattice fcc 0.8442
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.0 87287 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
fix 1 all nve
thermo 5
run ${steps}
"""


def test_tag_names_a_run_by_its_sorted_settings():
    assert runner.tag({"u": 2000, "rc": 1.1}) == "rc1.1-u2000"
    assert runner.var_args({"a": 1, "b": "x y"}) == ["-var", "a", "1", "-var", "b", "x y"]


def test_keep_makes_a_result_once_and_reads_it_after(tmp_path):
    calls = []

    def make(workdir):
        calls.append(workdir)
        assert os.path.isdir(workdir)             # made before the run
        return {"dust": 3, "u": [1.0, 2.0]}

    folder = str(tmp_path / "run")
    assert runner.kept(folder) is None
    first = runner.keep(folder, make)
    second = runner.keep(folder, make)
    assert first == second == {"dust": 3, "u": [1.0, 2.0]}
    assert len(calls) == 1
    assert runner.kept(folder) == first


def test_log_readers(tmp_path):
    log = tmp_path / "log.lammps"
    log.write_text(LOG)
    assert runner.loops(LOG) == [(0.25, 2, 50, 4000), (0.5, 2, 50, 4000)]
    rows = runner.thermo(str(log))
    assert rows.shape == (4, 3)                   # both runs' rows, one after the other
    assert rows[-1].tolist() == [100.0, 1.5, -4.5]
    assert runner.finished(str(log))
    assert runner.wall_time(str(log)) == 65
    assert not runner.finished(str(tmp_path / "missing.log"))


def test_tables():
    assert runner.mean_sd([1.0, 2.0, 3.0]) == "2.00 ± 1.00"
    assert runner.mean_sd([1000.0, 3000.0], digits=1, scale=1000.0) == "2.0 ± 1.4"
    assert runner.table(["a", "b"], [[1, 2.5]]) == ["| a | b |", "|---|---|", "| 1 | 2.5 |"]


def test_one_input_run_in_process_and_as_a_command(tmp_path):
    """The same input and -var settings through the lammps module and through lmp: the same
    steps and the same final potential energy (to the printed digits)."""
    path = tmp_path / "in.crystal"
    path.write_text(INPUT)
    with runner.script(str(path), {"steps": 20}) as lmp:
        pe = lmp.get_thermo("pe")
        assert lmp.get_thermo("step") == 20
    out = runner.lmp_command(str(path), {"steps": 20}, str(tmp_path))
    assert [l[3] for l in runner.loops(out)] == [108]
    last = [l.split() for l in out.splitlines() if l.split()[:1] == ["20"]][-1]
    assert float(last[2]) == pytest.approx(pe, rel=1e-6)
    assert np.isfinite(pe)
