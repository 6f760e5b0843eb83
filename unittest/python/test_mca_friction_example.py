"""examples/mca-friction (pair_style mca's contact segments, 2D): the example's measured claims
from its reduced runs (run_friction.py --quick, about 35 s on two cores).

- Amontons: the mean mu of a stiff-spring slide at loads 0.05 and 0.2 agree within 3 %.
- Prandtl-Tomlinson: the measured critical stiffness K_c = max(-dF/dx) lies within the range
  the roughness allows (closed form mu0 P A2_eff pi / l2 with the pieces' amplitudes in
  [A2/2, 3A2/2], and a residue of the loaded surface's ripple); a spring of 0.3 K_c sticks
  for a large part of the drive, one of 3 K_c (almost) never.
- Energy: the pair's friction work c_pw[6] equals the integral of F_fr over the block's path
  within 1 % in an elastic run.
- Element size: the relative spread of mu falls with the element's size as the contact
  length's average of the short wave, sinc(S / 2 l1), within 20 %.
- 3D (in.friction3d, about 4 s more): an fcc block dragged over a large counterface element
  and over fix wall/gran slides at mu0 (Coulomb's law of each contact) within 5 % at two
  loads, the loads' mu within 1 % of each other; the pair's friction work on the large element
  is the integral of F_fr over the block's path within 2 %.
- The running-in's profile measure (no run: the three laps are the full run's longest scene):
  the rms height and the mean |slope| of a sampled sine row, unsorted and across the period's
  wrap, are the closed forms a / sqrt(2) and 4 a / L."""
import math
import os
import sys

import numpy as np
import pytest

# an importable module: its runs go to worker processes (multiprocessing pickles by name)
sys.path.insert(0, os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..",
                                                "examples", "mca-friction")))
import run_friction  # noqa: E402


@pytest.fixture(scope="module")
def example():
    module = run_friction
    results, settings, kc = module.simulate(quick=True)
    table = {name: module.measure(name, results[name][0], settings[name]["V"])
             for name in settings}
    return module, table, kc


def test_amontons(example):
    _, table, _ = example
    high, low = table["stiff, load 0.2"], table["stiff, load 0.05"]
    assert high["FN"] == pytest.approx(0.2, rel=0.01)
    assert low["FN"] == pytest.approx(0.05, rel=0.01)
    assert high["mu"] == pytest.approx(low["mu"], rel=0.03)
    assert 0.2 < low["mu"] < 0.4    # mu0 0.3 times a block average of K_mu


def test_critical_stiffness_in_the_roughness_range(example):
    module, _, kc = example
    closed, _ = module.closed_form_kc(module.PT_LOAD)
    # the pieces' amplitudes are drawn in [A2/2, 3A2/2] (the steepest piece up to 1.5 times
    # the closed form), and the average over 1 leaves a residue of the loaded surface's ripple
    assert 0.5 * closed < kc < 2.0 * closed


def test_stick_slip_below_and_smooth_above_the_critical_stiffness(example):
    _, table, _ = example
    soft = table["K 0.3 K_c, V 0.01"]
    stiff = table["K 3.0 K_c, V 0.01"]
    assert soft["stick"] > 0.25
    assert stiff["stick"] < 0.08
    # the soft spring's block jumps: its top speed is above the drive's
    assert soft["vmax"] > 1.2


def test_friction_work_is_the_force_times_the_path(example):
    _, table, _ = example
    m = table["stiff, load 0.05"]
    assert m["broken"] == 0
    assert m["wfr"] == pytest.approx(m["work_path"], rel=0.01)
    assert m["work_drive"] >= m["wfr"]


def test_larger_elements_fluctuate_less_as_their_contact_averages(example):
    module, table, _ = example
    rel = {k: table[f"size: {k}"]["mu_sd"] / table[f"size: {k}"]["mu"]
           for k in ("diameter 1", "diameter 2", "no roughness")}
    l1 = float(module.SIZE_ROUGH.split()[1])

    def sinc(s):
        u = math.pi * s / (2 * l1)
        return math.sin(u) / u

    s1 = 2 * 0.5 / math.sqrt(3.0)                      # R_h of two discs of radius 0.5
    s2 = 2 * (2 * 1.0 * 0.5 / 1.5) / math.sqrt(3.0)    # R_h of radius 1 on radius 0.5
    assert rel["diameter 2"] / rel["diameter 1"] == pytest.approx(sinc(s2) / sinc(s1), rel=0.2)
    assert rel["no roughness"] < 0.2 * rel["diameter 2"]


@pytest.fixture(scope="module")
def example_3d():
    module = run_friction
    results, settings, _ = module.simulate_3d(quick=True)
    return module, {name: module.measure_3d(name, results[name], settings[name]["V"])
                    for name in settings}


def test_3d_flat_counterfaces_slide_at_mu0_at_two_loads(example_3d):
    """Every contact of the block's face with a flat counterface slides at mu0 times its
    normal force (Coulomb), so the block's mu is mu0 at any load."""
    module, table = example_3d
    low_load, high_load = module.LOADS_3D
    for wall in module.WALLS:
        low, high = table[f"3D {wall}, load {low_load}"], table[f"3D {wall}, load {high_load}"]
        assert low["FN"] == pytest.approx(low_load, rel=0.01)
        assert high["FN"] == pytest.approx(high_load, rel=0.01)
        assert low["mu"] == pytest.approx(module.MU0, rel=0.05), wall
        assert high["mu"] == pytest.approx(low["mu"], rel=0.01), wall
        assert low["stick"] < 0.05   # a stiff spring on a flat: it never stops


def test_3d_large_element_friction_work_is_the_force_times_the_path(example_3d):
    _, table = example_3d
    m = table["3D large, load 0.2"]
    assert m["broken"] == 0
    assert m["wfr"] == pytest.approx(m["work_path"], rel=0.02)


def test_profile_measure_of_a_sine_row_is_the_closed_form():
    """A row of 40 elements y = a sin(2 pi x / L) sampled one apart over the period L = 40 (its
    extremes among the samples), shuffled and shifted by a period: rms a / sqrt(2), and the
    mean |slope| between neighbours its total variation 4 a over L."""
    amplitude, period = 0.05, run_friction.LAP
    x = np.arange(40) * period / 40
    y = amplitude * np.sin(2 * np.pi * x / period)
    order = np.random.default_rng(7).permutation(len(x))
    rms, slope = run_friction.profile_stats(x[order] + period, y[order], period)
    assert rms == pytest.approx(amplitude / math.sqrt(2.0), rel=1e-12)
    assert slope == pytest.approx(4 * amplitude / period, rel=1e-12)
