"""One cheap check per recommendation of doc/accuracy_vs_cost.rst, on the 1D chain (each run
well under a second): the numbers the page states, with margin."""
import os
import sys

from conftest import PLUGIN

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "examples", "chain-1d"))
os.environ["LAMMPS_PLUGIN_PATH"] = os.path.dirname(PLUGIN)
import run_study  # noqa: E402


def test_recommended_step_closes_the_energy_balance_where_t0_steps_fail():
    good = run_study.run(u=4000, damp="relative", dtrule="Tmin", theta=0.02)
    assert good["balance"] < 1e-3          # stated: 3-5e-4
    bad = run_study.run(u=4000, damp="relative", dtrule="T0", theta=0.04)
    assert not bad["balance"] < 1e-2       # stated: blows up


def test_energy_error_falls_as_dt_squared():
    coarse = run_study.run(u=2000, damp="relative", dtrule="Tmin", theta=0.04)["balance"]
    fine = run_study.run(u=2000, damp="relative", dtrule="Tmin", theta=0.02)["balance"]
    assert 3.0 < coarse / fine < 5.0


def test_shifted_cut_conserves_through_fracture_and_wagner_better():
    cut = run_study.run(u=2000, tail="cut")
    wagner = run_study.run(u=2000, tail="wagner")
    assert cut["detached"] > 0 and cut["balance"] < 2e-4      # stated: 5e-5
    assert wagner["balance"] < 2e-5                            # stated: 2e-6


def test_any_j_from_10_removes_the_surface_dust():
    assert run_study.run(u=2000, damp="relative", J=10)["detached"] == 0


def test_hard_cases_stay_finite_with_the_recommended_step():
    r = run_study.run(u=10000, tail="lagunov", dtrule="Tmin", theta=0.02)
    assert r["balance"] < 1e-3 and all(abs(v) < 1e5 for v in r["v"])
    r = run_study.run(u=2000, damp="relative", J=1, dtrule="Tmin", theta=0.02)
    assert r["balance"] < 1e-3
