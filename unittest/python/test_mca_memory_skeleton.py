"""bench/mca_memory_skeleton.cpp, the memory skeleton of pair mca's passes that
doc/benchmarks/bench_mca.md ("The data flow's own cost") reads: its half list holds every pair
within pair mca's cutoff with the skin once, and its rows every pair of nearest neighbours,
periodic images included (against minimum-image counts), so that a narrow plate is not cheaper
for missing pairs; a plate twice as wide sums four times as much
(periodic across: every share reaches its owner, every value its ghosts); the data flows that keep pair mca's results
(a gather, a packed force pass, the fused walks, one record) give the as-is flow's sums up to
their order, the two that drop data do not; bad arguments stop with the usage."""
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

SOURCE = Path(__file__).resolve().parents[2] / "bench" / "mca_memory_skeleton.cpp"
KEEP = ["volume-gather", "force-packed", "fused", "one-record"]


@pytest.fixture(scope="module")
def skeleton(tmp_path_factory):
    cxx = shutil.which("g++") or shutil.which("c++")
    if cxx is None:
        pytest.skip("no C++ compiler")
    exe = tmp_path_factory.mktemp("skeleton") / "skeleton"
    subprocess.run([cxx, "-O2", "-o", str(exe), str(SOURCE)], check=True)
    return exe


def run(exe, width, flow, steps=3):
    out = subprocess.run([str(exe), str(width), str(steps), flow], capture_output=True, text=True,
                         check=True).stdout
    m = re.search(r"elements (\d+) ghosts (\d+) entries/element ([0-9.]+) walked/element ([0-9.]+) "
                  r"rows/element ([0-9.]+).*all ([0-9.]+)\s+sums: volume (\S+) heat (\S+) force (\S+)",
                  out)
    assert m, out
    n, ghosts = int(m.group(1)), int(m.group(2))
    entries, walked, per, time, volume, heat, force = (float(m.group(k)) for k in range(3, 10))
    return dict(n=n, ghosts=ghosts, entries=entries, walked=walked, per=per, time=time,
                volume=volume, heat=heat, force=force)


def pairs_within(width, cut, length=30):
    """pairs closer than cut in the plate: fcc, unit nearest distance, periodic across (y, z)"""
    a = np.sqrt(2.0)
    basis = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
    cells = np.array([(i, j, k) for i in range(length) for j in range(width) for k in range(width)])
    pos = ((cells[:, None, :] + basis[None] + 0.25) * a).reshape(-1, 3)
    box = np.array([length, width, width]) * a
    pairs = 0
    for p in pos:
        d = pos - p
        d[:, 1:] -= box[1:] * np.round(d[:, 1:] / box[1:])
        r = np.sqrt((d * d).sum(axis=1))
        pairs += np.count_nonzero((r > 0) & (r < cut))
    return len(pos), pairs // 2


@pytest.mark.parametrize("width", [3, 4, 7])
def test_the_half_list_holds_every_pair_once(skeleton, width):
    got = run(skeleton, width, "as-is")
    # pair mca's list on the example's plate: 1.875 d with the skin, 20.6 entries per element
    n, entries = pairs_within(width, 1.875)
    assert got["n"] == n
    assert got["entries"] == pytest.approx(entries / n, abs=0.006)
    # the passes walk the pairs within the reach, (1 + tolerance) d + skin: two shells, 9
    n, near = pairs_within(width, 1.62)
    assert got["walked"] == pytest.approx(near / n, abs=0.006)
    # rows for the links only: 12 nearest neighbours inside, fewer on the free ends along x
    n, links = pairs_within(width, 1.2)
    assert got["per"] == pytest.approx(links / n, abs=0.006)
    assert got["ghosts"] > 0 and got["time"] > 0


@pytest.mark.parametrize("flow", ["as-is"] + KEEP)
def test_a_plate_twice_as_wide_sums_four_times_as_much(skeleton, flow):
    # periodic across: the 8 x 8 plate is the 4 x 4 one four times over, element for element, if
    # every share reaches its owner and every value its ghosts
    small, wide = run(skeleton, 4, flow), run(skeleton, 8, flow)
    assert wide["n"] == 4 * small["n"]
    for key in ("volume", "heat", "force"):
        assert wide[key] == pytest.approx(4 * small[key], rel=1e-7, abs=0), key


@pytest.mark.parametrize("flow", KEEP)
def test_the_flows_that_keep_the_results_keep_the_sums(skeleton, flow):
    ref, got = run(skeleton, 4, "as-is"), run(skeleton, 4, flow)
    for key in ("volume", "force"):
        assert got[key] == pytest.approx(ref[key], rel=1e-12, abs=0), key
    # the heat's shares are added in another order by some flows
    assert got["heat"] == pytest.approx(ref["heat"], rel=1e-7, abs=0)
    assert ref["volume"] > 0 and ref["heat"] > 0 and ref["force"] > 0


def test_the_flows_that_drop_data_change_the_sums(skeleton):
    ref = run(skeleton, 4, "as-is")
    # the volume pass's shares to the partners left out: half of each pair's volume
    assert run(skeleton, 4, "volume-own")["volume"] == pytest.approx(0.5 * ref["volume"], rel=1e-12)
    # one row for all pairs: the pairs' state is lost
    assert run(skeleton, 4, "no-rows")["force"] != pytest.approx(ref["force"], rel=1e-3)


@pytest.mark.parametrize("args", [[], ["5", "10"], ["2", "10", "as-is"], ["5", "0", "as-is"],
                                  ["5", "10", "gather"]])
def test_bad_arguments_stop_with_the_usage(skeleton, args):
    out = subprocess.run([str(skeleton)] + args, capture_output=True, text=True)
    assert out.returncode == 1
    assert "mca_memory_skeleton" in out.stderr and out.stdout == ""
