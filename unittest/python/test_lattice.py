"""examples/lattice: Krivtsov & Krivtsova's Table 3, the equilibrium nearest distance of the
chain, the triangular lattice and fcc for Lennard-Jones cut at 2.1 a, from box/relax +
minimize with lj/spline, against the paper's seven digits and their closed form (eq 77)."""
import os
import re

import pytest
from conftest import PLUGIN, run_lmp

EXAMPLES = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "examples"))
ENV = {"LAMMPS_PLUGIN_PATH": os.path.dirname(PLUGIN)}
TABLE3 = {"chain": 0.9974599, "tri": 0.9917496, "fcc": 0.9784147}   # R1/a, the paper


@pytest.mark.parametrize("lattice", TABLE3)
def test_relaxed_nearest_distance_is_table_3(tmp_path, lattice):
    script = open(os.path.join(EXAMPLES, "lattice", "in.relax")).read()
    out = run_lmp(tmp_path, script, env=ENV, args=["-var", "lattice", lattice, "-var", "n", "4"])
    relaxed, closed, pressure = (float(v) for v in re.search(
        r"R1/a = (\S+) relaxed, (\S+) eq 77;.*pressure (\S+)", out).groups())
    assert relaxed == pytest.approx(TABLE3[lattice], abs=1e-7)
    assert closed == pytest.approx(TABLE3[lattice], abs=1e-7)
    assert abs(pressure) < 1e-10
