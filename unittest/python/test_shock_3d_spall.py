"""examples/shock-3d and examples/spall, reduced to fit CI (a 1 mm sample counted at 0.4 us
instead of 5 mm at 1.5 us; the plates as in the example), against the paper's statements."""
import os
import re
import sys

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


def test_linked_sample_two_ranks_and_thermal_seeds(tmp_path):
    # the neighbour-fixed model (link 1.05, dust on the link graph): the serial count on two
    # ranks at 0.2 us; a seed changes the count only through the 1 m/s thermal velocity
    serial = shock(tmp_path, rc=1.1, u=2000, time=2e-7, link=1.05)
    parallel = shock(tmp_path, 2, rc=1.1, u=2000, time=2e-7, link=1.05)
    assert serial[0] > 0 and parallel[0] == serial[0]
    seeded = [shock(tmp_path, rc=1.1, u=2000, time=2e-7, link=1.05, seed=s)[0] for s in (1, 2)]
    assert seeded[0] != seeded[1] and all(c > 0 for c in seeded)
