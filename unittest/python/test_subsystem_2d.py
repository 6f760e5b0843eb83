"""examples/subsystem-2d, reduced: Chernyshev's method (fix descent/normalized) on the clamped
strip (units lj) and the Fig. 2 plate (units si).  Oracles: Hooke's slope from the law's
lattice modulus 2C/sqrt(3), LAMMPS's min_style fire on the same links and start, a SfePy
finite-element solution of the plate (plane stress, Poisson 1/3 as the lattice has)."""
import math
import os
import shutil

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp

EXAMPLE = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "subsystem-2d")


def example(tmp_path, name, nprocs=1, **var):
    text = open(os.path.join(EXAMPLE, name)).read()
    args = [a for k, v in var.items() for a in ("-var", k, str(v))]
    return run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + text, nprocs=nprocs, args=args)


def test_strip_follows_hooke_and_unloads_to_its_shape(tmp_path):
    example(tmp_path, "in.strip", nx=6, ny=30, deps=0.005, nload=2, nunload=2, imperfection=0,
            maxiter=20000, out="strip.dat")
    table = np.loadtxt(tmp_path / "strip.dat")
    e2d = 2 * (0.25 * 1.0 * 0.5) / math.sqrt(3)          # 2 C / sqrt(3), C = D n m / a^2
    slope = table[0, 1] / table[0, 0]
    assert slope == pytest.approx(e2d, rel=0.02)
    assert table[1, 1] / table[1, 0] == pytest.approx(e2d, rel=0.03)
    assert table[-1, 0] == pytest.approx(0, abs=1e-12) and abs(table[-1, 1]) < 1e-4 * table[1, 1]
    assert table[-1, 6] < 0.01                             # back to the lattice (a)
    assert not table[:, 3].any()                           # no link broke


def faces(path):
    d = np.loadtxt(path, skiprows=9)                       # id x y fx fy, sorted by id
    lower = d[:, 2] < d[:, 2].mean()
    return d, lower


def test_plate_descent_matches_fire_and_the_finite_element_mean(tmp_path):
    example(tmp_path, "in.plate", nx=6, maxiter=60000)
    shutil.move(tmp_path / "plate_faces_6.txt", tmp_path / "descent.txt")
    example(tmp_path, "in.plate", nx=6, solver="fire")
    descent, lower = faces(tmp_path / "descent.txt")
    fire, _ = faces(tmp_path / "plate_faces_6.txt")
    assert np.abs(descent[:, 4] - fire[:, 4]).max() < 5e-3 * np.abs(fire[:, 4]).max()
    mean_lower = -descent[lower, 4].sum() / 0.010 / 1e6     # MPa, compression positive
    mean_upper = descent[~lower, 4].sum() / 0.010 / 1e6
    assert mean_lower == pytest.approx(mean_upper, rel=1e-3)
    sfepy = pytest.importorskip("sfepy", reason="SfePy (python3-sfepy) is installed by "
                                "tools/bootstrap.sh; without it the FE comparison is skipped")
    import sys
    sys.path.insert(0, EXAMPLE)
    from plate_fe import solve
    x, fe_lower, _ = solve(1.0 / 3.0, 10, 100)
    fe_mean = -fe_lower.mean() / 1e6
    assert fe_mean == pytest.approx(72e3 * 0.03, rel=0.01)   # the clamps add 0.3 %
    assert mean_lower == pytest.approx(fe_mean, rel=0.03)    # 6 particles across: -1.8 %
