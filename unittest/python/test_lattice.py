"""examples/lattice: Krivtsov & Krivtsova's Table 3, the equilibrium nearest distance of the
chain, the triangular lattice and fcc for Lennard-Jones cut at 2.1 a, from box/relax +
minimize with lj/spline, against the paper's seven digits and their closed form (eq 77); their
Table 2 (wave speeds, E/K, Poisson) from compute born/matrix and simulated pulses."""
import os
import re
import sys

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp

EXAMPLES = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "examples"))
ENV = {"LAMMPS_PLUGIN_PATH": os.path.dirname(PLUGIN)}
os.environ.update(ENV)          # table2.py runs in.pulse in-process: it relies on auto-loading
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


sys.path.insert(0, os.path.join(EXAMPLES, "lattice"))
import table2  # noqa: E402


def rounds_to(value, paper):
    """The paper gives two decimals."""
    return abs(value - paper) <= 0.005 + 1e-12


@pytest.mark.parametrize("pot", ["lj-reduced", "al-cluster-10um"])
def test_table_2_from_born_matrix(pot):
    """Krivtsov's Table 2 from compute born/matrix with nearest-neighbour bonds (units lj and
    si): every number of the paper to its two decimals, the bulk modulus to eq 71 (K V0 / (C
    a^2) = (d + 1) / (2 d)) to 1e-12; the isotropy-plane row is the paper's only as the
    transversely isotropic part about [111]: the crystal itself has E/K = 3/2, shear speeds 1/2
    and 1/sqrt 2 and Poisson's ratios 1/6 (lateral [111]) and 1/3 (lateral [11-2])."""
    rows, c = table2.table(pot)
    for name, d in (("chain", 1), ("tri", 2), ("fcc", 3)):
        assert table2.bulk(c[name], d) == pytest.approx((d + 1) / (2 * d), rel=1e-12)
    for name, (vl, vs, ek, nus) in table2.PAPER.items():
        if name == "fcc [1-10], isotropy plane":
            continue
        ours_vl, ours_vs, ours_ek, ours_nus = rows[name]
        assert rounds_to(ours_vl, vl) and rounds_to(ours_ek, ek), name
        assert all(rounds_to(v, vs) for v in ours_vs) and all(rounds_to(n, nus) for n in ours_nus)
    vl, vs, ek, nus = table2.PAPER["fcc [1-10], isotropy plane"]
    t_vl, t_vs, t_ek, t_nus = rows["fcc [1-10], transversely isotropic part"]
    assert rounds_to(t_vl, vl) and rounds_to(max(t_vs), vs) and rounds_to(t_ek, ek)
    assert rounds_to(np.mean(t_nus), nus)
    c_vl, c_vs, c_ek, c_nus = rows["fcc [1-10], isotropy plane"]
    assert c_vl == pytest.approx(np.sqrt(5) / 2, rel=1e-12) and c_ek == pytest.approx(1.5, rel=1e-12)
    assert c_vs == pytest.approx([0.5, np.sqrt(0.5)], rel=1e-12)
    assert c_nus[:2] == pytest.approx([1 / 6, 1 / 3], rel=1e-12)


@pytest.mark.parametrize("pot,case", [("lj-reduced", ("tri", "100", "y")),
                                      ("lj-reduced", ("fcc", "111", "x")),
                                      ("lj-reduced", ("fcc", "110", "z")),
                                      ("al-cluster-10um", ("fcc", "100", "x"))])
def test_pulse_runs_at_the_born_matrix_speed(pot, case):
    """A Gaussian velocity pulse (width 8 a) splits and runs at the Christoffel speed of the
    born/matrix constants along its direction and polarization, within 0.2 % (measured 0.02 -
    0.07 %: the lattice's dispersion)."""
    (lattice, direction, pol, theory, measured), = table2.pulses(pot, [case])
    assert measured == pytest.approx(theory, rel=2e-3)
