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
from lammps import LMP_VAR_STRING

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
    "ta-bcc110-10um": ["--density", "16650", "--sound-speed", "4150", "--hugoniot", "3414",
                       "1.20", "--spall-strength", "17e9", "--size", "1e-5", "--lattice", "bcc",
                       "--orientation", "110", "--up", "200", "--name",
                       "ta-bcc110-10um: tantalum at the floor of bcc [110] (17 GPa; the metal "
                       "spalls at 5.1)"],
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


NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def parts(text):
    """A set file as (its comment lines with every number masked, those numbers, its
    variables {name: [tokens]} with the numeric tokens as floats)."""
    comments, numbers, variables = [], [], {}
    for line in text.splitlines():
        if line.startswith("#"):
            comments.append(NUMBER.sub("#", line))
            numbers += [float(x) for x in NUMBER.findall(line)]
        elif line.startswith("variable"):
            _, name, _, value = line.split(None, 3)
            variables[name] = [float(t) if NUMBER.fullmatch(t) else t
                               for t in value.strip('"').split()]
    return comments, numbers, variables


def test_the_committed_sets_are_the_tools_output():
    """The committed sets are what the tool writes today, compared as numbers: the variables
    to 1e-8 (the law's shape solves s(shape) = S on five-point differences of the stress,
    round-off about 1e-10 relative, and Rc the strength by regula falsi to 1e-13; a CPU
    whose numpy sums in another order, AVX-512 or not, moves them in the 10th-11th digit),
    the comments' printed numbers (4 to 6 digits) to 1e-3 (a rounding of the last digit
    printed), the comments' text with its numbers masked exactly."""
    for name, args in SETS.items():
        out = tool(*args)
        assert out.returncode == 0, out.stderr
        got = parts(out.stdout)
        want = parts(open(os.path.join(TOP, "potentials", f"{name}.cd")).read())
        assert got[0] == want[0]
        assert got[1] == pytest.approx(want[1], rel=1e-3)
        assert got[2].keys() == want[2].keys()
        for key, tokens in want[2].items():
            assert len(got[2][key]) == len(tokens), key
            for g, w in zip(got[2][key], tokens):
                assert g == (pytest.approx(w, rel=1e-8) if isinstance(w, float) else w), key
        if name.startswith("ta-"):    # bcc at its floor: a soft law, dusting below u_sp
            assert "dusts the lattice from u_cr" in out.stderr
            continue
        # the warning that the strength-matched cut dusts before it spalls
        assert "dusts the lattice from u_cr" in out.stderr and "far below the papers'" in out.stderr
        assert "far from the papers' sets" not in out.stderr
    steep = tool(*SETS["al-hugoniot-10um"][:5], "5350", "4.0", *SETS["al-hugoniot-10um"][7:])
    assert steep.returncode == 0 and "far from the papers' sets" in steep.stderr


def test_set_comparison_masks_numbers_not_words():
    """The committed-set comparison above: a change in the 11th digit passes, one in the 8th
    or in a word of a comment does not."""
    text = open(os.path.join(TOP, "potentials", "cu-hugoniot-10um.cd")).read()
    base = parts(text)
    rc = f"{base[2]['pot_rc'][0]!r}"
    nudged = parts(text.replace(rc, f"{float(rc) * (1 + 1e-11)!r}"))
    assert nudged[2]["pot_rc"][0] == pytest.approx(base[2]["pot_rc"][0], rel=1e-8)
    moved = parts(text.replace(rc, f"{float(rc) * (1 + 1e-7)!r}"))
    assert moved[2]["pot_rc"][0] != pytest.approx(base[2]["pot_rc"][0], rel=1e-8)
    assert parts(text.replace("predicted", "expected"))[0] != base[0]


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
        c0, strength = lmp.extract_variable("pot_c0"), lmp.extract_variable("pot_strength")
        # the strength in pressure units against LAMMPS's D / a^3 in them (nktv2p)
        d_over_a3 = (float(lmp.extract_variable("pot_coeff", vartype=LMP_VAR_STRING).split()[0])
                     / lmp.extract_variable("pot_a") ** 3 * lmp.extract_global("nktv2p"))
        lattice = (lmp.extract_variable("pot_lattice", vartype=LMP_VAR_STRING),
                   lmp.extract_variable("pot_orient", vartype=LMP_VAR_STRING))
    velocity = {"si": 1.0, "metal": 100.0, "lj": p["vd"] / math.sqrt(2)}[units]  # m/s per unit
    # metal: LAMMPS's own constants (ftm2v) differ from CODATA's in the 8th digit
    assert v0 * velocity == pytest.approx(3940.0, rel=1e-7)
    assert vd * velocity == pytest.approx(p["vd"], rel=1e-7)
    assert rc == pytest.approx(p["rc"], rel=1e-12)
    # the set's own longitudinal speed along the impact (in.plate's c0): v0 on fcc [100]
    assert c0 == pytest.approx(v0, rel=1e-7) and lattice == ("fcc", "100")
    assert strength / d_over_a3 == pytest.approx(p["strength"] / (p["D"] / p["a"] ** 3),
                                                 rel=1e-7)


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


KRIVTSOV = {"--density": "2700", "--sound-speed": "6420", "--spall-speed": "1500",
            "--size": "1e-5", "--lattice": "fcc"}
METAL = {"--density": "2700", "--hugoniot": ["5350", "1.34"], "--spall-strength": "1.2e9",
         "--size": "1e-5", "--lattice": "fcc"}
TANTALUM = dict(METAL, **{"--density": "16650", "--hugoniot": ["3414", "1.20"],
                          "--spall-strength": "2.5e10", "--lattice": "bcc"})
MAGNESIUM = dict(METAL, **{"--density": "1740", "--hugoniot": ["4520", "1.24"],
                           "--spall-strength": "1e9", "--lattice": "hcp"})


@pytest.mark.parametrize("base,change,code,message", [
    (KRIVTSOV, {"--size": "nan"}, 1, "--size must be a finite number > 0 (got nan)"),
    (KRIVTSOV, {"--size": "1e-300"}, 1, "--density, --size and the speeds together overflow"),
    (KRIVTSOV, {"--size": "1e300"}, 1, "--density, --size and the speeds together overflow"),
    (KRIVTSOV, {"--density": "inf"}, 1, "--density must be a finite number > 0 (got inf)"),
    (KRIVTSOV, {"--sound-speed": "0"}, 1, "--sound-speed must be a finite number > 0"),
    (KRIVTSOV, {"--lattice": "bcc"}, 1, "--lattice bcc: Krivtsov's calibration"),
    (KRIVTSOV, {"--orientation": "110"}, 1, "--orientation belongs to the metal calibration"),
    (KRIVTSOV, {"--units": "parsec"}, 1, "unknown --units 'parsec'"),
    (KRIVTSOV, {"--density": "abc"}, 2, "argument --density: invalid float value: 'abc'"),
    (METAL, {"--size=": "-1e-5"}, 1, "--size must be a finite number > 0 (got -1e-05)"),
    (METAL, {"--size": "-1e-5"}, 1, "--size must be a finite number > 0 (got -1e-05)"),
    (METAL, {"--size": "-3.2e-10"}, 1, "--size must be a finite number > 0 (got -3.2e-10)"),
    (METAL, {"--spall-strength": "-1e10"}, 1, "--spall-strength must be a finite number"),
    (METAL, {"--size": "0"}, 1, "--size must be a finite number > 0 (got 0.0)"),
    (METAL, {"--size": "1e-300"}, 1, "--density, --size and the speeds together overflow"),
    (METAL, {"--size": "1e300"}, 1, "--density, --size and the speeds together overflow"),
    (METAL, {"--hugoniot": ["nan", "1.34"]}, 1, "--hugoniot C0 must be a finite number"),
    (METAL, {"--hugoniot": ["5350", "inf"]}, 1, "--hugoniot S must be a finite number"),
    (METAL, {"--hugoniot": ["5350"]}, 2, "argument --hugoniot: expected 2 arguments"),
    (METAL, {"--spall-strength=": "-1.2e9"}, 1, "--spall-strength must be a finite number"),
    (METAL, {"--sound-speed": "-1"}, 1, "--sound-speed must be a finite number > 0"),
    (METAL, {"--lattice": "hex"}, 1, "unknown --lattice 'hex' (expected chain, tri, fcc, bcc, "
     "hcp)"),
    (METAL, {"--orientation": "0001"}, 1, "--orientation: orientation '0001' is not one of "
     "fcc's: 100, 110, 111"),
    (METAL, {"--lattice": "tri", "--orientation": "100"}, 1, "orientation '100' is not one of "
     "tri's: row, across"),
    (METAL, {"--law": "mie", "--n": "nan", "--m": "6"}, 1, "Mie exponents need finite --n > --m"),
    (METAL, {"--hugoniot": None, "--grueneisen": "1.68", "--bulk-speed": "nan"}, 1,
     "--bulk-speed must be a finite number > 0"),
    (TANTALUM, {"--orientation": "0001"}, 1, "orientation '0001' is not one of bcc's: 100, 110, "
     "111"),
    (TANTALUM, {"--spall-strength": "5.5e9"}, 1, "--spall-strength 5.5e+09 is outside what a "
     "cut between 6 % beyond the second neighbours (a free face relaxes them"),
    (TANTALUM, {"--hugoniot": ["3414", "3.0"]}, 1, ("--hugoniot S = 3.0 is outside what morse on "
     "bcc [100] gives", "the lattice is not Born-stable")),
    (MAGNESIUM, {"--orientation": "111"}, 1, "orientation '111' is not one of hcp's: 0001, "
     "2-1-10, 01-10"),
    (MAGNESIUM, {"--orientation": "11-20"}, 1, "orientation '11-20' is not one of hcp's"),
    (MAGNESIUM, {"--spall-strength": "1e12"}, 1, "--spall-strength 1e+12 is outside what a cut "
     "between the nearest and the second neighbours gives on hcp [0001]"),
    (MAGNESIUM, {"--up": "1e6"}, 1, "--up 1e+06 m/s compresses the lattice beyond half"),
])
def test_hostile_arguments_end_in_a_message_naming_them(base, change, code, message):
    """Hostile values (NaN, inf, negative, zero, sizes that overflow), unknown or foreign
    lattices and orientations, options of the other calibration, bcc and hcp limits: exit 1
    (the tool's message) or 2 (argparse's), the argument named, no traceback.  A key ending
    in '=' passes its value joined to it (argparse takes '-1e-5' for an option otherwise)."""
    args = []
    given = dict(base, **change)
    for key, value in given.items():
        if key.endswith("="):
            args.append(key + value)
        elif value is not None and key + "=" not in given:
            args += [key] + (value if isinstance(value, list) else [value])
    out = tool(*args)
    messages = message if isinstance(message, tuple) else (message,)
    assert out.returncode == code and all(m in out.stderr for m in messages), out.stderr
    assert "Traceback" not in out.stderr and "Warning" not in out.stderr and out.stdout == ""


def test_grueneisen_gives_s_and_other_orientations():
    """--grueneisen G: s = (G + 1)/2 with c0 from --bulk-speed; [111] and the triangular
    lattice match the same Hugoniot and strength with their own alpha a and cut."""
    out = tool("--density", "2700", "--sound-speed", "6420", "--grueneisen", "1.68",
               "--bulk-speed", "5350", "--spall-strength", "1.2e9", "--size", "1e-5",
               "--lattice", "fcc")
    assert out.returncode == 0
    matched = re.search(r"the Hugoniot's c0 = (\S+) m/s and s = (\S+) \(weak", out.stdout)
    assert float(matched.group(1)) == pytest.approx(5350, rel=1e-4)         # 5 digits printed
    assert float(matched.group(2)) == pytest.approx((1.68 + 1) / 2, rel=1e-3)
    assert float(re.search(r"not matched: the longitudinal speed (\S+) m/s",
                           out.stdout).group(1)) == 6420
    for lattice, orient in (("fcc", "111"), ("tri", "row"), ("tri", "across")):
        density = 2700.0 if lattice == "fcc" else 2700.0 * 1e-5
        strength = 1.2e9 if lattice == "fcc" else 1.2e9 * 1e-5      # Pa, or N/m on tri
        p = cd_calibrate.calibrate_metal(density, 5350.0, 1.34, strength, 1e-5, lattice, orient)
        model = cd_uniaxial.Uniaxial(lattice, orient, cd_uniaxial.Law("morse", p["kv"],
                                                                      rc=p["rc"]))
        dim = 3 if lattice == "fcc" else 2
        assert model.speed() * math.sqrt(p["D"] / p["m"]) == pytest.approx(5350.0, rel=1e-9)
        assert model.slope() == pytest.approx(1.34, rel=1e-6)
        assert model.strength() * p["D"] / 1e-5 ** dim == pytest.approx(strength, rel=1e-9)
        assert p["m"] == pytest.approx(density * model.volume * 1e-5 ** dim, rel=1e-14)
        assert 1 < p["rc"] < 1.1


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
