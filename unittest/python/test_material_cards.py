"""The shock material cards potentials/*.shock (potentials/README.md) against their own handbook
data:
- each card is sane: c_L = sqrt((K + 4G/3) / rho0) > c0 and Poisson's ratio from K = rho0 c0^2
  and G within 0.2-0.45; potentials/README.md lists it with its c_L and Hugoniot elastic limit;
- examples/mca-shock/in.piston reduced (a target of 30 cells) at two piston speeds inside the
  card's range (0.45 and 0.9 of its upmax) drives its plastic shock at the card's Hugoniot
  us = c0 + s up within 3 % (the oracle is the card file's c0 and s, parsed here; the front
  read from the x-t records as run_shock.py reads it);
- the inputs find the cards from the example's folder and from elsewhere (-var here), and an
  unknown card stops with an error naming the path tried.
About 20 s on one core.
"""
import glob
import math
import os
import re
import subprocess
import sys

import pytest

from conftest import LMP, PLUGIN
from test_mca_shock import EXAMPLE, example

sys.path.insert(0, EXAMPLE)
from run_shock import CARDS, CELL, card, front_speed  # noqa: E402
from shock_records import XT  # noqa: E402  (run_shock.py puts examples/ on the path)

NAMES = sorted(os.path.basename(p)[:-len(".shock")]
               for p in glob.glob(os.path.join(CARDS, "*.shock")))
LENGTH = 30               # target cells (in.piston's length)
TOLERANCE = 0.03          # us against c0 + s up


def derived(c):
    """K, c_L, Poisson's ratio and the Hugoniot elastic limit of a card's numbers."""
    k = c["rho"] * c["c0"] ** 2
    cl = math.sqrt((k + 4.0 * c["G"] / 3.0) / c["rho"])
    nu = (3 * k - 2 * c["G"]) / (2 * (3 * k + c["G"]))
    return k, cl, nu, c["Y"] * (1 - nu) / (1 - 2 * nu)


def test_the_five_metals_have_cards():
    assert set(NAMES) >= {"al", "cu", "fe", "ni", "ti"}


@pytest.mark.parametrize("name", NAMES)
def test_card_is_sane_and_documented(name):
    c = card(name)
    for key in ("rho", "c0", "s", "gamma", "G", "Y", "spall", "spall_rate", "spall_m", "upmax"):
        assert c[key] > 0, key
    assert c["spall_m"] < 1.0
    k, cl, nu, hel = derived(c)
    assert cl > c["c0"]
    assert 0.2 < nu < 0.45
    assert 1.0 < c["s"] < 2.0 and 0.5 < c["gamma"] < 3.0
    row = next(line for line in open(os.path.join(CARDS, "README.md"))
               if line.startswith(f"| [{name}.shock]"))
    cells = [x.strip() for x in row.split("|")[1:-1]]
    assert float(cells[9]) == pytest.approx(cl, abs=1.0)             # c_L (m/s)
    assert float(cells[10]) == pytest.approx(nu, abs=0.001)
    assert float(cells[11]) == pytest.approx(hel / 1e9, abs=0.001)   # HEL (GPa)


@pytest.mark.parametrize("name,share", [(n, f) for n in NAMES for f in (0.45, 0.9)])
def test_piston_drives_the_cards_hugoniot(tmp_path, name, share):
    c = card(name)
    up = round(share * c["upmax"])
    _, cl, _, hel = derived(c)
    assert up / 2 > 2 * hel / (c["rho"] * cl)    # the level up/2 lies above the precursor
    out = example(tmp_path, "in.piston", metal=name, up=up, length=LENGTH, out="piston")
    assert "WARNING" not in out
    dt = float(re.search(r"dt (\S+) s", out).group(1))
    length = LENGTH * CELL
    us = front_speed(XT(str(tmp_path / "piston.xt"), dt), up / 2, 0.2 * length, 0.7 * length)
    print(f"{name} up {up} m/s: us {us:.0f} m/s, c0 + s up {c['c0'] + c['s'] * up:.0f} m/s "
          f"({us / (c['c0'] + c['s'] * up) - 1:+.2%})")
    assert us == pytest.approx(c["c0"] + c["s"] * up, rel=TOLERANCE)


def piston_command(tmp_path, script, *var):
    """lmp on script (in.piston with the plugin under test) run in examples/mca-shock without
    -var here: (exit status, stdout)."""
    args = [a for k, v in var for a in ("-var", k, str(v))]
    done = subprocess.run([LMP, "-in", str(script), "-log", "none", "-nocite", *args],
                          cwd=EXAMPLE, capture_output=True, text=True, timeout=120)
    return done.returncode, done.stdout


def test_cards_are_found_from_the_example_folder_and_an_unknown_one_is_named(tmp_path):
    script = tmp_path / "in.piston"
    script.write_text(open(os.path.join(EXAMPLE, "in.piston")).read()
                      .replace("clusterdynplugin.so", PLUGIN))
    rc, out = piston_command(tmp_path, script, ("metal", "ni"), ("up", 500), ("length", 8),
                             ("out", tmp_path / "here"))
    assert rc == 0 and "Result: piston ni (nickel)" in out
    rc, out = piston_command(tmp_path, script, ("metal", "unobtainium"))
    assert rc != 0
    assert "ERROR: no material card ../../potentials/unobtainium.shock" in out
    assert "potentials/README.md" in out


def test_up_beyond_the_cards_range_warns(tmp_path):
    out = example(tmp_path, "in.piston", metal="fe", up=400, length=8)
    assert re.search(r"WARNING: up 400 m/s is beyond the range of the card fe .*up to 320", out)
