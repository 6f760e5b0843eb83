"""pair mca prints each material's derived numbers at the start of a run (doc/pair_mca.rst
"Units"): K, G, E, nu, c_L, c_S, the bulk speed c0 = sqrt(K/rho), the Hugoniot elastic limit of
a yield stress, and the density also in g/cm^3 (metal, real, cgs) or kg/m^3 (si), so a density
typed in the wrong unit shows itself.  Oracles: aluminium's handbook numbers (test_mca_shock.py)
converted with CODATA's constants, not with the plugin's."""
import math
import re

import pytest

from conftest import PLUGIN, run_lmp
from test_mca_shock import CL, C0, G, K, RHO0, UNITS, Y, plate_setup

NU = (3 * K - 2 * G) / (2 * (3 * K + G))
HEL = Y * (1 - NU) / (1 - 2 * NU)
# the density unit a person reads, per unit style, and kg/m^3 in it
PERSON = {"si": ("kg/m^3", 1.0), "metal": ("g/cm^3", 1.0e-3)}


def report(tmp_path, setup):
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + "\n".join(setup)
                  + "\nfix 1 all nve/sphere\nrun 0 post no\n")
    at = out.index("Pair mca materials")
    return out[at:at + 600]


def number(text, pattern):
    m = re.search(pattern + r"\s*(-?[\d.]+(?:e[-+]?\d+)?)", text)
    assert m, (pattern, text)
    return float(m.group(1))


@pytest.mark.parametrize("units", ["si", "metal"])
def test_the_log_gives_the_materials_numbers_in_the_unit_style(tmp_path, units):
    L, V, R, P, _ = UNITS[units]
    text = report(tmp_path, plate_setup(units, 2, 3))
    unit, scale = PERSON[units]
    assert f"units {units}" in text and "type 1: shock law" in text
    assert number(text, r"density") == pytest.approx(RHO0 * R, rel=1e-5)
    assert number(text, r"\(rho0\) =") == pytest.approx(RHO0 * scale, rel=1e-5)
    assert f"{RHO0 * scale:.6g} {unit}" in text
    assert number(text, r" K") == pytest.approx(K * P, rel=1e-5)
    assert number(text, r" G") == pytest.approx(G * P, rel=1e-5)
    assert number(text, r"nu") == pytest.approx(NU, abs=1e-4)
    assert number(text, r"c_L") == pytest.approx(CL * V, rel=1e-5)
    assert number(text, r"c_S") == pytest.approx(math.sqrt(G / RHO0) * V, rel=1e-5)
    assert number(text, r"sqrt\(K/rho\)") == pytest.approx(C0 * V, rel=1e-5)
    assert number(text, r"Y \(1 - nu\)/\(1 - 2 nu\) =") == pytest.approx(HEL * P, rel=1e-5)


def test_a_density_typed_in_g_per_cm3_in_metal_units_shows_itself(tmp_path):
    """2.703 typed as rho0 in metal units (g/mol/A^3 expected) reads 4.49 g/cm^3 in the log."""
    _, V, R, P, _ = UNITS["metal"]
    setup = [c.replace(f"shock {RHO0 * R} ", "shock 2.703 ") for c in plate_setup("metal", 2, 3)]
    setup = [f"set group all density {2.703 / (math.pi / math.sqrt(18.0))}"
             if c.startswith("set group all density") else c for c in setup]
    text = report(tmp_path, setup)
    assert number(text, r"\(rho0\) =") == pytest.approx(2.703 / 0.602214076, rel=1e-5)
    assert "g/cm^3" in text


def test_a_linear_material_reads_its_density_from_the_elements(tmp_path):
    """The linear law has no rho0: the elements' mass over their volume, in lj reduced units."""
    setup = ["units lj", "atom_style sphere", "comm_modify vel yes", "lattice fcc 1.4142135623731",
             "region box block 0 3 0 3 0 3", "create_box 2 box", "create_atoms 1 box",
             "set group all diameter 1.0", "set group all density 2.0",
             "pair_style mca fraction 0.74048", "pair_coeff 1 1 young 1.0 poisson 0.25",
             "pair_coeff 2 2 bulk 1.0 shear 0.5 yield 0.01", "neighbor 0.25 bin"]
    text = report(tmp_path, setup)
    rho = 2.0 * 0.74048
    e, nu = 1.0, 0.25
    k, g = e / (3 * (1 - 2 * nu)), e / (2 * (1 + nu))
    first, second = text.split("type 2")
    assert number(first, r"density") == pytest.approx(rho, rel=1e-4)
    assert number(first, r"c_L") == pytest.approx(math.sqrt((k + 4 * g / 3) / rho), rel=1e-4)
    assert "g/cm^3" not in text and "kg/m^3" not in text
    assert "no elements of this type here yet" in second
    nu2 = (3 - 1) / (2 * (3 + 0.5))
    assert number(second, r"Y \(1 - nu\)/\(1 - 2 nu\) =") == pytest.approx(0.01 * (1 - nu2) / (1 - 2 * nu2), rel=1e-5)
