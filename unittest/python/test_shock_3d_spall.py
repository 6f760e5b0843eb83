"""examples/shock-3d and examples/spall, reduced to fit CI (a 1 mm sample counted at 0.4 us
instead of 5 mm at 1.5 us; the plates as in the example), against the paper's statements."""
import os
import re
import sys

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp

EXAMPLES = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "examples"))
ENV = {"LAMMPS_PLUGIN_PATH": os.path.dirname(PLUGIN)}
sys.path.insert(0, os.path.join(EXAMPLES, "spall"))
os.environ.update(ENV)
import run_spall  # noqa: E402


def shock(tmp_path, nprocs=1, **var):
    script = open(os.path.join(EXAMPLES, "shock-3d", "in.shock3d")).read()
    args = []
    for k, v in {"length": 1e-3, "time": 4e-7, **var}.items():
        args += ["-var", k, str(v)]
    out = run_lmp(tmp_path, script, nprocs, env=ENV, args=args)
    dust = int(re.search(r"dust clusters beyond the body: (\d+)", out).group(1))
    vfree = float(re.search(r"free-surface speed \(front layer of the body\): ([-\d.]+)", out).group(1))
    return dust, vfree


def test_rc_1_2_no_dust_well_below_threshold_dust_well_above(tmp_path):
    assert shock(tmp_path, rc=1.2, u=800)[0] == 0      # paper: u_cr = 1.4 km/s for Rc = 1.2
    assert shock(tmp_path, rc=1.2, u=3000)[0] > 0


def test_relative_damping_removes_the_dust_of_rc_1_1_at_2_km_s(tmp_path):
    plain, damped = shock(tmp_path, rc=1.1, u=2000), shock(tmp_path, rc=1.1, u=2000, damp="relative")
    assert plain[0] > 0 and damped[0] == 0             # paper: the dust disappears completely
    assert damped[1] == pytest.approx(2 * 2000, rel=0.05)   # the free surface flies at about 2u


def test_two_ranks_give_the_serial_dust_count(tmp_path):
    # counted at 0.2 us, before the chaos of fracture amplifies the round-off differences of
    # another summation order (later the counts agree only statistically: 240 vs 224 at 0.4 us)
    serial = shock(tmp_path, rc=1.1, u=2000, time=2e-7)
    parallel = shock(tmp_path, 2, rc=1.1, u=2000, time=2e-7)
    assert serial[0] > 0 and parallel[0] == serial[0]


def test_spall_below_and_above_vd():
    assert not run_spall.run(0.7, "al-cluster-10um")["spall"]
    assert run_spall.run(1.5, "al-cluster-10um")["spall"]


def test_damping_holds_a_plate_that_spalls_undamped():
    """in.spall at 1.5 vd spalls undamped; with fix viscous/relative J = 10 it holds
    (examples/spall/damping.md: damping moves the threshold up) and the fix has removed about
    40 % of the impact's kinetic energy.  (The total energy is no oracle here: with the cut
    tail it jumps by Pi(1.3 a) = -0.54 D each time a pair crosses the cutoff, at the contact
    and in the shock.)"""
    assert run_spall.run(1.5, "al-cluster-10um")["spall"]
    damped = run_spall.run(1.5, "al-cluster-10um", J=10)
    assert not damped["spall"]
    assert 0.3 < damped["removed"] / damped["impact"] < 0.5


def test_linked_sample_two_ranks_and_thermal_seeds(tmp_path):
    # the neighbour-fixed model (link 1.05, dust on the link graph): the serial count on two
    # ranks at 0.2 us; a seed changes the count only through the 1 m/s thermal velocity
    serial = shock(tmp_path, rc=1.1, u=2000, time=2e-7, link=1.05)
    parallel = shock(tmp_path, 2, rc=1.1, u=2000, time=2e-7, link=1.05)
    assert serial[0] > 0 and parallel[0] == serial[0]
    seeded = [shock(tmp_path, rc=1.1, u=2000, time=2e-7, link=1.05, seed=s)[0] for s in (1, 2)]
    assert seeded[0] != seeded[1] and all(c > 0 for c in seeded)



sys.path.insert(0, EXAMPLES)
from shock_records import XT, histogram, shock_speed  # noqa: E402


def shock_records(tmp_path, **var):
    """A reduced in.shock3d run with records; its printed shock line: c0, c(u), dt."""
    args = []
    for k, v in {"length": 1e-3, "time": 4e-7, **var}.items():
        args += ["-var", k, str(v)]
    out = run_lmp(tmp_path, open(os.path.join(EXAMPLES, "shock-3d", "in.shock3d")).read(),
                  env=ENV, args=args)
    line = re.search(r"shock: c0 = (\S+) m/s, c\(u\) = (\S+) m/s, dt = (\S+) s", out)
    return out, [float(v) for v in line.groups()]


def test_hugoniot_point_obeys_rankine_hugoniot(tmp_path):
    """u = 2 km/s on the 1 mm sample: the shock front from the x-t data (fix ave/chunk) runs
    faster than sound (c0) and slower than the chain's c(u) (the fcc [100] bonds at 45 degrees
    stiffen less than the chain's); behind it the density is the Rankine-Hugoniot mass balance
    rho1/rho0 = Us/(Us - u) and the virial pressure the momentum balance rho0 Us u."""
    _, (c0, cu, dt) = shock_records(tmp_path, u=2000, time=3e-7, records=60)
    xt = XT(str(tmp_path / "shock3d.xt"), dt)
    times, fronts, us = shock_speed(xt, 2000.0, 1e-3)
    assert len(times) >= 8 and c0 < us < cu
    layer = xt.x[1] - xt.x[0]
    k = int(np.argmin(np.abs(xt.t - times[len(times) // 2])))
    behind = (xt.x >= 2000.0 * xt.t[k] + layer) & (xt.x <= fronts[len(fronts) // 2] - layer)
    rho0 = np.nanmedian(xt.density[(xt.x > 0.1e-3) & (xt.x < 0.9e-3), 0])
    rho1, p1 = np.nanmedian(xt.density[behind, k]), np.nanmedian(xt.pressure[behind, k])
    assert rho1 / rho0 == pytest.approx(us / (us - 2000.0), rel=0.03)
    assert p1 == pytest.approx(rho0 * us * 2000.0, rel=0.10)


def test_fragment_histograms_add_up_and_wall_piston_drives_at_u(tmp_path):
    """The example's fragment size histogram counts every fragment, its dust spectrum weighs
    the dust mass (fix ave/histo on compute dust's local rows); fix wall/piston drives the
    sample along z, and the free surface then flies at about 2u as with fix move."""
    out, _ = shock_records(tmp_path, rc=1.1, u=2000, records=0)
    nfrag, dust = re.search(r"of (\d+) fragments, dust mass (\S+)", out).groups()
    header = [line.split() for line in open(tmp_path / "shock3d.sizes")
              if not line.startswith("#") and len(line.split()) == 6][-1]
    total, missing = float(header[2]), float(header[3])     # missing: over 50 (the body ...)
    sizes = histogram(str(tmp_path / "shock3d.sizes"))[1]
    spectrum = histogram(str(tmp_path / "shock3d.spectrum"))[1]
    assert total + missing == int(nfrag) > 5 and missing >= 1 and sizes.sum() == total
    assert spectrum.sum() == pytest.approx(float(dust), rel=1e-10)
    _, vfree = shock(tmp_path, rc=1.1, u=2000, piston="wall", damp="relative")
    assert vfree == pytest.approx(4000, rel=0.05)


def test_spall_strength_from_the_pull_back_matches_the_virial_tension(tmp_path):
    """The simulated VISAR record of a 1.3 vd impact (fcc [100], 4x4 cells): the free surface
    first flies at the impact speed (velocity doubling of a symmetric impact), and the spall
    strength from its pull-back (tools/pull_back.py with one speed, a lattice of clusters:
    sigma_sp = 1/2 rho0 c_l dU, Kanel's delta = 0) is the largest tension the x-t virial pressure
    shows, within 20 %."""
    r = run_spall.record(1.3, 1, 1.0, root=str(tmp_path), pot="al-cluster-10um", cells=4)
    assert r["large"] >= 2
    assert r["peak"][1] == pytest.approx(r["v"], rel=0.08)
    assert r["sigma"] == pytest.approx(r["tension"], rel=0.2)


def test_spall_assumptions_thick_impactor_and_fcc_111():
    """examples/spall/run_assumptions.py: an impactor as thick as the target does not spall it
    at 1.5 vd (the release waves meet at its rear face); with [111] along the impact the
    threshold drops below the [100] one (1.17 against 1.25 vd): at 1.2 vd [111] spalls and
    [100] does not (seed 1, 1 m/s thermal start)."""
    base = {"pot": "al-cluster-10um", "seed": 1, "vtherm": 1.0}
    assert not run_spall.run(1.5, flyer=20, **base)["spall"]
    assert run_spall.run(1.2, orient=111, flyer=6, target=12, **base)["spall"]
    assert not run_spall.run(1.2, **base)["spall"]
