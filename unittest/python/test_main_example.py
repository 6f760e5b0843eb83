"""The README's main command (tools/run_example.sh: examples/shock-3d's default scene, aluminium
clusters at u = 2 km/s, Rc = 1.2) prints what the README says it prints: a dust count within the
spread of the scene's ensemble (examples/shock-3d/thresholds.md: five thermal seeds; the run from
rest is one draw of a symmetric lattice, parted by round-off, so its count moves between
machines and kernels) and the paper's threshold, 1400 m/s for Rc = 1.2 (below 2 km/s: dust)."""
import re
import statistics
import subprocess

from doc_pages import TOP


def ensemble():
    """The five seeds' dust counts of the default scene (2x2 section, Rc 1.2, u 2000)."""
    text = (TOP / "examples" / "shock-3d" / "thresholds.md").read_text()
    m = re.search(r"^\| 2x2 \| 1\.2 \| 2000 \| \d+ \| [\d.]+ ± [\d.]+ \(([\d, ]+)\) \|$", text, re.M)
    assert m, "the default scene's row is not in thresholds.md"
    return [int(n) for n in m.group(1).split(",")]


def test_the_main_command_prints_the_readme_result():
    out = subprocess.run(["bash", str(TOP / "tools" / "run_example.sh")], capture_output=True,
                         text=True, timeout=900)
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    count = int(re.search(r"dust clusters beyond the body: (\d+)", out.stdout).group(1))
    seeds = ensemble()
    mean, sd = statistics.mean(seeds), statistics.stdev(seeds)
    assert 0 < count and abs(count - mean) <= 2.5 * sd, (count, seeds)
    assert re.search(r"1400 m/s", out.stdout)
    # the README quotes the same scene and the same ensemble
    readme = (TOP / "README.md").read_text()
    quoted = re.search(r"prints (\d+) dust clusters beyond the body.*?five thermal seeds give "
                       r"([\d.]+) ± ([\d.]+)", readme, re.S)
    assert quoted, "README.md does not quote the main command's result"
    assert abs(int(quoted.group(1)) - mean) <= 2.5 * sd
    assert float(quoted.group(2)) == round(mean, 1) and float(quoted.group(3)) == round(sd, 1)
