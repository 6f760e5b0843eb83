"""examples/mca-spall, reduced (issue 27): the aluminium plate impact with movable cellular
automata, with peridynamics (pair peri/lps) and with cluster dynamics on the same plates.

Oracles: the acoustic theory of a symmetric impact at v (the free surface flies at v, the
tension where the release waves meet is 1/2 rho c_L v, c_L = sqrt((K + 4G/3) / rho)), the
spall strength given to the models (1.2 GPa) read back from the pull-back by tools/pull_back.py
(elastic elements: one speed, 1/2 rho c_L dU; yielding elements: Kanel's 1/2 rho c_b (dU +
delta) with the bulk speed c_b = sqrt(K/rho) beside c_L), and the cluster-dynamics threshold
of examples/spall (1.2-1.25 vd, vd = 1451 m/s)."""
import math
import os
import re
import sys

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp

EXAMPLES = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "examples"))
sys.path.insert(0, EXAMPLES)
from shock_records import XT, spall_strength  # noqa: E402

RHO, K, G, SIGMA = 2700.0, 75.5e9, 26.1e9, 1.2e9
C_L = math.sqrt((K + 4.0 * G / 3.0) / RHO)
C_B = math.sqrt(K / RHO)
LATERAL = (K - 2.0 * G / 3.0) / (K + 4.0 * G / 3.0)     # sigma_yy / sigma_xx in uniaxial strain
FLYER = 10 * math.sqrt(2.0) * 1e-5


def plate(tmp_path, method, v, **var):
    """in.plate (with the plugin under test) in tmp_path: spall (0/1), the free-surface
    velocity history and the x-t records (their times in steps)."""
    text = open(os.path.join(EXAMPLES, "mca-spall", "in.plate")).read()
    args = [a for k, x in dict(method=method, v=v, **var).items() for a in ("-var", k, str(x))]
    out = run_lmp(tmp_path, text.replace("clusterdynplugin.so", PLUGIN), args=args)
    spall = int(re.search(r"spall: (\d)", out).group(1))
    t, u = np.loadtxt(tmp_path / "plate.visar", usecols=(1, 2), unpack=True)
    xt = XT(tmp_path / "plate.xt", 1.0) if var.get("records", 200) else None   # times in steps
    return spall, t, u, xt


@pytest.mark.parametrize("speed,spall", [(110, 0), (120, 1)])
def test_elements_spall_between_110_and_120_m_s(tmp_path, speed, spall):
    """Elements of strength 1.2 GPa: no spall at 110 m/s, spall at 120 m/s, below the acoustic
    threshold 161 m/s (the pairs at 45 degrees to the impact carry 0.87 sigma_xx, so they
    break at sigma_xx = 1.39 GPa = 1/2 rho c_L v): the tension overshoots the acoustic value
    behind the sharp elastic fronts of a lattice of elements; the layers' largest virial
    tension is 1.26 times the acoustic mean stress at 120 m/s.  Near the threshold the free
    surface falls almost to rest before the spall signal, and the pull-back gives the spall
    strength within 15 %."""
    got, t, u, xt = plate(tmp_path, "mca", speed)
    assert got == spall
    r = spall_strength(t, u, 2 * FLYER / C_L, RHO, C_L)     # elastic: one speed, delta = 0
    assert r.v_peak == pytest.approx(speed, rel=0.05)        # the free surface flies at v
    if spall:
        assert r.delta == 0.0 and r.sigma == pytest.approx(SIGMA, rel=0.15)
        acoustic_mean = 0.5 * RHO * C_L * speed * (1.0 + 2.0 * LATERAL) / 3.0
        assert -np.nanmin(xt.pressure) > 1.15 * acoustic_mean


def test_elements_pull_back_shrinks_far_above_the_threshold(tmp_path):
    """At 400 m/s (3.3 times the threshold) the sharp release fronts break the target where
    they meet at once, and the free surface sees little of the release: the pull-back is a
    fifth of the threshold's, so 1/2 rho c_L dU reads 0.2 GPa, not the 1.2 GPa of the
    material.  The pull-back measures the spall strength only for a release that ramps."""
    got, t, u, _ = plate(tmp_path, "mca", 400)
    assert got == 1
    assert spall_strength(t, u, 2 * FLYER / C_L, RHO, C_L).sigma < 0.4 * SIGMA


def test_yielding_elements_read_their_spall_strength_from_the_pull_back(tmp_path):
    """The same elements with a yield stress of 0.3 GPa: the release is elastic-plastic (an
    elastic front, then the plastic release), so the tension where the release waves meet
    builds up over time and the free surface sees the release until the target breaks: at
    300 m/s, where the elastic elements read 0.3 GPa, Kanel's 1/2 rho c_b (dU + delta) (the
    bulk speed c_b, c_L, the spall layer the flyer's thickness) gives the 1.2 GPa given within
    15 % (measured 1.12: delta 18 m/s on dU 138 m/s; the plain acoustic values beside, 1/2 rho
    c_b dU 0.99 and 1/2 rho c_L dU 1.19; 1.10 before the return about each element's weighted
    mean)."""
    got, t, u, _ = plate(tmp_path, "mca", 300, **{"yield": 0.3e9})
    r = spall_strength(t, u, 2 * FLYER / C_B, RHO, C_L, C_B, FLYER)
    assert got == 1
    assert r.delta > 0.0 and r.sigma == pytest.approx(SIGMA, rel=0.15)


def test_peridynamics_cuts_the_target_at_150_m_s(tmp_path):
    """peri/lps with the critical stretch sigma_sp / (K + 4G/3): at 150 m/s (above the acoustic
    threshold 139 m/s of the bonds along the impact) a layer of particles loses more than
    half of its bonds (the spall plane); the free surface flies at v."""
    got, t, u, _ = plate(tmp_path, "peri", 150, records=100)
    assert got == 1
    assert np.max(u) == pytest.approx(150, rel=0.15)


def test_cluster_dynamics_holds_at_400_m_s_on_the_same_plates(tmp_path):
    """The aluminium clusters of the dusting paper on the same plates (in.spall, 5 x 5 cells):
    no spall at 400 m/s, where the elements and peridynamics spall (its threshold is 1.2-1.25
    vd = 1750-1800 m/s: the ideal lattice's strength, not the metal's); the free surface
    flies at v on average over the pulse."""
    script = open(os.path.join(EXAMPLES, "spall", "in.spall")).read()
    out = run_lmp(tmp_path, script, env={"LAMMPS_PLUGIN_PATH": os.path.dirname(PLUGIN)},
                  args=["-var", "pot", "al-cluster-10um", "-var", "cells", "5", "-var", "ratio",
                        str(400 / 1451.0), "-var", "records", "100"])
    assert "spall: 0" in out
    t, u = np.loadtxt(tmp_path / "spall.visar", usecols=(1, 2), unpack=True)
    arrived = t[np.argmax(u > 200.0)]
    plateau = (t > arrived) & (t < arrived + 2 * FLYER / 5454.0)   # c0 of the clusters
    assert np.mean(u[plateau]) == pytest.approx(400, rel=0.1)  # the lattice's face rings about it
