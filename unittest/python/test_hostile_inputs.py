"""Hostile, bad and edge-case input for every style of the plugin, table-driven.

Each row: (setup commands, hostile commands, expected outcome).  The hostile commands run one
after another in a LAMMPS instance with the plugin loaded, then `run 0`:
  * expected an error regex: some hostile command (or the final `run 0`) must stop with a
    LAMMPS error whose message (the first ~99 characters the Python exception carries) matches;
    the same instance must then still take commands (`variable alive equal 1`);
  * expected OK: no error, and the thermo pe and press of the final `run 0` are finite
    (thermo_modify norm no), as is every other thermo value (the computes').
A clear error names the offending argument or keyword (a parameter name, or the plugin's
own words for it) and what is wrong.  Generic LAMMPS messages raised from inside the plugin's
parsers (utils::numeric/inumeric/bnumeric/logical/bounds: "Expected floating point parameter
instead of 'abc'", "Numeric index 3 is out of bounds", "Invalid range string") do not say
which parameter of the command is wrong and count as unclear, as do messages that mislead.

Rows that show a defect keep the behaviour they should have and are marked xfail(strict=True)
with what they do now.  Rows flagged `isolate` (NaN, huge values) run in a child process, so
that a crash or a hang could not take the test runner down."""
import json
import math
import os
import re
import subprocess
import sys

import pytest
from conftest import session

OK = "ok"
HERE = os.path.dirname(os.path.abspath(__file__))

LAW = {"morse/spline": "1.0 6.0 1.0", "lj/spline": "1.0 1.0", "mie/spline": "1.0 1.0 12 6",
       "harmonic/spline": "1.0 6.0 1.0"}
STYLES = list(LAW)
TAIL = {"morse/spline": "cut 1.3", "lj/spline": "wagner", "mie/spline": "lagunov 1.4",
        "harmonic/spline": "lagunov 1.3 start 1.1"}


def box(units="lj", ntypes=2, omp=False):
    """An empty periodic box of ntypes types (units lj: -3..3), thermo not normalised."""
    return (["package omp 2"] if omp else []) + [
        f"units {units}", "atom_modify map array", "region box block -3 3 -3 3 -3 3",
        f"create_box {ntypes} box", "mass * 1.0", "thermo_modify norm no"]


def dimer(r=1.05, omp=False, ntypes=2):
    """Two type-1 atoms r apart along x (a = 1)."""
    return box(omp=omp, ntypes=ntypes) + ["create_atoms 1 single 0 0 0",
                                          f"create_atoms 1 single {r!r} 0 0"]


def pair(style="morse/spline", tail=None, law=None, omp=False):
    return [f"pair_style {style}{'/omp' if omp else ''} {tail or TAIL[style]}",
            f"pair_coeff * * {law or LAW[style]}"]


MORSE = dimer() + pair("morse/spline", "cut 1.3")
MORSE_LINK = dimer() + pair("morse/spline", "cut 1.3 link 1.1")
NOBOX = ["units lj"]
BOX = box()

# unit styles: (units, a, D, alpha, mass, skin); the dimer 1.05 a apart
UNIT_SCENES = {
    "metal": ("metal", 2.5, 0.3, 1.5, 63.5, 1.0),
    "real": ("real", 3.0, 0.2, 2.0, 27.0, 1.0),
    "si": ("si", 1.0e-5, 2.46e-6, 3.76e5, 1.0e-12, 2.0e-6),
}


def unit_scene(name, style):
    units, a, d, alpha, mass, skin = UNIT_SCENES[name]
    law = {"morse/spline": f"{d} {alpha} {a}", "harmonic/spline": f"{d} {alpha} {a}",
           "lj/spline": f"{d} {a}", "mie/spline": f"{d} {a} 9 6"}[style]
    tail = "lagunov 1.3 start 1.1" if style == "harmonic/spline" else "cut 1.3"
    return [f"units {units}", "atom_modify map array",
            f"region box block {-4 * a} {4 * a} {-4 * a} {4 * a} {-4 * a} {4 * a}",
            "create_box 1 box", f"mass 1 {mass}", f"neighbor {skin} bin",
            "thermo_modify norm no", "create_atoms 1 single 0 0 0",
            f"create_atoms 1 single {1.05 * a!r} 0 0", f"pair_style {style} {tail}",
            f"pair_coeff 1 1 {law}"]


ROWS = []
ISOLATE = set()


def row(rid, setup, cmds, expect, defect=None, isolate=False):
    """defect: what the row does now instead (strict xfail)."""
    if isinstance(cmds, str):
        cmds = [cmds]
    marks = []
    if defect:
        marks.append(pytest.mark.xfail(reason=defect, strict=True))
    if isolate:
        ISOLATE.add(rid)
    ROWS.append(pytest.param(list(setup), list(cmds), expect, id=rid, marks=marks))


GENERIC = "generic LAMMPS message, does not name the parameter"

# ---------------------------------------------------------------- A. before a box exists
NORUN = r"Run command before simulation box is defined"
row("nobox-pair_style", NOBOX, "pair_style morse/spline cut 1.3", NORUN)
row("nobox-pair_coeff", NOBOX, ["pair_style morse/spline cut 1.3", "pair_coeff * * 1.0 6.0 1.0"],
    "Pair_coeff command before simulation box is defined")
row("nobox-fix-viscous", NOBOX, "fix v all viscous/relative gamma 1.0",
    "Fix viscous/relative command before simulation box is defined")
row("nobox-fix-descent", NOBOX, "fix d all descent/normalized h 0.1",
    "Fix descent/normalized command before simulation box is defined")
row("nobox-compute-dust", NOBOX, "compute d all dust", NORUN)
row("nobox-compute-links", NOBOX, "compute l all links/atom", NORUN)
row("nobox-compute-params", NOBOX, "compute p all pair/params 1 1", r"box",
    None)

# ---------------------------------------------------------------- B. pair_style settings
for s in STYLES:
    for omp in (False, True):
        sfx = "/omp" if omp else ""
        row(f"style-{s}{sfx}-no-tail", box(omp=omp), f"pair_style {s}{sfx}",
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
    ("cut-2-numbers", "cut 1.3 1.5", r"unknown keyword '1.5' after tail cut", None),
    ("cut-uppercase", "CUT 1.3", r"unknown tail 'CUT'", None),
    ("order-link-before-tail", "link 1.05 cut 1.3", r"unknown tail 'link'", None),
    ("wagner-number", "wagner 1.5", r"wagner: takes no arguments \(got 1.5\)", None),
    ("wagner-word", "wagner abc", r"unknown keyword 'abc' after tail wagner", None),
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
    ("link-0.5", "cut 1.3 link 0.5", r"link L must be >= 1 in units of a \(got 0.5\)", None),
    ("link--0", "cut 1.3 link -0", r"link L must be >= 1 in units of a \(got -0\)", None),
    ("link-nan", "cut 1.3 link nan", r"link.*nan", None),
    ("link-nothing", "cut 1.3 link", r"keyword link needs a value", None),
    ("relink-maybe", "cut 1.3 link 1.05 relink maybe", r"relink must be yes or no \(got 'maybe'\)",
     None),
    ("relink-without-link", "cut 1.3 relink yes", r"relink needs link L", None),
    ("link-with-chain", "cut 1.3 link 1.05 chain 2", r"link and chain N do not combine", None),
]:
    row(f"style-{rid}", BOX, P + args, expect, defect)

# known defects, fixed in the build these rows were written against
row("style-link-twice", BOX, P + "cut 1.3 link 1.05 link 1.1", r"keyword link given twice")
row("style-relink-twice", BOX, P + "cut 1.3 link 1.05 relink yes relink no",
    r"keyword relink given twice")
row("style-cut-1e300", BOX, P + "cut 1e300", r"Rc must be <= .*\(got 1e300\)")
row("style-link-beyond-tail", MORSE[:-2], [P + "cut 1.3 link 5", "pair_coeff * * 1.0 6.0 1.0"],
    r"link L .*(tail|Rc|1\.3)")
row("style-omp-cut-abc", box(omp=True), "pair_style morse/spline/omp cut abc",
    r"expected a number Rc \(got 'abc'\)")
row("style-omp-lj-lagunov-0.5", box(omp=True), "pair_style lj/spline/omp lagunov 0.5",
    r"lagunov: Rc must be > 1")
row("style-omp-mie-chain-0", box(omp=True), "pair_style mie/spline/omp cut 1.3 chain 0",
    r"chain N must be between 1 and 1000 \(got 0\)")
row("style-omp-harmonic-wagner", box(omp=True), "pair_style harmonic/spline/omp wagner",
    r"tail wagner needs an inflection point")
row("style-harmonic-lagunov-no-start", BOX, "pair_style harmonic/spline lagunov 1.3",
    r"tail lagunov needs 'start Rs'")
RS_BELOW_A = ("silently accepted: smoothing from Rs < 1 reshapes the well (pe at r = 1.05 a "
              "{})")
row("style-harmonic-lagunov-start-0.5", dimer(),
    ["pair_style harmonic/spline lagunov 1.3 start 0.5", "pair_coeff * * 1.0 6.0 1.0"],
    r"Rs.*(> 1|>= 1|0\.5)", None)
row("style-morse-lagunov-start-0.9", dimer(),
    ["pair_style morse/spline lagunov 1.3 start 0.9", "pair_coeff * * 1.0 6.0 1.0"],
    r"Rs.*(> 1|>= 1|0\.9)", None)
row("coeff-rs-0.5", dimer(),
    ["pair_style morse/spline lagunov 1.3", "pair_coeff * * 1.0 6.0 1.0 rs 0.5"],
    r"rs.*(> 1|>= 1|0\.5)", None)
row("style-switch-link-off", MORSE_LINK, ["run 0 post no", "pair_style morse/spline cut 1.3"],
    r"link cannot be switched off once set")

# ---------------------------------------------------------------- C. pair_coeff
for s in STYLES:
    usage = {"morse/spline": "D alpha a", "lj/spline": "D a", "mie/spline": "D a n m",
             "harmonic/spline": "D alpha a"}[s]
    short = " ".join(LAW[s].split()[:-1])
    row(f"coeff-{s}-missing-arg", BOX, [f"pair_style {s} cut 1.3", f"pair_coeff 1 1 {short}"],
        rf"Pair {s}: expected pair_coeff I J {usage}")
    row(f"coeff-{s}-extra-arg", BOX, [f"pair_style {s} cut 1.3", f"pair_coeff 1 1 {LAW[s]} 7"],
        rf"Pair {s}: unknown pair_coeff keyword '7'")

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
    ("lj-mie-args", L, "pair_coeff 1 1 1.0 1.0 12 6", r"unknown pair_coeff keyword '12'", None),
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
    ("KAPPA", M, "pair_coeff 1 1 1.0 6.0 1.0 KAPPA 2", r"unknown pair_coeff keyword 'KAPPA'",
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
    row(f"coeff-{rid}", BOX + pre, coeff, expect, defect)

row("coeff-rc-1e300", BOX + M, "pair_coeff 1 1 1.0 6.0 1.0 rc 1e300",
    r"rc must be > 1 and <= .*\(got 1e300\)")    # known, fixed
row("coeff-I-gt-J", BOX + M, ["pair_coeff * * 1.0 6.0 1.0", "pair_coeff 2 1 1.0 6.0 1.1"], OK)
row("coeff-omp-D-0", box(omp=True) + ["pair_style morse/spline/omp cut 1.3"],
    "pair_coeff 1 1 0 6.0 1.0", r"D must be > 0 \(got 0\)")
row("coeff-omp-mie-n-below-m", box(omp=True) + ["pair_style mie/spline/omp cut 1.3"],
    "pair_coeff 1 1 1.0 1.0 6 9", r"n must be > m")

# ---------------------------------------------------------------- D. runs: each style
for s in STYLES:
    for omp in (False, True):
        sfx = "/omp" if omp else ""
        row(f"run-{s}{sfx}-dimer", dimer(omp=omp), pair(s, omp=omp), OK)
        row(f"run-{s}{sfx}-overlap", dimer(r=0.0, omp=omp), pair(s, omp=omp),
            r"atoms 1 and 2 are 0 apart")
for s in STYLES:
    row(f"run-{s}-beyond-cutoff", dimer(r=2.5), pair(s), OK)
    row(f"run-{s}-zero-atoms", BOX, pair(s), OK)
    for u in UNIT_SCENES:
        row(f"units-{u}-{s}", [], unit_scene(u, s), OK)
row("run-overlap-other-type", dimer(r=0.0)[:-1] + ["create_atoms 2 single 0 0 0"],
    pair("lj/spline", "cut 1.3"), r"atoms 1 and 2 are 0 apart")
NOT_SET = "LAMMPS's own check (Pair::init, before any style code) says 'All pair coeffs are not set'"
row("run-missing-coeff-2-2", dimer(), ["pair_style morse/spline cut 1.3",
                                       "pair_coeff 1 1 1.0 6.0 1.0"],
    r"types 2 2 are not set", NOT_SET)
row("run-no-coeff", dimer(), ["pair_style lj/spline cut 1.3"], r"types 1 1 are not set", NOT_SET)
row("run-missing-coeff-1-2", dimer(), ["pair_style morse/spline cut 1.3",
                                       "pair_coeff 1 1 1.0 6.0 1.0", "pair_coeff 2 2 1.0 6.0 1.0"],
    r"coefficients for atom types 1 2 are not set")
row("run-mix-arithmetic", dimer(), ["pair_style morse/spline cut 1.3",
                                    "pair_coeff 1 1 1.0 6.0 1.0", "pair_coeff 2 2 1.0 6.0 1.2",
                                    "pair_modify mix arithmetic"], r"coefficients for atom types 1 2 are not set")
row("run-shift-yes", MORSE, "pair_modify shift yes", OK)
row("run-lj-kappa-2-singular", dimer(r=0.4), pair("lj/spline", "cut 1.3", "1.0 1.0 kappa 2"),
    r"atoms 1 and 2 are 0.4 apart")
row("run-lj-kappa-tiny", dimer(), pair("lj/spline", "cut 1.3", "1.0 1.0 kappa 1e-300"), OK)
row("run-D-huge", dimer(r=0.9), pair("morse/spline", "cut 1.3", "1e300 6.0 1.0"), OK)
row("run-D-tiny", dimer(), pair("morse/spline", "cut 1.3", "1e-300 6.0 1.0"), OK)
row("run-morse-a-tiny", dimer(), pair("morse/spline", "cut 1.3", "1.0 6.0 1e-300"),
    r"neighbor skin 0.3 is .* x the interaction range 1.3e-300")
row("run-lj-a-tiny", dimer(), pair("lj/spline", "cut 1.3", "1.0 1e-300"),
    r"overflows at r = a/2 \(D / a\^3 is beyond double precision")
row("run-lj-a-huge", dimer(), pair("lj/spline", "cut 1.3", "1.0 1e300"), r"\ba\b.*1e\+?300",
    "LAMMPS's binning fails first: 'Cannot use neighbor bins - box size << cutoff' (cutoff 1.3e300)")
row("run-alpha-tiny", dimer(), pair("morse/spline", "cut 1.3", "1.0 1e-300 1.0"), OK)
row("run-harmonic-lagunov-rs", dimer(), ["pair_style harmonic/spline lagunov 1.3",
                                         "pair_coeff * * 1.0 6.0 1.0 rs 1.1"],
    r"tail lagunov needs 'start Rs'; the harmonic well")    # doc: start Rs first, rs per pair
row("run-chain-3", dimer(), pair("morse/spline", "cut 1.3 chain 3"), OK)
row("run-chain-1000", dimer(), pair("morse/spline", "cut 1.3 chain 1000"), r"chain",
    "LAMMPS's binning fails first: 'Cannot use neighbor bins - box size << cutoff' (cutoff 1300)")
row("run-link", MORSE_LINK, [], OK)
row("run-tail-yes", MORSE, "pair_modify tail yes", r"tail",
    None)
row("run-pair-respa", MORSE, ["run_style respa 2 2"], r"Pair morse/spline is not for run_style "
    r"respa")
row("run-skin-huge", MORSE, "neighbor 1e300 bin", r"neighbor skin 1e\+300 is .* the interaction "
    r"range")
row("run-hybrid", dimer(), ["pair_style hybrid/overlay morse/spline cut 1.3 lj/spline wagner",
                            "pair_coeff * * morse/spline 1.0 6.0 1.0",
                            "pair_coeff * * lj/spline 1.0 1.0"], OK)
row("run-hybrid-two-links", dimer(), "pair_style hybrid/overlay morse/spline cut 1.3 link 1.05 "
    "lj/spline cut 1.3 link 1.05", r"another pair style already keeps links")
row("run-unfix-link-state", MORSE_LINK, ["run 0 post no", "unfix NEIGH_HISTORY_LINK"],
    r"link state \(fix NEIGH_HISTORY_LINK\) was deleted by unfix")
row("run-pair-local-link", MORSE_LINK, "compute pl all pair/local dist eng",
    r"does not support compute pair/local")
row("run-born-matrix-link", MORSE_LINK, "compute b all born/matrix",
    r"morse/spline does not support compute born/matrix")
row("run-pair-write-link", MORSE_LINK, "pair_write 1 1 10 r 0.5 1.3 /dev/null X",
    r"does not support pair_write")
row("run-minimize-link", MORSE_LINK, "minimize 0 0 10 100", OK)
# replacing a pair style with link L: the link state must not outlive it
NORM = "thermo_modify norm no"
row("run-link-to-lj-cut", MORSE_LINK, ["run 0 post no", "pair_style lj/cut 1.5",
                                       "pair_coeff * * 1.0 1.0", "run 3 post no"], OK)
row("run-link-to-none", MORSE_LINK, ["run 0 post no", "pair_style none", "run 3 post no"], OK)
row("run-link-to-other-spline", MORSE_LINK, ["run 0 post no", "pair_style lj/spline cut 1.3",
                                             "pair_coeff * * 1.0 1.0", "run 3 post no"], OK)
row("run-link-to-hybrid", MORSE_LINK, ["run 0 post no",
                                       "pair_style hybrid/overlay lj/cut 1.5 morse/spline cut 1.3",
                                       "pair_coeff * * lj/cut 1.0 1.0",
                                       "pair_coeff * * morse/spline 1.0 6.0 1.0", "run 3 post no"],
    OK)
row("run-link-to-lj-cut-viscous", MORSE_LINK, ["fix n all nve", "fix v all viscous/relative gamma 1",
                                               "run 0 post no", "pair_style lj/cut 1.5",
                                               "pair_coeff * * 1.0 1.0", "run 3 post no"], OK)
row("run-link-to-lj-cut-dust", MORSE_LINK, ["compute d all dust links",
                                            "thermo_style custom step pe press c_d[1]", NORM,
                                            "run 0 post no", "pair_style lj/cut 1.5",
                                            "pair_coeff * * 1.0 1.0"],
    r"Compute dust links needs a pair style with link L")
row("run-hybrid-link-computes", dimer(), [
    "pair_style hybrid/overlay lj/cut 1.5 morse/spline cut 1.3 link 1.1",
    "pair_coeff * * lj/cut 0.1 1.0", "pair_coeff * * morse/spline 1.0 6.0 1.0",
    "compute l all links/atom", "compute n all reduce sum c_l", "compute d all dust links",
    "fix n all nve", "fix v all viscous/relative J 50",
    "thermo_style custom step pe press c_n c_d[1]", NORM, "run 3 post no"], OK)
row("run-hybrid-pair-params", dimer(), [
    "pair_style hybrid/overlay lj/cut 1.5 morse/spline cut 1.3 link 1.1",
    "pair_coeff * * lj/cut 0.1 1.0", "pair_coeff * * morse/spline 1.0 6.0 1.0",
    "compute c all pair/params 1 1"], r"pair style hybrid/overlay has no single\(\)")
row("run-delete-all-linked", MORSE_LINK, [
    "compute l all links/atom", "compute d all dust links", "compute n all reduce sum c_l",
    "thermo_style custom step pe press c_n c_d[1] c_d[4]", NORM, "run 0 post no",
    "delete_atoms group all", "run 3 post no"], OK)

# the link state is kept by partner ID: what it needs from the box and the commands around it
row("link-thin-periodic-box", ["units lj", "region box block 0 2.25 -4 4 -4 4", "create_box 1 box",
                               "mass 1 1.0", "create_atoms 1 single 0.2 0 0 units box",
                               "create_atoms 1 single 1.2 0 0 units box", "neighbor 0.3 bin"]
    + pair("morse/spline", "cut 1.3 link 1.05"),
    [], r"the periodic box is 2\.25 wide along x, not more than twice")
row("link-tiled-newton-on", MORSE_LINK, ["comm_style tiled"],
    r"the link state needs newton off under comm_style tiled")
row("link-tiled-newton-off", dimer() + ["newton off on", "comm_style tiled"]
    + pair("morse/spline", "cut 1.3 link 1.1"), ["fix n all nve", "run 5 post no"], OK)
row("link-evaporate-before-pair-style", dimer() + [
    "region r block INF INF INF INF INF INF", "fix ev all evaporate 1 1 r 4711"]
    + pair("morse/spline", "cut 1.3 link 1.1"), ["fix n all nve"],
    r"fix ev \(evaporate\) adds or deletes atoms before the link state")
row("link-evaporate-after-pair-style", MORSE_LINK, [
    "region r block INF INF INF INF INF INF", "fix ev all evaporate 1 1 r 4711", "fix n all nve",
    "run 3 post no"], OK)

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
    row(f"adapt-{rid}", dimer() + pair(style, "cut 1.3"),
        [f"variable k equal {value}", f"fix a all adapt 1 pair {style} {param} * * v_k"], NEED)
row("adapt-omp-kappa-0", dimer(omp=True) + pair("morse/spline", "cut 1.3", omp=True),
    ["variable k equal 0", "fix a all adapt 1 pair morse/spline/omp kappa * * v_k"], NEED)
row("adapt-lj-a-0", dimer() + pair("lj/spline", "cut 1.3"),
    ["variable k equal 0", "fix a all adapt 1 pair lj/spline a * * v_k"], NEED)
# a cutoff (Rc a) that fix adapt moves past the neighbour lists' reach would lose pairs
GROWN = r"fix adapt moved the cutoff of types 1 1 to 1\.313 beyond 1\.3,"
row("adapt-a-grows-past-list", MORSE, ["variable k equal 1.0+step*0.01", "fix n all nve",
                                       "fix a all adapt 1 pair morse/spline a * * v_k",
                                       "run 10 post no"], GROWN)
row("adapt-omp-a-grows-past-list", dimer(omp=True) + pair("morse/spline", "cut 1.3", omp=True),
    ["variable k equal 1.0+step*0.01", "fix n all nve",
     "fix a all adapt 1 pair morse/spline/omp a * * v_k", "run 10 post no"], GROWN)
row("adapt-hybrid-a-grows-past-list", dimer() + [
    "pair_style hybrid/overlay lj/cut 1.5 morse/spline cut 1.3", "pair_coeff * * lj/cut 0.1 1.0",
    "pair_coeff * * morse/spline 1.0 6.0 1.0"],
    ["variable k equal 1.0+step*0.2", "fix n all nve",
     "fix a all adapt 1 pair morse/spline a * * v_k", "run 10 post no"],
    r"fix adapt moved the cutoff of types 1 1 to 1\.56 beyond 1\.5,")
row("adapt-a-grows-in-a-later-run", MORSE,
    ["fix n all nve", "run 0 post no", "variable k equal 1.1",
     "fix a all adapt 1 pair morse/spline a * * v_k", "run 0 post no"],
    r"fix adapt moved the cutoff of types 1 1 to 1\.43 beyond 1\.3,")
# reset no keeps a = 0.9 for the next run, whose lists are made for it: a back to 1 is past them
row("adapt-a-back-up-after-reset-no", MORSE,
    ["fix n all nve", "variable k equal 0.9", "fix a all adapt 1 pair morse/spline a * * v_k",
     "run 0 post no", "variable k equal 1.0", "run 0 post no"],
    r"fix adapt moved the cutoff of types 1 1 to 1\.3 beyond 1\.17,")
row("adapt-a-back-up-after-reset-yes", MORSE,
    ["fix n all nve", "variable k equal 0.9",
     "fix a all adapt 1 pair morse/spline a * * v_k reset yes", "run 0 post no",
     "variable k equal 1.0", "run 0 post no"], OK)
row("adapt-C", MORSE, ["variable k equal 5", "fix a all adapt 1 pair morse/spline C * * v_k"],
    r"C of types 1 1 is the law's stiffness, derived from its parameters")
for u, grown in [("metal", r"to 4\.0625 beyond 3\.25,"), ("si", r"to 1\.625e-05 beyond 1\.3e-05,")]:
    a = UNIT_SCENES[u][1]
    row(f"adapt-units-{u}-a-grows-past-list", unit_scene(u, "morse/spline"),
        [f"variable k equal {1.25 * a!r}", "fix n all nve",
         "fix a all adapt 1 pair morse/spline a * * v_k", "run 10 post no"],
        "fix adapt moved the cutoff of types 1 1 " + grown)
# the styles' extract() also hands their state objects to this package's fixes and computes:
# fix adapt must not write a number over them (it refuses the dimension; was a crash)
OBJECT = r"Pair style parameter {} is not compatible with fix adapt"
row("adapt-damping_pass", MORSE, ["variable k equal 1",
                                   "fix a all adapt 1 pair morse/spline damping_pass * * v_k"],
    OBJECT.format("damping_pass"), isolate=True)
row("adapt-pair_state", MORSE_LINK, ["variable k equal 1",
                                     "fix a all adapt 1 pair morse/spline pair_state * * v_k"],
    OBJECT.format("pair_state"), isolate=True)
row("adapt-a-shrinks", MORSE, ["variable k equal 1.0-step*0.01", "fix n all nve",
                               "fix a all adapt 1 pair morse/spline a * * v_k",
                               "run 10 post no"], OK)
row("adapt-kappa-ramp", MORSE, ["variable k equal 0.5+step*0.01", "fix n all nve",
                                "fix a all adapt 1 pair morse/spline kappa * * v_k",
                                "run 10 post no"], OK)

# ---------------------------------------------------------------- E. fix viscous/relative
V = "fix v all viscous/relative "
for rid, args, expect, defect in [
    ("no-args", "", r"expected fix ID group viscous/relative gamma G \| J J", None),
    ("gamma-nothing", "gamma", r"expected fix ID group viscous/relative", None),
    ("style-G", "G 1.0", r"unknown style 'G' \(expected gamma or J\)", None),
    ("gamma-abc", "gamma abc", r"gamma.*abc", None),
    ("gamma-nan", "gamma nan", r"gamma.*nan", None),
    ("gamma-inf", "gamma inf", r"gamma.*inf", None),
    ("gamma-1e309", "gamma 1e309", r"gamma.*1e309", None),
    ("gamma--0", "gamma -0", r"gamma must be > 0 \(got -0\)", None),
    ("gamma-0", "gamma 0", r"gamma must be > 0 \(got 0\)", None),
    ("J--1", "J -1", r"J must be > 0 \(got -1\)", None),
    ("mode-sideways", "gamma 1.0 mode sideways", r"unknown mode 'sideways'", None),
    ("mode-nothing", "gamma 1.0 mode", r"keyword mode needs a value", None),
    ("weight-bogus", "gamma 1.0 weight gauss", r"unknown weight 'gauss'", None),
    ("weight-twice", "gamma 1.0 weight dpd weight none", r"keyword weight given twice", None),
    ("mode-twice", "gamma 1.0 mode full mode normal", r"keyword mode given twice", None),
    ("cutoff-0", "gamma 1.0 cutoff 0", r"cutoff must be > 0 \(got 0\)", None),
    ("cutoff--1", "gamma 1.0 cutoff -1", r"cutoff must be > 0 \(got -1\)", None),
    ("cutoff-abc", "gamma 1.0 cutoff abc", r"cutoff.*abc", None),
    ("unknown-keyword", "gamma 1.0 foo 1", r"unknown keyword 'foo'", None),
    ("wrong-order", "mode normal gamma 1.0", r"unknown style 'mode'", None),
    ("extra-number", "gamma 1.0 2.0", r"unknown keyword '2.0'|extra argument '2.0'",
     None),
]:
    row(f"viscous-{rid}", MORSE, V + args, expect, defect)

row("viscous-cutoff-1e300", MORSE, V + "gamma 1.0 cutoff 1e300", r"ghost")
row("viscous-J-stock-pair", dimer(), ["pair_style lj/cut 1.5", "pair_coeff * * 1.0 1.0",
                                      V + "J 50"], r"J .*(stiffness|C\b)")
row("viscous-no-pair", dimer(), [V + "gamma 1.0"], r"viscous/relative.*pair style")
row("viscous-no-pair-cutoff", dimer(), [V + "gamma 1.0 cutoff 1.2"], r"ghost|cutoff")
row("viscous-empty-group", MORSE, ["group none empty", "fix v none viscous/relative gamma 1.0"],
    OK)
row("viscous-zero-atoms", BOX + pair("morse/spline"), [V + "J 50"], OK)
row("viscous-respa", dimer(), ["pair_style lj/cut 1.5", "pair_coeff * * 1.0 1.0",
                               "run_style respa 2 2", V + "gamma 1.0"],
    r"[Ff]ix viscous/relative.*respa")
row("viscous-J-tiny", MORSE, ["velocity all create 0.1 4711", "fix n all nve", V + "J 1e-300",
                              "timestep 0.001", "run 5 post no"],
    r"viscous/relative.*(J|G|time step|stab)", None,
    isolate=True)
row("viscous-gamma-huge", MORSE, ["velocity all create 0.1 4711", "fix n all nve",
                                  V + "gamma 1e300", "timestep 0.001", "run 5 post no"],
    r"viscous/relative: G x bonds x dt = 1e\+300", None, isolate=True)
row("viscous-J-huge", MORSE, ["velocity all create 0.1 4711", "fix n all nve", V + "J 1e300",
                              "run 5 post no"], OK)
row("viscous-normal-overlap", dimer(r=0.0), ["pair_style zero 1.5", "pair_coeff * *",
                                             "velocity all create 0.1 4711", "fix n all nve",
                                             V + "gamma 1.0 mode normal cutoff 1.2",
                                             "run 5 post no"], OK)
# LAMMPS: "it is an error to use pre no" after a change; the fix has no forces of the step
# before to kick with (was a crash: fd never allocated)
row("viscous-minimize-then-run-pre-no", MORSE,
    ["fix n all nve", V + "J 50", "minimize 0 1e-8 20 40", "run 10 pre no"],
    r"no damping forces of step \d+ for its second half kick: run \.\.\. pre no", isolate=True)
for u in UNIT_SCENES:
    row(f"viscous-units-{u}", unit_scene(u, "morse/spline"), ["fix n all nve", V + "J 50",
                                                              "run 3 post no"], OK)
row("viscous-fix_modify", MORSE, ["velocity all create 0.1 4711", "fix n all nve",
                                  V + "gamma 1.0", "fix_modify v energy yes virial yes",
                                  "run 5 post no"], OK)
row("viscous-omp", dimer(omp=True) + pair("morse/spline", omp=True),
    ["fix n all nve", V + "gamma 1.0 mode normal weight dpd", "run 3 post no"], OK)

# ---------------------------------------------------------------- F. fix descent/normalized
D = "fix d all descent/normalized "
for rid, args, expect, defect in [
    ("no-args", "", r"expected fix ID group descent/normalized h H", None),
    ("h-nothing", "h", r"expected fix ID group descent/normalized h H", None),
    ("H-uppercase", "H 0.1", r"expected fix ID group descent/normalized h H", None),
    ("h-abc", "h abc", r"\bh\b.*abc", None),
    ("h-nan", "h nan", r"\bh\b.*nan", None),
    ("h-inf", "h inf", r"\bh\b.*inf", None),
    ("h-1e309", "h 1e309", r"\bh\b.*1e309", None),
    ("h--0", "h -0", r"h must be > 0 \(got -0\)", None),
    ("h-0", "h 0", r"h must be > 0 \(got 0\)", None),
    ("decay-0", "h 0.1 decay 0", r"decay F must be in \(0,1\] \(got 0\)", None),
    ("decay-1.5", "h 0.1 decay 1.5", r"decay F must be in \(0,1\] \(got 1.5\)", None),
    ("decay-nan", "h 0.1 decay nan", r"decay.*nan", None),
    ("min--1", "h 0.1 min -1", r"min Hmin must be in \[0,h\] \(got -1\)", None),
    ("min-above-h", "h 0.1 min 1", r"min Hmin must be in \[0,h\] \(got 1\)", None),
    ("inertia-0", "h 0.1 inertia 0 0.5", r"inertia M must be >= 1 \(got 0\)", None),
    ("inertia-1001", "h 0.1 inertia 1001 0.5", r"inertia M must be an integer <= 1000", None),
    ("inertia-one-value", "h 0.1 inertia 3", r"keyword inertia needs 2 values", None),
    ("inertia-K-1", "h 0.1 inertia 3 1", r"inertia K must be in \[0,1\) \(got 1\)", None),
    ("inertia-K--0.1", "h 0.1 inertia 3 -0.1", r"inertia K must be in \[0,1\) \(got -0.1\)",
     None),
    ("inertia-K-nan", "h 0.1 inertia 3 nan", r"inertia K.*nan|K.*nan", None),
    ("decay-twice", "h 0.1 decay 0.9 decay 0.8", r"keyword decay given twice", None),
    ("unknown-keyword", "h 0.1 foo 1", r"unknown keyword 'foo'", None),
    ("wrong-order", "decay 0.9 h 0.1", r"expected fix ID group descent/normalized h H", None),
]:
    row(f"descent-{rid}", MORSE, D + args, expect, defect)

row("descent-h-1e308", MORSE, [D + "h 1e308", "run 2 post no"],
    r"h = 1e\+308 must be smaller than the box", isolate=True)    # known, fixed
row("descent-inertia-3.0", MORSE, [D + "h 0.01 inertia 3.0 0.5", "run 3 post no"], OK)
row("descent-h-tiny", MORSE, [D + "h 1e-300 decay 1e-300", "run 3 post no"], OK)
row("descent-with-nve", MORSE, ["fix n all nve", D + "h 0.01"], r"nve|descent/normalized.*n\b")
row("descent-empty-group", MORSE, ["group none empty", "fix d none descent/normalized h 0.01",
                                   "run 3 post no"], OK)
row("descent-zero-atoms", BOX + pair("morse/spline"), [D + "h 0.01", "run 3 post no"], OK)
row("descent-respa", dimer(), ["run_style respa 2 2", D + "h 0.01"],
    r"[Ff]ix descent/normalized.*(respa|verlet)")
row("descent-fix_modify", MORSE, [D + "h 0.01", "fix_modify d energy yes"],
    r"descent/normalized does not support fix_modify energy")
row("descent-minimize", MORSE, [D + "h 0.01", "minimize 0 0 10 100"], OK)
row("descent-no-pair", dimer(), [D + "h 0.01", "run 3 post no"], OK)
row("descent-overlap", dimer(r=0.0) + pair("morse/spline"), [D + "h 0.01"],
    r"atoms 1 and 2 are 0 apart")
row("descent-units-si", unit_scene("si", "morse/spline"), [D + "h 1e-8 decay 0.9 min 1e-12",
                                                           "run 3 post no"], OK)
row("descent-omp", dimer(omp=True) + pair("lj/spline", omp=True),
    [D + "h 0.01 inertia 2 0.5", "run 3 post no"], OK)

# ---------------------------------------------------------------- G. compute dust
CD = "compute c all dust "
USE = ["thermo_style custom step pe press c_c[1] c_c[6]", "thermo_modify norm no"]
for rid, args, expect, defect in [
    ("cutoff-nothing", "cutoff", r"keyword cutoff needs a value", None),
    ("cutoff-abc", "cutoff abc", r"cutoff.*abc", None),
    ("cutoff-nan", "cutoff nan", r"cutoff.*nan", None),
    ("cutoff-0", "cutoff 0", r"cutoff must be > 0 \(got 0\)", None),
    ("cutoff--1", "cutoff -1", r"cutoff must be > 0 \(got -1\)", None),
    ("maxsize-0", "maxsize 0", r"maxsize must be >= 1 \(got 0\)", None),
    ("maxsize--1", "maxsize -1", r"maxsize must be >= 1 \(got -1\)", None),
    ("maxsize-1.5", "maxsize 1.5", r"maxsize.*1\.5", None),
    ("rows-bogus", "rows some", r"rows must be all or dust \(got some\)", None),
    ("links-and-cutoff", "links cutoff 1.2", r"links and cutoff exclude each other", None),
    ("unknown-keyword", "cutof 1.2", r"unknown keyword 'cutof'", None),
    ("cutoff-twice", "cutoff 1.2 cutoff 1.3", r"keyword cutoff given twice", None),
    ("links-twice", "links links", r"keyword links given twice", None),
]:
    row(f"dust-{rid}", MORSE, CD + args, expect, defect)

row("dust-rows-twice", MORSE, CD + "rows all rows dust", r"keyword rows given twice")  # known
row("dust-cutoff-1e300", MORSE, [CD + "cutoff 1e300"] + USE, r"exceeds the ghost atom range")
row("dust-links-no-link", MORSE, [CD + "links"] + USE, r"links needs a pair style with link")
row("dust-no-pair", dimer(), [CD.strip()] + USE, r"without the cutoff keyword it needs a pair "
                                                 r"style")
row("dust-no-pair-cutoff", dimer(), [CD + "cutoff 1.2"] + USE, r"ghost|cutoff")
row("dust-empty-group", MORSE, ["group none empty", "compute c none dust"] + USE, OK)
row("dust-zero-atoms", BOX + pair("morse/spline"), [CD.strip()] + USE, OK)
row("dust-links", MORSE_LINK, [CD + "links maxsize 1 rows dust"] + USE, OK)
row("dust-units-si", unit_scene("si", "morse/spline"), [CD + "cutoff 1.2e-5"] + USE, OK)

# ---------------------------------------------------------------- H. compute links/atom
LUSE = ["compute n all reduce sum c_c", "thermo_style custom step pe press c_n",
        "thermo_modify norm no"]
row("links-extra-arg", MORSE_LINK, "compute c all links/atom 1",
    r"links/atom takes no arguments \(got 1\)")
row("links-no-pair", dimer(), ["compute c all links/atom"] + LUSE,
    r"links/atom needs a pair style with link L")
row("links-pair-without-link", MORSE, ["compute c all links/atom"] + LUSE,
    r"links/atom needs a pair style with link L")
row("links-stock-pair", dimer(), ["pair_style lj/cut 1.5", "pair_coeff * * 1.0 1.0",
                                  "compute c all links/atom"] + LUSE,
    r"links/atom needs a pair style with link L")
row("links-ok", MORSE_LINK, ["compute c all links/atom"] + LUSE, OK)
row("links-empty-group", MORSE_LINK, ["group none empty", "compute c none links/atom"] + LUSE,
    OK)
row("links-zero-atoms", BOX + pair("morse/spline", "cut 1.3 link 1.05"),
    ["compute c all links/atom"] + LUSE, OK)
row("links-omp", dimer(omp=True) + pair("morse/spline", "cut 1.3 link 1.1", omp=True),
    ["compute c all links/atom"] + LUSE, OK)

# ---------------------------------------------------------------- I. compute pair/params
CP = "compute c all pair/params "
PUSE = ["thermo_style custom step pe press c_c[1] c_c[14]", "thermo_modify norm no"]
for rid, args, expect, defect in [
    ("one-type", "1", r"expected compute ID group pair/params I J", None),
    ("type-0", "0 1", r"atom type 0 is out of range 1-2", None),
    ("type-ntypes+1", "1 3", r"atom type 3 is out of range 1-2", None),
    ("type-star", "* 1", r"[Tt]ype.*\*", None),
    ("type-range", "2*1 1", r"[Tt]ype.*2\*1", None),
    ("type-abc", "abc 1", r"[Tt]ype.*abc", None),
    ("type-float", "1.0 1", r"[Tt]ype.*1\.0", None),
    ("mass-0", "1 1 mass 0", r"mass must be > 0 \(got 0\)", None),
    ("mass--1", "1 1 mass -1", r"mass must be > 0 \(got -1\)", None),
    ("mass-nan", "1 1 mass nan", r"mass.*nan", None),
    ("mass-nothing", "1 1 mass", r"keyword mass needs a value", None),
    ("rc-0", "1 1 rc 0", r"rc must be > 0 \(got 0\)", None),
    ("rc-abc", "1 1 rc abc", r"\brc\b.*abc", None),
    ("lattice-hex", "1 1 lattice hex", r"unknown lattice 'hex'", None),
    ("u-nothing", "1 1 u", r"keyword u needs at least one speed \(got nothing\)", None),
    ("u-abc", "1 1 u abc", r"keyword u needs at least one speed \(got 'abc'\)", None),
    ("u-0", "1 1 u 0", r"loading speed u must be a finite number > 0 \(got 0\)", None),
    ("u--1", "1 1 u -1", r"loading speed u must be a finite number > 0 \(got -1\)", None),
    ("u-nan", "1 1 u nan", r"loading speed u must be a finite number > 0 \(got nan\)", None),
    ("u-inf", "1 1 u inf", r"loading speed u must be a finite number > 0 \(got inf\)", None),
    ("u-1e309", "1 1 u 1e309", r"finite number > 0 \(got 1e309\)", None),
    ("unknown-keyword", "1 1 lattic fcc", r"unknown keyword 'lattic'", None),
]:
    row(f"params-{rid}", MORSE, CP + args, expect, defect)

row("params-rc-0.5", MORSE, [CP + "1 1 rc 0.5"] + PUSE, r"rc must be > 1",
    None)
row("params-mass-twice", MORSE, CP + "1 1 mass 1 mass 2", r"keyword mass given twice",
    None)
row("params-u-twice", MORSE, CP + "1 1 u 1 u 2", r"keyword u given twice",
    None)
row("params-no-pair", dimer(), [CP + "1 1"] + PUSE, r"pair/params needs a pair style")
row("params-stock-lj", dimer(), ["pair_style lj/cut 2.5", "pair_coeff * * 1.0 1.0",
                                 CP + "1 1 lattice fcc u 0.5 1"] + PUSE, OK)
row("params-pair-zero", dimer(), ["pair_style zero 2.5", "pair_coeff * *", CP + "1 1"] + PUSE,
    r"pair/params.*(zero|no interaction|law|minimum|equilibrium)")
row("params-link", MORSE_LINK, [CP + "1 1"] + PUSE, OK)
row("params-harmonic-u-beyond-c0", dimer() + pair("harmonic/spline"), [CP + "1 1 u 1e6"] + PUSE,
    OK)
row("params-zero-atoms", BOX + pair("mie/spline"), [CP + "1 2 mass 2 rc 1.3 u 1"] + PUSE, OK)
row("params-units-metal", unit_scene("metal", "lj/spline"), [CP + "1 1 lattice fcc u 100"] +
    PUSE, OK)


# ---------------------------------------------------------------- J. pair_style mca, compute mca/atom

def mca_box(style="sphere", units="lj", zlo=-3.0, zhi=3.0):
    """Two touching elements of diameter 1 (types 1 and 2 exist, both atoms type 1)."""
    return [f"units {units}", f"atom_style {style}", "atom_modify map array",
            "comm_modify vel yes", f"region box block -3 3 -3 3 {zlo} {zhi}", "create_box 2 box",
            "create_atoms 1 single 0 0 0", "create_atoms 1 single 1.0 0 0",
            "thermo_modify norm no"] + (["set group all diameter 1.0"] if style == "sphere" else [])


MCA = mca_box()
MP = "pair_style mca fraction 0.6"
MC = "pair_coeff * * young 1.0 poisson 0.3"
for rid, cmds, expect in [
    ("mca-no-fraction", "pair_style mca", "fraction F is required"),
    ("mca-fraction-abc", "pair_style mca fraction abc", r"fraction must be a finite number"),
    ("mca-fraction-0", "pair_style mca fraction 0", r"fraction must be > 0"),
    ("mca-fraction-2", "pair_style mca fraction 2", r"must be in \[0\.05, 1\]"),
    ("mca-fraction-tiny", "pair_style mca fraction 1e-200", r"must be in \[0\.05, 1\] \(got 1e-200\)"),
    ("mca-fraction-missing", "pair_style mca fraction", "fraction needs a value"),
    ("mca-tolerance-neg", MP + " tolerance -0.1", r"tolerance must be in \[0, 1\)"),
    ("mca-tolerance-1", MP + " tolerance 1", r"tolerance must be in \[0, 1\)"),
    ("mca-manybody-maybe", MP + " manybody maybe", "manybody must be yes or no"),
    ("mca-keyword-twice", MP + " fraction 0.7", "keyword fraction given twice"),
    ("mca-unknown-keyword", MP + " cut 2", "unknown keyword 'cut'"),
    ("mca-coeff-nothing", [MP, "pair_coeff * *"], "give bulk K shear G, or young E poisson nu"),
    ("mca-coeff-I-ne-J", [MP, "pair_coeff 1 2 bulk 1 shear 1"], "a material belongs"),
    ("mca-coeff-type-0", [MP, "pair_coeff 0 0 bulk 1 shear 1"], "I must be an atom type"),
    ("mca-coeff-type-3", [MP, "pair_coeff 3 3 bulk 1 shear 1"], "I must be an atom type"),
    ("mca-coeff-bulk-abc", [MP, "pair_coeff * * bulk abc shear 1"],
     "bulk modulus K must be a finite number"),
    ("mca-coeff-shear-0", [MP, "pair_coeff * * bulk 1 shear 0"], "shear modulus G must be > 0"),
    ("mca-coeff-young-neg", [MP, "pair_coeff * * young -1 poisson 0.3"],
     "Young's modulus E must be > 0"),
    ("mca-coeff-nu-half", [MP, "pair_coeff * * young 1 poisson 0.5"],
     r"Poisson's ratio nu must lie in \(-1, 0.5\)"),
    ("mca-coeff-mixed-forms", [MP, "pair_coeff * * bulk 1 poisson 0.3"],
     "give bulk K shear G, or young E poisson nu"),
    ("mca-coeff-value-missing", [MP, "pair_coeff * * bulk 1 shear"], "shear needs a value"),
    ("mca-coeff-huge", [MP, "pair_coeff * * young 1e300 poisson 0.3"], "outside the range"),
    ("mca-coeff-strength-neg", [MP, "pair_coeff * * young 1 poisson 0.3 strength -1"],
     "strength must be > 0"),
    ("mca-ok-strength", [MP, "pair_coeff * * young 1 poisson 0.3 strength 0.01"], OK),
    ("mca-missing-type-2", [MP, "pair_coeff 1 1 bulk 1 shear 1"], "no material for atom type 2"),
    ("mca-radius-zero", ["set atom 1 diameter 0.0", MP, MC], "radius <= 0"),
    ("mca-coincident", ["set atom 2 x 0.0", MP, MC], "coincident"),
    ("mca-vel-no", ["comm_modify vel no", MP, MC], "comm_modify vel yes"),
    ("mca-shift", [MP, MC, "pair_modify shift yes"], "shift yes does not apply"),
    ("mca-compute-args", [MP, MC, "compute s all mca/atom 1"], "takes no arguments"),
    ("mca-compute-other-pair", ["pair_style zero 1.0", "pair_coeff * *",
                                "compute s all mca/atom"], "needs pair_style mca"),
    ("mca-ok", [MP, MC, "compute s all mca/atom", "compute m all reduce max c_s[8]",
                "thermo_style custom step pe press c_m"], OK),
    ("mca-ok-manybody-no", [MP + " manybody no", MC], OK),
    ("mca-ok-newton-off", ["newton off on", MP, MC], OK),
    ("mca-ok-negative-nu", [MP, "pair_coeff * * young 1 poisson -0.9"], OK),
]:
    row(rid, MCA, cmds, expect)
row("adapt-mca-pair_state", MCA, [MP, MC, "variable k equal 1",
                                  "fix a all adapt 1 pair mca pair_state * * v_k"],
    OBJECT.format("pair_state"), isolate=True)
row("mca-atomic-style", mca_box("atomic"), ["mass * 1.0", MP, MC], "requires atom_style sphere")
row("mca-empty-box", MCA[:5] + ["create_box 2 box", "thermo_modify norm no"], [MP, MC], OK)
row("mca-thin-periodic-box", mca_box(zlo=-0.5, zhi=0.5), [MP, MC], "periodic box is 1 wide")
row("mca-units-metal", mca_box(units="metal"), ["neighbor 0.2 bin", MP,
                                               "pair_coeff * * young 1e6 poisson 0.3"], OK)
row("mca-units-metal-default-skin", mca_box(units="metal"),
    [MP, "pair_coeff * * young 1e6 poisson 0.3"], "periodic box is 6 wide along x")


# ---------------------------------------------------------------- the test

def observe(setup, cmds):
    """('error', message, command) or ('ok', pe, press, {thermo keyword: value}) for one row,
    in this process."""
    with session() as lmp:
        lmp.commands_list(setup)
        for cmd in cmds + ["run 0 post no"]:
            try:
                lmp.command(cmd)
            except Exception as e:    # LAMMPS's error, as the library reports it
                lmp.command("variable alive equal 1")    # the instance still takes commands
                return ["error", str(e), cmd]
        return ["ok", lmp.get_thermo("pe"), lmp.get_thermo("press"), lmp.last_thermo()]


def observe_isolated(rid, timeout=120):
    """observe() of the row rid in a child process: a crash or a hang is an outcome too."""
    code = (f"import json, test_hostile_inputs as t; p = [r for r in t.ROWS if r.id == {rid!r}]"
            f"[0]; print('RESULT', json.dumps(t.observe(p.values[0], p.values[1])))")
    env = dict(os.environ)
    env.pop("LAMMPS_PLUGIN_PATH", None)
    try:
        out = subprocess.run([sys.executable, "-c", code], cwd=HERE, env=env,
                             capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return ["hang", timeout]
    for line in out.stdout.splitlines():
        if line.startswith("RESULT "):
            return json.loads(line[len("RESULT "):])
    return ["crash", out.returncode, (out.stdout + out.stderr)[-2000:]]


@pytest.mark.parametrize("setup,cmds,expect", ROWS)
def test_hostile_input(request, setup, cmds, expect):
    rid = request.node.callspec.id
    got = observe_isolated(rid) if rid in ISOLATE else observe(setup, cmds)
    if expect == OK:
        assert got[0] == "ok", got
        assert math.isfinite(got[1]) and math.isfinite(got[2]), got
        assert all(math.isfinite(v) for v in got[3].values()), got    # the computes' too
    else:
        assert got[0] == "error", got
        assert re.search(expect, got[1]), got


def test_enough_rows():
    assert len(ROWS) >= 150
    assert len({r.id for r in ROWS}) == len(ROWS)
