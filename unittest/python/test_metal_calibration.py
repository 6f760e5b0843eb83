"""tools/cd_calibrate.py's metal calibration (--hugoniot, --spall-strength) and the lattice
mechanics under it (tools/cd_uniaxial.py), against closed forms and stock LAMMPS (pair_style
morse on a periodic block strained along the impact), and its predictions checked by
simulation for aluminium and copper (examples/spall/run_metals.py reduced): the shock speed of
a piston run against the predicted and the handbook Hugoniot, the spall strength of a plate
impact against the strength the set was matched to, reported as it is (doc/plate_impact.rst)."""
import math
import os
import re
import subprocess
import sys

import numpy as np
import pytest
from conftest import PLUGIN, session

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CALIBRATE = os.path.join(TOP, "tools", "cd_calibrate.py")
sys.path.insert(0, os.path.join(TOP, "tools"))
sys.path.insert(0, os.path.join(TOP, "examples"))
sys.path.insert(0, os.path.join(TOP, "examples", "spall"))
os.environ["LAMMPS_PLUGIN_PATH"] = os.path.dirname(PLUGIN)
import cd_calibrate  # noqa: E402
import cd_uniaxial  # noqa: E402
import run_metals  # noqa: E402

# the committed sets and the command lines that make them (potentials/README.md)
SETS = {
    "al-hugoniot-10um": ["--density", "2700", "--sound-speed", "6420", "--hugoniot", "5350",
                         "1.34", "--spall-strength", "1.2e9", "--size", "1e-5", "--lattice",
                         "fcc", "--up", "200", "--name", "al-hugoniot-10um: aluminium"],
    "cu-hugoniot-10um": ["--density", "8930", "--sound-speed", "4760", "--hugoniot", "3940",
                         "1.49", "--spall-strength", "1.5e9", "--size", "1e-5", "--lattice",
                         "fcc", "--up", "200", "--name", "cu-hugoniot-10um: copper"],
}


def tool(*args):
    return subprocess.run([sys.executable, CALIBRATE, *args], capture_output=True, text=True)


@pytest.mark.parametrize("law", [cd_uniaxial.Law("morse", 3.76), cd_uniaxial.Law("morse", 6.0),
                                 cd_uniaxial.Law("mie", 0.7), cd_uniaxial.Law("mie", 1.3, 9, 6)])
def test_uniaxial_closed_forms(law):
    """fcc [100]: c = a sqrt(Pi''(a) / m) (the chain's), s = (Gamma - 3/2)/4; the chain:
    s = Gamma / 2 (the Rayleigh line's expansion, Gamma = -a Pi''' / (2 Pi''))."""
    pi2 = {"morse": 2 * law.shape ** 2}.get(law.name, law.shape ** 2 * law.n * law.m)
    fcc = cd_uniaxial.Uniaxial("fcc", "100", law)
    chain = cd_uniaxial.Uniaxial("chain", "row", law)
    assert fcc.speed() == pytest.approx(math.sqrt(pi2), rel=1e-7)
    assert chain.speed() == pytest.approx(math.sqrt(pi2), rel=1e-7)
    assert fcc.slope() == pytest.approx((law.gamma() - 1.5) / 4, rel=1e-6)
    assert chain.slope() == pytest.approx(law.gamma() / 2, rel=1e-6)
    assert cd_uniaxial.Uniaxial("fcc", "100", cd_uniaxial.Law(law.name, law.shape, law.n, law.m,
                                                              rc=1.3)).strength() > 0


def block_stress(lmp, strains, units_pressure):
    """pxx (tension positive, SI) of the periodic block at each uniaxial strain along x."""
    out = []
    lx0 = lmp.get_thermo("lx")
    for e in strains:
        lmp.command(f"change_box all x final 0 {lx0 * (1 + e)!r} remap units box")
        lmp.command("run 0 post no")
        out.append(-lmp.get_thermo("pxx") * units_pressure)
        lmp.command(f"change_box all x final 0 {lx0!r} remap units box")
    return np.array(out)


@pytest.mark.parametrize("units", ["si", "metal"])
@pytest.mark.parametrize("orient", ["100", "111"])
def test_uniaxial_against_stock_morse(units, orient):
    """The aluminium set's lattice strained along [100] and [111] with stock pair_style morse
    cut at Rc a: the modulus, the Hugoniot slope's second derivative and the ideal strength of
    cd_uniaxial.py equal LAMMPS's virial stress (SI and metal units)."""
    p = cd_calibrate.in_units(run_metals.calibrated("aluminium"), units)
    to_pa = {"si": 1.0, "metal": 1e5}[units]
    a = p["a"]
    rows = {"100": "orient x 1 0 0 orient y 0 1 0 orient z 0 0 1 ",
            "111": "orient x 1 1 1 orient y -1 1 0 orient z -1 -1 2 "}[orient]
    with session(plugin=False) as lmp:
        lmp.commands_list([
            f"units {units}", "atom_modify map array", "boundary p p p",
            f"lattice fcc {a * math.sqrt(2)!r} {rows}", "region box block 0 3 0 3 0 3",
            "create_box 1 box", "create_atoms 1 box", f"mass 1 {p['m']!r}",
            f"pair_style morse {p['rc'] * a!r}",
            f"pair_coeff 1 1 {p['D']!r} {p['kv'] / a!r} {a!r}",
            f"neighbor {0.2 * a!r} bin", "thermo_style custom step pxx lx", "run 0 post no"])
        h = 1e-4
        s = block_stress(lmp, [-h, 0.0, h], to_pa)
        model = cd_uniaxial.Uniaxial("fcc", orient, cd_uniaxial.Law("morse", p["kv"],
                                                                    rc=p["rc"]))
        eps, strength = model.peak()
        eps *= 1 - 1e-6          # just below the break (exactly at it round-off decides)
        curve = block_stress(lmp, list(np.linspace(0.0, 0.03, 301)) + [eps], to_pa)
    unit = run_metals.calibrated("aluminium")["D"] / 1e-15          # D / a^3 in Pa
    m, m2 = model.moduli()
    assert (s[2] - s[0]) / (2 * h) == pytest.approx(m * unit, rel=1e-6)
    assert -(s[2] - 2 * s[1] + s[0]) / h ** 2 == pytest.approx(m2 * unit, rel=1e-3)
    assert curve[-1] == pytest.approx(model.stress(eps) * unit, rel=1e-6)   # at the peak
    assert curve[-1] == pytest.approx(strength * unit, rel=1e-4)
    assert curve.max() <= strength * unit * (1 + 1e-6)              # and nothing above it
    if orient == "100":
        assert curve[-1] == pytest.approx(1.2e9, rel=1e-4)          # the strength matched


def test_the_committed_sets_are_the_tools_output():
    for name, args in SETS.items():
        out = tool(*args)
        assert out.returncode == 0, out.stderr
        assert out.stdout == open(os.path.join(TOP, "potentials", f"{name}.cd")).read()
        # the warning that the strength-matched cut dusts before it spalls
        assert "dusts the lattice from u_cr" in out.stderr and "far below the papers'" in out.stderr
        assert "far from the papers' sets" not in out.stderr
    steep = tool(*SETS["al-hugoniot-10um"][:5], "5350", "4.0", *SETS["al-hugoniot-10um"][7:])
    assert steep.returncode == 0 and "far from the papers' sets" in steep.stderr


@pytest.mark.parametrize("units", ["si", "metal", "lj"])
def test_metal_set_loads_and_gives_its_speeds(tmp_path, units):
    """The set written in each unit style gives, by compute pair/params, the Hugoniot's c0
    as the long-wave speed along fcc [100] (v0, index 14) and the set's vd."""
    args = SETS["cu-hugoniot-10um"][:-2] + ["--units", units]
    out = tool(*args)
    assert out.returncode == 0, out.stderr
    path = tmp_path / "cu.cd"
    path.write_text(out.stdout)
    p = run_metals.calibrated("copper")
    with session() as lmp:
        lmp.command(f"include {path}")
        lmp.commands_list([
            f"units {units}", "region box block 0 $(10*v_pot_a) 0 $(10*v_pot_a) 0 $(10*v_pot_a) "
            "units box", "create_box 1 box", "mass 1 ${pot_m}", "neighbor $(0.2*v_pot_a) bin",
            "pair_style ${pot_style} cut ${pot_rc}", "pair_coeff 1 1 ${pot_coeff}",
            "compute p all pair/params 1 1", "thermo_style custom step c_p[1]", "run 0 post no"])
        v0, vd = lmp.extract_compute("p", 0, 1)[13], lmp.extract_compute("p", 0, 1)[14]
        rc = lmp.extract_variable("pot_rc")
    velocity = {"si": 1.0, "metal": 100.0, "lj": p["vd"] / math.sqrt(2)}[units]  # m/s per unit
    # metal: LAMMPS's own constants (ftm2v) differ from CODATA's in the 8th digit
    assert v0 * velocity == pytest.approx(3940.0, rel=1e-7)
    assert vd * velocity == pytest.approx(p["vd"], rel=1e-7)
    assert rc == pytest.approx(p["rc"], rel=1e-12)


@pytest.mark.parametrize("args,message", [
    (["--hugoniot", "5350", "1.34"], "--spall-strength"),
    (["--hugoniot", "5350", "40", "--spall-strength", "1.2e9"], "--hugoniot S = 40.0"),
    (["--hugoniot", "5350", "1.34", "--spall-strength", "1e12"], "--spall-strength 1e+12 is "
     "outside"),
    (["--hugoniot", "5350", "1.34", "--spall-strength", "1"], "--spall-strength 1 is outside"),
    (["--hugoniot", "5350", "1.34", "--spall-strength", "1.2e9", "--orientation", "112"],
     "orientation '112'"),
    (["--hugoniot", "5350", "1.34", "--grueneisen", "2", "--spall-strength", "1.2e9"],
     "not both"),
    (["--hugoniot", "-5350", "1.34", "--spall-strength", "1.2e9"], "--hugoniot C0 must be a finite"),
    (["--hugoniot", "5350", "1.34", "--spall-strength", "inf"], "--spall-strength must be a finite"),
    (["--grueneisen", "2.0", "--spall-strength", "1.2e9"], "--bulk-speed"),
    (["--hugoniot", "5350", "1.34", "--spall-strength", "1.2e9", "--up", "nan"], "--up must be"),
    (["--hugoniot", "5350", "1.34", "--spall-strength", "1.2e9", "--up", "1e5"],
     "--up 100000 m/s compresses"),
    (["--hugoniot", "5350", "1.34", "--spall-strength", "1.2e9", "--spall-speed", "1500"],
     "not both"),
    (["--hugoniot", "5350", "1.34", "--spall-strength", "1.2e9", "--law", "mie", "--n",
      "6.000001", "--m", "6"], "reaches only"),
    (["--hugoniot", "5350", "1.34", "--spall-strength", "1.2e9", "--law", "lj", "--n", "9"],
     "--n and --m belong to --law mie"),
    (["--hugoniot", "1e300", "1.34", "--spall-strength", "1.2e9"], "overflow"),
    (["--hugoniot", "5350", "1.34", "--spall-strength", "1.2e9", "--name", "a\nprint x"],
     "--name must be one line"),
    (["--sound-speed", "6420", "--spall-speed", "1500", "--up", "200"],
     "--up belongs to the metal calibration"),
])
def test_metal_calibration_errors_name_the_argument(args, message):
    out = tool("--density", "2700", "--size", "1e-5", "--lattice", "fcc", *args)
    assert out.returncode != 0 and message in out.stderr and "Traceback" not in out.stderr


def test_grueneisen_gives_s_and_other_orientations():
    """--grueneisen G: s = (G + 1)/2 with c0 from --bulk-speed; [111] and the triangular
    lattice match the same Hugoniot and strength with their own alpha a and cut."""
    out = tool("--density", "2700", "--sound-speed", "6420", "--grueneisen", "1.68",
               "--bulk-speed", "5350", "--spall-strength", "1.2e9", "--size", "1e-5",
               "--lattice", "fcc")
    assert out.returncode == 0 and "s = 1.34" in out.stdout and "c0 = 5350" in out.stdout
    assert "not matched: the longitudinal speed 6420" in out.stdout
    for lattice, orient in (("fcc", "111"), ("tri", "row"), ("tri", "across")):
        density = 2700.0 if lattice == "fcc" else 2700.0 * 1e-5
        p = cd_calibrate.calibrate_metal(density, 5350.0, 1.34, 1.2e9 if lattice == "fcc" else
                                         1.2e9 * 1e-5, 1e-5, lattice, orient)
        model = cd_uniaxial.Uniaxial(lattice, orient, cd_uniaxial.Law("morse", p["kv"],
                                                                      rc=p["rc"]))
        assert model.speed() * math.sqrt(p["D"] / p["m"]) == pytest.approx(5350.0, rel=1e-9)
        assert model.slope() == pytest.approx(1.34, rel=1e-6)
        assert p["strength"] == pytest.approx(p["strength"], rel=1e-9) and 1 < p["rc"] < 1.1


@pytest.mark.parametrize("metal", ["aluminium", "copper"])
def test_a_piston_run_gives_the_predicted_and_the_handbook_shock_speed(metal):
    """The issue's check: at the guide's up = 200 m/s (400 m/s impacts) and at 1000 m/s the
    piston run's shock speed is within 3 % of the tool's cold-lattice prediction at 200 m/s
    (within 4 %, shock heat, at 1000) and within 10 % of the metal's Hugoniot."""
    for up, predicted_within in ((200.0, 0.03), (1000.0, 0.04)):
        r = run_metals.hugoniot_point((metal, up, 1))
        assert r["us"] == pytest.approx(r["predicted"], rel=predicted_within)
        assert r["us"] == pytest.approx(r["handbook"], rel=0.10)


@pytest.mark.parametrize("metal", ["aluminium", "copper"])
def test_a_plate_impact_reads_a_fraction_of_the_matched_strength(metal):
    """The issue's check, as it is: at 400 m/s the matched set spalls; its pull-back reads
    0.1-0.2 of the strength undamped and 0.55-0.6 with fix viscous/relative J = 10
    (examples/spall/metals.md): the lattice's ringing breaks the strength-matched bonds
    (u_cr = 59 and 30 m/s, below the 83 and 43 m/s that load the strength) before the mean
    tension reaches the strength; doc/plate_impact.rst explains."""
    strength = run_metals.METALS[metal]["strength"]
    plain = run_metals.impact((metal, 400.0, 0, 1, None))
    damped = run_metals.impact((metal, 400.0, 10, 1, None))
    assert plain["spall"] and damped["spall"]
    assert 0.05 < plain["sigma"] / strength < 0.3
    assert 0.45 < damped["sigma"] / strength < 0.7
    assert damped["tension"] < 0.8 * strength
