"""pair_style morse/spline, lj/spline, mie/spline, harmonic/spline: bad input gives a clear
LAMMPS error naming the argument; hard cases (deep compression past the kappa singularity,
coincident atoms, kappa or a skin beyond what the law and LAMMPS can bear) stop with an error,
never NaN forces; an error inside the /omp region is the serial style's, catchable, and the host
survives.  The table of hostile input (conftest.InputTable) of the styles' settings,
coefficients, runs and fix adapt.  Links (link L) have theirs in test_pair_spline_link.py."""
import numpy as np
import pytest
from conftest import (OK, SCENE_BOX, SCENE_EMPTY, SCENE_LAW, SCENE_MORSE, SCENE_NOBOX, SCENE_UNITS,
                      SI_CLUSTERS, InputTable, check_input, scene_box, scene_dimer, scene_pair,
                      scene_unit_dimer, session)

BAD_SETTINGS = [
    ("morse/spline", "", "missing tail"),
    ("morse/spline", "spline 1.2", "unknown tail 'spline'"),
    ("morse/spline", "cut", "cut: expected a number Rc \\(got nothing\\)"),
    ("morse/spline", "cut chain 2", "cut: expected a number Rc \\(got 'chain'\\)"),
    ("morse/spline", "cut 1.0", "Rc must be > 1"),
    ("morse/spline", "cut 0.8", "Rc must be > 1"),
    ("lj/spline", "wagner 1.5", "takes no arguments"),
    ("morse/spline", "lagunov 1.2 start 1.3", "Rc = 1.2 must be > start Rs = 1.3"),
    ("morse/spline", "lagunov 1.2 begin 1.1", "unknown keyword 'begin'"),
    ("morse/spline", "lagunov -1", "lagunov Rc must be > 0"),
    ("harmonic/spline", "wagner", "tail wagner needs an inflection point"),
    ("harmonic/spline", "lagunov 1.3", "needs 'start Rs'"),
    ("morse/spline", "cut 1.2 chain 0", "chain N must be between 1 and 1000 \\(got 0\\)"),
    ("morse/spline", "cut 1.2 chain 2147483647", "chain N must be between 1 and 1000"),
    ("morse/spline", "cut 1.2 chain", "keyword chain needs a value"),
    ("morse/spline", "cut 1.2 junk 3", "after tail cut\\): unknown keyword 'junk' \\(expected start, chain, lin"),
    ("morse/spline", "wagner chain", "keyword chain needs a value"),
    ("morse/spline", "lagunov 1.0", "lagunov: Rc must be > 1"),
    ("morse/spline", "lagunov 0.9 start 0.5", "lagunov: Rc must be > 1"),
]

BAD_COEFFS = [  # pair_style, pair_coeff args, message
    ("morse/spline cut 1.2", "1.0 6.0", "expected pair_coeff I J D alpha a"),
    ("morse/spline cut 1.2", "0 6.0 1.0", "D must be > 0"),
    ("morse/spline cut 1.2", "1.0 -6.0 1.0", "alpha must be > 0"),
    ("morse/spline cut 1.2", "1.0 6.0 0", "a must be > 0"),
    ("harmonic/spline cut 1.2", "1.0 0 1.0", "alpha must be > 0"),
    ("lj/spline cut 1.2", "-1.0 1.0", "D must be > 0"),
    ("mie/spline cut 1.2", "1.0 1.0 6 6", "n must be > m"),
    ("mie/spline cut 1.2", "1.0 1.0 4 6", "n must be > m"),
    ("mie/spline cut 1.2", "1.0 1.0 6 0", "m must be > 0"),
    ("morse/spline cut 1.2", "1.0 6.0 1.0 kappa 0", "kappa must be > 0"),
    ("morse/spline cut 1.2", "1.0 6.0 1.0 kappa", "keyword kappa needs a value"),
    ("morse/spline cut 1.2", "1.0 6.0 1.0 gamma 2", "pair_coeff: unknown keyword 'gamma'"),
    ("morse/spline cut 1.2", "1.0 6.0 1.0 rc 0.9", "rc must be > 1"),
    ("morse/spline lagunov 1.3", "1.0 6.0 1.0 rc 0.9", "rc must be > 1"),
    ("mie/spline cut 1.2", "1.0 1.0 1e6 6", "law of types 1 1 overflows at r = a/2 \\(the exponents n and m must be below"),
    ("mie/spline cut 1.2", "1.0 1.0 1e6 999999", "overflows at r = a/2"),
    ("morse/spline cut 1.2", "1.0 2000 1.0", "overflows at r = a/2 \\(alpha a must be below about 700"),
    ("lj/spline wagner", "1.0 1.0 kappa 0.1", "wagner has no cutoff for types 1 1 \\(raise kappa\\)"),
    ("morse/spline wagner", "1.0 6.0 1.0 rc 1.3", "rc does not apply to tail wagner"),
    ("morse/spline cut 1.2", "1.0 6.0 1.0 rs 1.1", "rs applies only to tail lagunov"),
    ("morse/spline wagner", "1.0 1.2 1.0", "tail wagner has no cutoff for types 1 1 \\(Morse needs kappa alpha a"),
    ("morse/spline lagunov 1.05", "1.0 6.0 1.0", "lagunov Rc = 1.05 a must be > its start"),
    ("mie/spline lagunov 1.3", "1.0 1.0 12 6 rs 1.4", "must be > its start Rs = 1.4"),
]


def box(lmp, commands=(), threads=0):
    lmp.commands_list(["units lj", *([f"package omp {threads}", "suffix omp"] if threads else []),
                       "region box block 0 4 0 4 0 4", "create_box 1 box", "mass 1 1.0",
                       "neighbor 0.3 bin", *commands])


@pytest.mark.parametrize("style,args,message", BAD_SETTINGS)
def test_bad_pair_style_settings(style, args, message):
    with session() as lmp:
        box(lmp)
        with pytest.raises(Exception, match=message):
            lmp.command(f"pair_style {style} {args}")


@pytest.mark.parametrize("pair_style,args,message", BAD_COEFFS)
def test_bad_pair_coeff(pair_style, args, message):
    with session() as lmp:
        box(lmp)
        lmp.command(f"pair_style {pair_style}")
        with pytest.raises(Exception, match=message):
            lmp.command(f"pair_coeff 1 1 {args}")


def test_morse_wagner_cutoff_exists_from_alpha_a_1_56():
    with session() as lmp:
        box(lmp)
        lmp.commands_list(["pair_style morse/spline wagner", "pair_coeff 1 1 1.0 1.56 1.0"])
        with pytest.raises(Exception, match="wagner has no cutoff"):
            lmp.command("pair_coeff 1 1 1.0 1.55 1.0")


@pytest.mark.parametrize("law,coeff", [("lj", "1.0 1.0 kappa 2.0"), ("mie", "1.0 1.0 9 6 kappa 1.5")])
def test_compression_past_kappa_singularity_is_an_error_naming_the_atoms(law, coeff):
    # kappa > 1: the law is singular at r = a (1 - 1/kappa); a pair closer than that stops
    with session() as lmp:
        box(lmp)
        lmp.commands_list(["create_atoms 1 single 1.0 1.0 1.0", "create_atoms 1 single 1.2 1.0 1.0",
                           f"pair_style {law}/spline cut 1.3", f"pair_coeff 1 1 {coeff}"])
        with pytest.raises(Exception, match="atoms 1 and 2 are 0.2 apart"):
            lmp.command("run 0")


def test_coincident_atoms_are_an_error_not_nan():
    with session() as lmp:
        box(lmp)
        lmp.commands_list(["create_atoms 1 single 1.0 1.0 1.0", "create_atoms 1 single 1.0 1.0 1.0",
                           "pair_style morse/spline cut 1.3", "pair_coeff 1 1 1.0 6.0 1.0"])
        with pytest.raises(Exception, match="atoms 1 and 2 are 0 apart"):
            lmp.command("run 0")


def test_kappa_within_the_bound_keeps_finite_energies():
    with session() as lmp:
        lmp.commands_list(SCENE_EMPTY + ["create_atoms 1 single 0 0 0",
                                         "create_atoms 1 single 0.5 0 0",
                                         "pair_style morse/spline cut 1.3",
                                         "pair_coeff * * 1.0 6.75 1.0 kappa 100", "run 0"])
        assert np.isfinite(lmp.get_thermo("pe")) and lmp.get_thermo("pe") > 0


# /omp: an error inside the OpenMP region is the serial style's clean, catchable error

@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("law,coeff,where,message", [
    ("morse", "1.0 6.0 1.0", 1.0, "atoms 1 and 2 are 0 apart"),
    ("lj", "1.0 1.0 kappa 2.0", 1.2, "atoms 1 and 2 are 0.2 apart"),
])
def test_omp_error_is_catchable_and_the_host_survives(threads, law, coeff, where, message):
    with session() as lmp:
        box(lmp, ["create_atoms 1 single 1.0 1.0 1.0", f"create_atoms 1 single {where} 1.0 1.0",
                  f"pair_style {law}/spline cut 1.3", f"pair_coeff 1 1 {coeff}"], threads)
        assert lmp.has_style("pair", f"{law}/spline/omp")
        with pytest.raises(Exception, match=message):
            lmp.command("run 0")
        lmp.command("delete_atoms group all")    # the instance still takes commands
        lmp.command("run 0 post no")
        assert lmp.get_natoms() == 0


def test_default_si_skin_at_cluster_scale_is_a_clear_error(tmp_path):
    log = tmp_path / "log.lammps"
    with session("-log", str(log)) as lmp:
        lmp.commands_list(SI_CLUSTERS + ["pair_style morse/spline cut 1.2",
                                         "pair_coeff 1 1 2.46e-6 3.76e5 1e-5"])
        with pytest.raises(Exception, match=r"neighbor skin 0.001 is 83.3 x the interaction range"):
            lmp.command("run 0")
        lmp.commands_list(["neighbor 3e-6 bin", "run 0 post no"])
        assert lmp.get_thermo("pe") < 0
    # the whole message (the Python exception keeps its first 100 characters)
    assert ("range 1.2e-05: set it, e.g. neighbor 3e-06 bin (the default skin of units si suits "
            "atoms, not clusters)") in log.read_text()


# ---------------------------------------------------------------- hostile input

INPUTS = InputTable()
row = INPUTS.row
STYLES = list(SCENE_LAW)

# before a box exists
NORUN = r"Run command before simulation box is defined"
row("nobox-pair_style", SCENE_NOBOX, "pair_style morse/spline cut 1.3", NORUN)
row("nobox-pair_coeff", SCENE_NOBOX, ["pair_style morse/spline cut 1.3", "pair_coeff * * 1.0 6.0 1.0"],
    "Pair_coeff command before simulation box is defined")

# pair_style settings
for s in STYLES:
    for omp in (False, True):
        sfx = "/omp" if omp else ""
        row(f"style-{s}{sfx}-no-tail", scene_box(omp=omp), f"pair_style {s}{sfx}",
            f"Pair style {s}: missing tail")

P = "pair_style morse/spline "
for rid, args, expect, defect in [
    ("cut-nothing", "cut", r"cut: expected a number Rc \(got nothing\)", None),
    ("cut-abc", "cut abc", r"expected a number Rc \(got 'abc'\)", None),
    ("cut-1e", "cut 1e", r"expected a number Rc \(got '1e'\)", None),
    ("cut-nan", "cut nan", r"expected a number Rc \(got 'nan'\)", None),
    ("cut-inf", "cut inf", r"expected a number Rc \(got 'inf'\)", None),
    ("cut--inf", "cut -inf", r"expected a number Rc \(got '-inf'\)", None),
    ("cut-1e309", "cut 1e309", r"Rc.*1e309", None),
    ("cut-1e-400", "cut 1e-400", r"Rc.*1e-400", None),
    ("cut--0", "cut -0", r"Rc must be > 1 .*\(got -0\)", None),
    ("cut-0", "cut 0", r"Rc must be > 1 .*\(got 0\)", None),
    ("cut-1", "cut 1", r"Rc must be > 1 .*\(got 1\)", None),
    ("cut-2-numbers", "cut 1.3 1.5", r"after tail cut\): unknown keyword '1.5'", None),
    ("cut-uppercase", "CUT 1.3", r"unknown tail 'CUT'", None),
    ("order-link-before-tail", "link 1.05 cut 1.3", r"unknown tail 'link'", None),
    ("wagner-number", "wagner 1.5", r"wagner: takes no arguments \(got 1.5\)", None),
    ("wagner-word", "wagner abc", r"after tail wagner\): unknown keyword 'abc'", None),
    ("lagunov-nothing", "lagunov", r"lagunov: expected a number Rc \(got nothing\)", None),
    ("lagunov-nan", "lagunov nan", r"lagunov: expected a number Rc \(got 'nan'\)", None),
    ("lagunov-0.5", "lagunov 0.5", r"lagunov: Rc must be > 1", None),
    ("lagunov-start-nothing", "lagunov 1.3 start", r"expected a number Rs after start \(got "
     r"nothing\)", None),
    ("lagunov-start-abc", "lagunov 1.3 start abc", r"expected a number Rs after start \(got "
     r"'abc'\)", None),
    ("lagunov-start-0", "lagunov 1.3 start 0", r"lagunov start Rs must be > 0 \(got 0\)", None),
    ("lagunov-start--0", "lagunov 1.3 start -0", r"lagunov start Rs must be > 0 \(got -0\)",
     None),
    ("lagunov-start-equal", "lagunov 1.3 start 1.3", r"Rc = 1.3 must be > start Rs = 1.3", None),
    ("lagunov-start-twice", "lagunov 1.3 start 1.1 start 1.2", r"start.*(twice|once)",
     None),
    ("lagunov-start-after-link", "lagunov 1.3 link 1.05 start 1.1", r"start.*(follow|right "
     r"after|directly after|Rc)", None),
    ("chain-1.5", "cut 1.3 chain 1.5", r"chain.*1\.5", None),
    ("chain-2.0", "cut 1.3 chain 2.0", r"chain.*2\.0", None),
    ("chain-abc", "cut 1.3 chain abc", r"chain.*abc", None),
    ("chain--1", "cut 1.3 chain -1", r"chain N must be between 1 and 1000 \(got -1\)", None),
    ("chain-1001", "cut 1.3 chain 1001", r"chain N must be between 1 and 1000 \(got 1001\)",
     None),
    ("chain-huge", "cut 1.3 chain 99999999999", r"chain.*99999999999", None),
    ("chain-twice", "cut 1.3 chain 2 chain 3", r"keyword chain given twice", None),
]:
    row(f"style-{rid}", SCENE_BOX, P + args, expect, defect)

row("style-cut-1e300", SCENE_BOX, P + "cut 1e300", r"Rc must be <= .*\(got 1e300\)")
row("style-omp-cut-abc", scene_box(omp=True), "pair_style morse/spline/omp cut abc",
    r"expected a number Rc \(got 'abc'\)")
row("style-omp-lj-lagunov-0.5", scene_box(omp=True), "pair_style lj/spline/omp lagunov 0.5",
    r"lagunov: Rc must be > 1")
row("style-omp-mie-chain-0", scene_box(omp=True), "pair_style mie/spline/omp cut 1.3 chain 0",
    r"chain N must be between 1 and 1000 \(got 0\)")
row("style-omp-harmonic-wagner", scene_box(omp=True), "pair_style harmonic/spline/omp wagner",
    r"tail wagner needs an inflection point")
row("style-harmonic-lagunov-no-start", SCENE_BOX, "pair_style harmonic/spline lagunov 1.3",
    r"tail lagunov needs 'start Rs'")
row("style-harmonic-lagunov-start-0.5", scene_dimer(),
    ["pair_style harmonic/spline lagunov 1.3 start 0.5", "pair_coeff * * 1.0 6.0 1.0"],
    r"Rs.*(> 1|>= 1|0\.5)", None)
row("style-morse-lagunov-start-0.9", scene_dimer(),
    ["pair_style morse/spline lagunov 1.3 start 0.9", "pair_coeff * * 1.0 6.0 1.0"],
    r"Rs.*(> 1|>= 1|0\.9)", None)
row("coeff-rs-0.5", scene_dimer(),
    ["pair_style morse/spline lagunov 1.3", "pair_coeff * * 1.0 6.0 1.0 rs 0.5"],
    r"rs.*(> 1|>= 1|0\.5)", None)

# the same in an empty box
P = "pair_style morse/spline "
row("style-chain-twice-empty-box", SCENE_EMPTY, P + "cut 1.2 chain 2 chain 3",
    "keyword chain given twice")
row("style-cut-1e300-empty-box", SCENE_EMPTY, P + "cut 1e300",
    "Pair style morse/spline cut: Rc must be <= 100 in units")
row("style-lagunov-1e300", SCENE_EMPTY, P + "lagunov 1e300", "lagunov: Rc must be > 1 and <= 100")

# pair_coeff
for s in STYLES:
    usage = {"morse/spline": "D alpha a", "lj/spline": "D a", "mie/spline": "D a n m",
             "harmonic/spline": "D alpha a"}[s]
    short = " ".join(SCENE_LAW[s].split()[:-1])
    row(f"coeff-{s}-missing-arg", SCENE_BOX, [f"pair_style {s} cut 1.3", f"pair_coeff 1 1 {short}"],
        rf"Pair {s}: expected pair_coeff I J {usage}")
    row(f"coeff-{s}-extra-arg", SCENE_BOX, [f"pair_style {s} cut 1.3", f"pair_coeff 1 1 {SCENE_LAW[s]} 7"],
        rf"Pair {s} pair_coeff: unknown keyword '7'")

M = ["pair_style morse/spline cut 1.3"]
L = ["pair_style lj/spline cut 1.3"]
MIE = ["pair_style mie/spline cut 1.3"]
H = ["pair_style harmonic/spline cut 1.3"]
for rid, pre, coeff, expect, defect in [
    ("no-args", M, "pair_coeff", r"[Pp]air_coeff|Illegal|expected pair_coeff", None),
    ("one-arg", M, "pair_coeff 1", r"Illegal pair_coeff command: missing argument", None),
    ("D-abc", M, "pair_coeff 1 1 abc 6.0 1.0", r"\bD\b.*abc", None),
    ("alpha-nan", M, "pair_coeff 1 1 1.0 nan 1.0", r"alpha.*nan", None),
    ("a-inf", M, "pair_coeff 1 1 1.0 6.0 inf", r"\ba\b.*inf", None),
    ("lj-D--inf", L, "pair_coeff 1 1 -inf 1.0", r"\bD\b.*-inf", None),
    ("lj-D-1e309", L, "pair_coeff 1 1 1e309 1.0", r"\bD\b.*1e309", None),
    ("lj-a-1e", L, "pair_coeff 1 1 1.0 1e", r"\ba\b.*1e", None),
    ("D--0", M, "pair_coeff 1 1 -0 6.0 1.0", r"D must be > 0 \(got -0\)", None),
    ("D-0", M, "pair_coeff 1 1 0 6.0 1.0", r"D must be > 0 \(got 0\)", None),
    ("harmonic-alpha-0", H, "pair_coeff 1 1 1.0 0 1.0", r"alpha must be > 0 \(got 0\)", None),
    ("harmonic-a--1", H, "pair_coeff 1 1 1.0 6.0 -1", r"a must be > 0 \(got -1\)", None),
    ("mie-n-abc", MIE, "pair_coeff 1 1 1.0 1.0 abc 6", r"\bn\b.*abc", None),
    ("mie-n-nan", MIE, "pair_coeff 1 1 1.0 1.0 nan 6", r"\bn\b.*nan", None),
    ("mie-n-1e309", MIE, "pair_coeff 1 1 1.0 1.0 1e309 6", r"\bn\b.*1e309", None),
    ("mie-n-equals-m", MIE, "pair_coeff 1 1 1.0 1.0 6 6", r"n must be > m", None),
    ("mie-n-below-m", MIE, "pair_coeff 1 1 1.0 1.0 6 12", r"n must be > m \(got n = 6, m = 12\)", None),
    ("mie-m--0", MIE, "pair_coeff 1 1 1.0 1.0 12 -0", r"m must be > 0 \(got -0\)", None),
    ("mie-m-inf", MIE, "pair_coeff 1 1 1.0 1.0 12 inf", r"\bm\b.*inf", None),
    ("lj-mie-args", L, "pair_coeff 1 1 1.0 1.0 12 6", r"pair_coeff: unknown keyword '12'", None),
    ("kappa-first", M, "pair_coeff 1 1 kappa 2 1.0 6.0 1.0", r"\bD\b.*kappa", None),
    ("kappa-abc", M, "pair_coeff 1 1 1.0 6.0 1.0 kappa abc", r"kappa.*abc", None),
    ("kappa-nan", L, "pair_coeff 1 1 1.0 1.0 kappa nan", r"kappa.*nan", None),
    ("kappa-0", M, "pair_coeff 1 1 1.0 6.0 1.0 kappa 0", r"kappa must be > 0 \(got 0\)", None),
    ("kappa--1", L, "pair_coeff 1 1 1.0 1.0 kappa -1", r"kappa must be > 0 \(got -1\)", None),
    ("kappa--0", L, "pair_coeff 1 1 1.0 1.0 kappa -0", r"kappa must be > 0 \(got -0\)", None),
    ("kappa-nothing", M, "pair_coeff 1 1 1.0 6.0 1.0 kappa", r"keyword kappa needs a value",
     None),
    ("kappa-twice", M, "pair_coeff 1 1 1.0 6.0 1.0 kappa 1.1 kappa 1.2",
     r"keyword kappa given twice", None),
    ("rc-twice", M, "pair_coeff 1 1 1.0 6.0 1.0 rc 1.2 rc 1.25", r"keyword rc given twice",
     None),
    ("KAPPA", M, "pair_coeff 1 1 1.0 6.0 1.0 KAPPA 2", r"pair_coeff: unknown keyword 'KAPPA'",
     None),
    ("kappa-1e300", L, "pair_coeff 1 1 1.0 1.0 kappa 1e300", r"kappa 1e\+300 overflows", None),
    ("rc-1", M, "pair_coeff 1 1 1.0 6.0 1.0 rc 1", r"rc must be > 1", None),
    ("rc-nan", M, "pair_coeff 1 1 1.0 6.0 1.0 rc nan", r"\brc\b.*nan", None),
    ("rs-under-cut", M, "pair_coeff 1 1 1.0 6.0 1.0 rs 1.1", r"rs applies only to tail lagunov",
     None),
    ("rs-beyond-rc", ["pair_style morse/spline lagunov 1.3"], "pair_coeff 1 1 1.0 6.0 1.0 rs 1.4",
     r"must be > its start Rs = 1.4", None),
    ("rs-0", ["pair_style morse/spline lagunov 1.3"], "pair_coeff 1 1 1.0 6.0 1.0 rs 0",
     r"rs must be > 0 \(got 0\)", None),
    ("rc-wagner", ["pair_style lj/spline wagner"], "pair_coeff 1 1 1.0 1.0 rc 1.3",
     r"rc does not apply to tail wagner", None),
    ("type-0", M, "pair_coeff 0 1 1.0 6.0 1.0", r"type.*\b0\b", None),
    ("type-ntypes+1", M, "pair_coeff 1 3 1.0 6.0 1.0", r"type.*\b3\b", None),
    ("type-range-2*1", M, "pair_coeff 2*1 * 1.0 6.0 1.0", r"2\*1", None),
    ("type-float", M, "pair_coeff 1.5 1 1.0 6.0 1.0", r"type.*1\.5", None),
    ("type-label", M, "pair_coeff Al Al 1.0 6.0 1.0", r"[Tt]ype.*Al", None),
    ("before-pair_style", [], "pair_coeff * * 1.0 6.0 1.0", r"Pair_coeff command without a "
     r"pair style", None),
]:
    row(f"coeff-{rid}", SCENE_BOX + pre, coeff, expect, defect)

row("coeff-rc-1e300", SCENE_BOX + M, "pair_coeff 1 1 1.0 6.0 1.0 rc 1e300",
    r"rc must be > 1 and <= .*\(got 1e300\)")    # known, fixed
row("coeff-I-gt-J", SCENE_BOX + M, ["pair_coeff * * 1.0 6.0 1.0", "pair_coeff 2 1 1.0 6.0 1.1"], OK)
row("coeff-omp-D-0", scene_box(omp=True) + ["pair_style morse/spline/omp cut 1.3"],
    "pair_coeff 1 1 0 6.0 1.0", r"D must be > 0 \(got 0\)")
row("coeff-omp-mie-n-below-m", scene_box(omp=True) + ["pair_style mie/spline/omp cut 1.3"],
    "pair_coeff 1 1 1.0 1.0 6 9", r"n must be > m")

# overflows of the law and bounds, in an empty box
for rid, cmds, message in [
    ("morse-kappa-1e300-overflows", ["pair_style morse/spline cut 1.3",
                                      "pair_coeff * * 1.0 6.75 1.0 kappa 1e300"],
     "law of types 1 1 with kappa 1e\\+300 overflows at r = 0.5 a"),
    ("harmonic-kappa-1e300-overflows", ["pair_style harmonic/spline cut 1.3",
                                         "pair_coeff * * 1.0 6.75 1.0 kappa 1e300"],
     "law of types 1 1 with kappa 1e\\+300 overflows"),
    ("morse-kappa-200-overflows", ["pair_style morse/spline cut 1.3",
                                    "pair_coeff * * 1.0 6.75 1.0 kappa 200"],
     "law of types 1 1 with kappa 200 overflows at r = 0.5 a \\(alpha a must"),
    ("lj-kappa-1e300-overflows", ["pair_style lj/spline cut 1.3",
                                   "pair_coeff * * 1.0 1.0 kappa 1e300"],
     "with kappa 1e\\+300 overflows"),
    ("kappa-twice-empty-box", ["pair_style morse/spline cut 1.2",
                               "pair_coeff * * 1.0 6.0 1.0 kappa 1.1 kappa 1.2"],
     "Pair morse/spline pair_coeff: keyword kappa given twice"),
    ("rc-1e300-empty-box", ["pair_style morse/spline cut 1.2",
                            "pair_coeff * * 1.0 6.0 1.0 rc 1e300"],
     "rc must be > 1 and <= 100 in units of a \\(got 1e300\\)"),
]:
    row(f"coeff-{rid}", SCENE_EMPTY, cmds, message)

# runs: each style
for s in STYLES:
    for omp in (False, True):
        sfx = "/omp" if omp else ""
        row(f"run-{s}{sfx}-dimer", scene_dimer(omp=omp), scene_pair(s, omp=omp), OK)
        row(f"run-{s}{sfx}-overlap", scene_dimer(r=0.0, omp=omp), scene_pair(s, omp=omp),
            r"atoms 1 and 2 are 0 apart")
for s in STYLES:
    row(f"run-{s}-beyond-cutoff", scene_dimer(r=2.5), scene_pair(s), OK)
    row(f"run-{s}-zero-atoms", SCENE_BOX, scene_pair(s), OK)
    for u in SCENE_UNITS:
        row(f"units-{u}-{s}", [], scene_unit_dimer(u, s), OK)
row("run-overlap-other-type", scene_dimer(r=0.0)[:-1] + ["create_atoms 2 single 0 0 0"],
    scene_pair("lj/spline", "cut 1.3"), r"atoms 1 and 2 are 0 apart")
NOT_SET = "LAMMPS's own check (Pair::init, before any style code) says 'All pair coeffs are not set'"
row("run-missing-coeff-2-2", scene_dimer(), ["pair_style morse/spline cut 1.3",
                                             "pair_coeff 1 1 1.0 6.0 1.0"],
    r"types 2 2 are not set", NOT_SET)
row("run-no-coeff", scene_dimer(), ["pair_style lj/spline cut 1.3"], r"types 1 1 are not set", NOT_SET)
row("run-missing-coeff-1-2", scene_dimer(), ["pair_style morse/spline cut 1.3",
                                             "pair_coeff 1 1 1.0 6.0 1.0", "pair_coeff 2 2 1.0 6.0 1.0"],
    r"coefficients for atom types 1 2 are not set")
row("run-mix-arithmetic", scene_dimer(), ["pair_style morse/spline cut 1.3",
                                          "pair_coeff 1 1 1.0 6.0 1.0", "pair_coeff 2 2 1.0 6.0 1.2",
                                          "pair_modify mix arithmetic"], r"coefficients for atom types 1 2 are not set")
row("run-shift-yes", SCENE_MORSE, "pair_modify shift yes", OK)
row("run-lj-kappa-2-singular", scene_dimer(r=0.4), scene_pair("lj/spline", "cut 1.3", "1.0 1.0 kappa 2"),
    r"atoms 1 and 2 are 0.4 apart")
row("run-lj-kappa-tiny", scene_dimer(), scene_pair("lj/spline", "cut 1.3", "1.0 1.0 kappa 1e-300"), OK)
row("run-D-huge", scene_dimer(r=0.9), scene_pair("morse/spline", "cut 1.3", "1e300 6.0 1.0"), OK)
row("run-D-tiny", scene_dimer(), scene_pair("morse/spline", "cut 1.3", "1e-300 6.0 1.0"), OK)
row("run-morse-a-tiny", scene_dimer(), scene_pair("morse/spline", "cut 1.3", "1.0 6.0 1e-300"),
    r"neighbor skin 0.3 is .* x the interaction range 1.3e-300")
row("run-lj-a-tiny", scene_dimer(), scene_pair("lj/spline", "cut 1.3", "1.0 1e-300"),
    r"overflows at r = a/2 \(D / a\^3 is beyond double precision")
row("run-lj-a-huge", scene_dimer(), scene_pair("lj/spline", "cut 1.3", "1.0 1e300"), r"\ba\b.*1e\+?300",
    "LAMMPS's binning fails first: 'Cannot use neighbor bins - box size << cutoff' (cutoff 1.3e300)")
row("run-alpha-tiny", scene_dimer(), scene_pair("morse/spline", "cut 1.3", "1.0 1e-300 1.0"), OK)
row("run-harmonic-lagunov-rs", scene_dimer(), ["pair_style harmonic/spline lagunov 1.3",
                                               "pair_coeff * * 1.0 6.0 1.0 rs 1.1"],
    r"tail lagunov needs 'start Rs'; the harmonic well")    # doc: start Rs first, rs per pair
row("run-chain-3", scene_dimer(), scene_pair("morse/spline", "cut 1.3 chain 3"), OK)
row("run-chain-1000", scene_dimer(), scene_pair("morse/spline", "cut 1.3 chain 1000"), r"chain",
    "LAMMPS's binning fails first: 'Cannot use neighbor bins - box size << cutoff' (cutoff 1300)")
row("run-tail-yes", SCENE_MORSE, "pair_modify tail yes", r"tail",
    None)
row("run-pair-respa", SCENE_MORSE, ["run_style respa 2 2"], r"Pair morse/spline is not for run_style "
    r"respa")
row("run-skin-huge", SCENE_MORSE, "neighbor 1e300 bin", r"neighbor skin 1e\+300 is .* the interaction "
    r"range")
row("run-hybrid", scene_dimer(), ["pair_style hybrid/overlay morse/spline cut 1.3 lj/spline wagner",
                                  "pair_coeff * * morse/spline 1.0 6.0 1.0",
                                  "pair_coeff * * lj/spline 1.0 1.0"], OK)

# fix adapt reaches the law's parameters past pair_coeff's checks: each change is checked
# again when the pair style takes it (its error names the type pair and the values)
NEED = r"types 1 1 need D, a, kappa > 0"
for rid, style, param, value in [
    ("kappa-0", "morse/spline", "kappa", "0"),
    ("kappa--1", "lj/spline", "kappa", "-1"),
    ("D--1", "morse/spline", "D", "-1"),
    ("a--1", "morse/spline", "a", "-1"),
    ("alpha--6", "morse/spline", "alpha", "-6"),
    ("mie-n-below-m", "mie/spline", "n", "3"),
    ("mie-m-0", "mie/spline", "m", "0"),
]:
    row(f"adapt-{rid}", scene_dimer() + scene_pair(style, "cut 1.3"),
        [f"variable k equal {value}", f"fix a all adapt 1 pair {style} {param} * * v_k"], NEED)
row("adapt-omp-kappa-0", scene_dimer(omp=True) + scene_pair("morse/spline", "cut 1.3", omp=True),
    ["variable k equal 0", "fix a all adapt 1 pair morse/spline/omp kappa * * v_k"], NEED)
row("adapt-lj-a-0", scene_dimer() + scene_pair("lj/spline", "cut 1.3"),
    ["variable k equal 0", "fix a all adapt 1 pair lj/spline a * * v_k"], NEED)
# a cutoff (Rc a) that fix adapt moves past the neighbour lists' reach would lose pairs
GROWN = r"fix adapt moved the cutoff of types 1 1 to 1\.313 beyond 1\.3,"
row("adapt-a-grows-past-list", SCENE_MORSE, ["variable k equal 1.0+step*0.01", "fix n all nve",
                                             "fix a all adapt 1 pair morse/spline a * * v_k",
                                             "run 10 post no"], GROWN)
row("adapt-omp-a-grows-past-list", scene_dimer(omp=True) + scene_pair("morse/spline", "cut 1.3", omp=True),
    ["variable k equal 1.0+step*0.01", "fix n all nve",
     "fix a all adapt 1 pair morse/spline/omp a * * v_k", "run 10 post no"], GROWN)
row("adapt-hybrid-a-grows-past-list", scene_dimer() + [
    "pair_style hybrid/overlay lj/cut 1.5 morse/spline cut 1.3", "pair_coeff * * lj/cut 0.1 1.0",
    "pair_coeff * * morse/spline 1.0 6.0 1.0"],
    ["variable k equal 1.0+step*0.2", "fix n all nve",
     "fix a all adapt 1 pair morse/spline a * * v_k", "run 10 post no"],
    r"fix adapt moved the cutoff of types 1 1 to 1\.56 beyond 1\.5,")
row("adapt-a-grows-in-a-later-run", SCENE_MORSE,
    ["fix n all nve", "run 0 post no", "variable k equal 1.1",
     "fix a all adapt 1 pair morse/spline a * * v_k", "run 0 post no"],
    r"fix adapt moved the cutoff of types 1 1 to 1\.43 beyond 1\.3,")
# reset no keeps a = 0.9 for the next run, whose lists are made for it: a back to 1 is past them
row("adapt-a-back-up-after-reset-no", SCENE_MORSE,
    ["fix n all nve", "variable k equal 0.9", "fix a all adapt 1 pair morse/spline a * * v_k",
     "run 0 post no", "variable k equal 1.0", "run 0 post no"],
    r"fix adapt moved the cutoff of types 1 1 to 1\.3 beyond 1\.17,")
row("adapt-a-back-up-after-reset-yes", SCENE_MORSE,
    ["fix n all nve", "variable k equal 0.9",
     "fix a all adapt 1 pair morse/spline a * * v_k reset yes", "run 0 post no",
     "variable k equal 1.0", "run 0 post no"], OK)
row("adapt-C", SCENE_MORSE, ["variable k equal 5", "fix a all adapt 1 pair morse/spline C * * v_k"],
    r"C of types 1 1 is the law's stiffness, derived from its parameters")
for u, grown in [("metal", r"to 4\.0625 beyond 3\.25,"), ("si", r"to 1\.625e-05 beyond 1\.3e-05,")]:
    a = SCENE_UNITS[u][1]
    row(f"adapt-units-{u}-a-grows-past-list", scene_unit_dimer(u, "morse/spline"),
        [f"variable k equal {1.25 * a!r}", "fix n all nve",
         "fix a all adapt 1 pair morse/spline a * * v_k", "run 10 post no"],
        "fix adapt moved the cutoff of types 1 1 " + grown)
# the styles' extract() also hands their state objects to this package's fixes and computes:
# fix adapt must not write a number over them (it refuses the dimension; was a crash)
row("adapt-damping_pass", SCENE_MORSE, ["variable k equal 1",
                                   "fix a all adapt 1 pair morse/spline damping_pass * * v_k"],
    r"Pair style parameter damping_pass is not compatible with fix adapt", isolate=True)
row("adapt-a-shrinks", SCENE_MORSE, ["variable k equal 1.0-step*0.01", "fix n all nve",
                                     "fix a all adapt 1 pair morse/spline a * * v_k",
                                     "run 10 post no"], OK)
row("adapt-kappa-ramp", SCENE_MORSE, ["variable k equal 0.5+step*0.01", "fix n all nve",
                                      "fix a all adapt 1 pair morse/spline kappa * * v_k",
                                      "run 10 post no"], OK)

row("run-respa-empty-box", SCENE_EMPTY,
    ["pair_style morse/spline cut 1.2", "pair_coeff * * 1.0 6.0 1.0", "run_style respa 2 2",
     "run 1"], "Pair morse/spline is not for run_style respa")
row("run-respa-with-descent", SCENE_EMPTY,
    ["pair_style morse/spline cut 1.2", "pair_coeff * * 1.0 6.0 1.0",
     "fix d all descent/normalized h 0.01", "run_style respa 2 2", "run 1"],
    "Pair morse/spline is not for run_style respa")


@pytest.mark.parametrize("setup,cmds,expect,isolate", INPUTS.rows)
def test_hostile_input(setup, cmds, expect, isolate):
    check_input(setup, cmds, expect, isolate)
