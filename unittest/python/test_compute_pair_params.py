"""compute pair/params against the spec's closed forms (section 4) on the analytic path
(this package's styles) and the numeric path (stock styles through single()), the shock
table against an independent solution of the c(u) equation (section 5; exactly, with Pi'' in
closed form), each type pair of three types with its own law, cutoff and mass, bad input (and
the table of hostile input, conftest.InputTable)."""
import math

import numpy as np
import pytest
from conftest import (OK, SCENE_BOX, SCENE_LINKED, SCENE_MORSE, SCENE_NOBOX, InputTable,
                      check_input, scene_dimer, scene_pair, scene_unit_dimer, session)
from spec_laws import Law

NAMES = ["a", "b", "sigma", "D", "fstar", "C", "eps", "kstar", "kv", "k2", "Gamma", "omega0",
         "T0", "v0", "vd", "Bstar", "Rc", "ucr", "ucr1d", "vl", "vd0"]


def closed_form(law, m=1.0):
    """The spec's closed forms and definitions, from spec_laws (independent of the plugin)."""
    a, D, k = law.a, law.D, law.kappa
    if law.base == "morse":
        c, gamma = 2 * law.alpha ** 2 * D, 1.5 * law.alpha * a
        k2 = math.exp(law.alpha * k * a) / (2 - math.exp(-law.alpha * k * a))
    elif law.base == "harmonic":
        c, gamma, k2 = 2 * law.alpha ** 2 * D, 0.0, None
    else:
        n, mm = (12.0, 6.0) if law.base == "lj" else (law.n, law.m)
        c, gamma = n * mm * D / a ** 2, (n + mm + 3) / 2
        k2 = (n - mm) / (n * 2 ** -mm - mm * 2 ** -n) if k == 1 else None
    c *= k * k
    gamma *= k
    b = law.b()
    fstar = abs(law.f(b)) if b else None
    v = {"a": a, "D": D, "C": c, "kv": a * math.sqrt(c / (2 * D)), "Gamma": gamma,
         "omega0": math.sqrt(c / m), "v0": a * math.sqrt(c / m), "vd": math.sqrt(2 * D / m),
         "Bstar": 2 * math.sqrt(m * c)}
    if b:
        v.update(b=b, fstar=fstar, eps=b / a - 1, kstar=c * (b - a) / fstar)
    if k2:
        v["k2"] = k2
    return v


def params(pair_style, pair_coeff, extra="", mass=1.0, commands=()):
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 6 0 6 0 6", "create_box 1 box",
                           f"mass 1 {mass}", "neighbor 0.0 nsq", "atom_modify sort 0 0.0", f"pair_style {pair_style}",
                           f"pair_coeff 1 1 {pair_coeff}",
                           *commands, f"compute p all pair/params 1 1 {extra}",
                           "thermo_style custom step c_p[1]", "run 0 post no"])
        vec = dict(zip(NAMES, lmp.numpy.extract_compute("p", 0, 1)[:21].copy()))
        rows = int(extra.count(" ") and "u " in extra and len(extra.split("u ")[1].split()))
        arr = lmp.numpy.extract_compute("p", 0, 2).copy() if rows else None
    return vec, arr


def check(values, expected, rel, gamma_rel):
    for key, want in expected.items():
        tol = gamma_rel if key == "Gamma" else rel
        got = values[key]
        assert abs(got - want) <= tol * max(abs(want), 1e-300) + (1e-12 if want == 0 else 0), \
            (key, got, want)


ANALYTIC = [  # law, pair_style tail, mass
    (Law("lj", 1.0, 1.0), "cut 2.5", 1.0),
    (Law("lj", 1.3, 1.2), "wagner", 2.0),
    (Law("lj", 1.0, 1.0), "lagunov 1.6", 1.0),
    (Law("lj", 1.0, 1.0, kappa=0.5), "cut 2.5", 1.0),
    (Law("mie", 1.0, 1.0, n=9, m=6), "cut 2.5", 1.0),
    (Law("mie", 2.0, 1.0, n=20, m=7), "lagunov 1.5", 1.0),
    (Law("mie", 1.0, 1.0, n=8, m=4, kappa=1.3), "wagner", 1.0),
    (Law("morse", 1.0, 1.0, alpha=6.0), "cut 2.5", 1.0),
    (Law("morse", 2.46e-6, 1e-5, alpha=3.76e5), "cut 1.2", 2.338e-12),
    (Law("morse", 1.0, 1.0, alpha=3.0), "wagner", 1.0),
    (Law("morse", 1.0, 1.0, alpha=4.0, kappa=1.5), "lagunov 1.5", 1.0),
    (Law("harmonic", 1.0, 1.0, alpha=5.0), "cut 1.3", 1.0),
]


@pytest.mark.parametrize("law,tail,mass", ANALYTIC,
                         ids=[f"{l.base}-{t.split()[0]}-k{l.kappa}" for l, t, _ in ANALYTIC])
def test_analytic_path_equals_closed_forms(law, tail, mass):
    values, _ = params(f"{law.style()} {tail}", law.coeff(), mass=mass)
    expected = closed_form(law, mass)
    if "k2" in expected and (tail != "cut 2.5"):
        del expected["k2"]  # the tail ends before 2a
    check(values, expected, 1e-9, 1e-9)
    if law.base == "harmonic":
        assert math.isnan(values["b"])
    if tail != "cut 2.5":
        assert values["k2"] == math.inf


NUMERIC = [  # stock style, coeff, the same law
    ("morse 2.5", "1.0 6.0 1.0", Law("morse", 1.0, 1.0, alpha=6.0)),
    ("morse 2.5", "1.0 3.76 1.0", Law("morse", 1.0, 1.0, alpha=3.76)),
    ("lj/cut 2.5", f"1.0 {2 ** (-1 / 6)!r}", Law("lj", 1.0, 1.0)),
    ("mie/cut 2.5", f"1.0 {(6 / 9) ** (1 / 3)!r} 9 6", Law("mie", 1.0, 1.0, n=9, m=6)),
    ("mie/cut 2.5", f"1.0 {(7 / 20) ** (1 / 13)!r} 20 7", Law("mie", 1.0, 1.0, n=20, m=7)),
]


@pytest.mark.parametrize("pair_style,coeff,law", NUMERIC, ids=[n[0] + n[1] for n in NUMERIC])
def test_numeric_path_with_stock_styles(pair_style, coeff, law):
    values, _ = params(pair_style, coeff)
    check(values, closed_form(law), 1e-7, 1e-5)


@pytest.mark.parametrize("law,tail", [(Law("lj", 1.0, 1.0, kappa=0.7), ("wagner",)),
                                      (Law("morse", 1.0, 1.0, alpha=5.0, kappa=1.2),
                                       ("lagunov", 1.6, 1.3))])
def test_numeric_path_with_lepton_tails(law, tail):
    """pair_style lepton with the spec's expression: a law no stock style has.  (A Lagunov
    smoothing that starts at b moves the strongest attraction beyond b, so the numeric
    path, which finds b there, is tested with a start beyond b.)"""
    expr, cutoff = law.lepton(*tail)
    values, _ = params(f"lepton {cutoff!r}", f'"{expr}"')
    expected = closed_form(law)
    expected.pop("k2", None)
    check(values, expected, 1e-7, 1e-5)


def test_table_style_within_its_interpolation_error(tmp_path):
    table = tmp_path / "morse.table"
    law = Law("morse", 1.0, 1.0, alpha=6.0)
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 6 0 6 0 6", "create_box 1 box",
                           "mass 1 1.0", "pair_style morse/spline cut 2.5",
                           f"pair_coeff 1 1 {law.coeff()}",
                           f"pair_write 1 1 20000 r 0.1 2.5 {table} MORSE"])
    values, _ = params("table spline 20000", f"{table} MORSE 2.5")
    check(values, {k: v for k, v in closed_form(law).items() if k != "Gamma"}, 1e-5, 1e-3)
    assert values["Gamma"] == pytest.approx(9.0, rel=1e-3)


def test_cutoff_before_inflection_point():
    """Al clusters, Rc = 1.1 < b = 1.184: analytic b from the law; stock morse: NaN, warned."""
    law = Law("morse", 1.0, 1.0, alpha=3.76)
    ours, _ = params("morse/spline cut 1.1", law.coeff())
    check(ours, {k: v for k, v in closed_form(law).items() if k != "k2"}, 1e-9, 1e-9)
    stock, _ = params("morse 1.1", "1.0 3.76 1.0")
    assert math.isnan(stock["b"]) and math.isnan(stock["kstar"])
    assert stock["C"] == pytest.approx(ours["C"], rel=1e-7)


def test_dusting_criteria_and_lattice_speed():
    law = Law("morse", 2.46e-6, 1e-5, alpha=3.76e5)
    m = 2.338e-12
    values, _ = params(f"{law.style()} cut 1.2", law.coeff(), "lattice fcc", mass=m)
    c0 = 3.76 * math.sqrt(2 * 2.46e-6 / m)
    assert values["v0"] == pytest.approx(c0, rel=1e-12)
    assert values["v0"] == pytest.approx(5454, abs=1)  # the paper's c0
    assert values["vd"] == pytest.approx(1451, abs=1)
    assert values["Rc"] == pytest.approx(1.2, rel=1e-12)
    assert values["ucr"] == pytest.approx(1.35 * 0.2 * c0, rel=1e-12)
    assert values["ucr1d"] == pytest.approx(0.2 * c0 / (2 * math.sqrt(2)), rel=1e-12)
    assert values["vl"] == pytest.approx(1.10 * c0, rel=1e-12)
    assert values["T0"] == pytest.approx(2 * math.pi / values["omega0"], rel=1e-14)
    other, _ = params(f"{law.style()} cut 1.2", law.coeff(), "rc 1.3 mass 1e-12", mass=m)
    assert other["Rc"] == 1.3 and other["vd"] == pytest.approx(math.sqrt(2 * 2.46e-6 / 1e-12))


@pytest.mark.parametrize("tail", ["cut 1.3", "wagner", "lagunov 1.2", "cut 1.3 shift"])
@pytest.mark.parametrize("units", ["lj", "si"])
def test_vd_of_the_law_as_computed_and_of_the_base_law(units, tail):
    """vd0 (index 21) is the papers' sqrt(2 D / m) of the base law, whatever the tail; vd
    (index 15) is that of the law as the pair style computes it, the depth its energy shift
    leaves: sqrt(-2 E(a) / m), E the energy LAMMPS reports for a dimer at the distance a
    (pair_modify shift lowers the depth by |Pi(Rc)|; the smooth tails keep Pi(a)).  In lj and
    si units (mvv2e 1)."""
    shift = tail.endswith("shift")
    tail = tail.replace(" shift", "")
    law = Law("morse", 1.0, 1.0, alpha=3.76) if units == "lj" else \
        Law("morse", 2.46e-6, 1e-5, alpha=3.76e5)
    m = 1.0 if units == "lj" else 2.338e-12
    with session() as lmp:
        lmp.commands_list([f"units {units}", "boundary f f f", "atom_modify map array",
                           f"region box block 0 {6 * law.a} 0 {6 * law.a} 0 {6 * law.a} units box",
                           "create_box 1 box", f"mass 1 {m}",
                           f"create_atoms 1 single {law.a} {law.a} {law.a} units box",
                           f"create_atoms 1 single {2 * law.a} {law.a} {law.a} units box",
                           f"neighbor {0.1 * law.a} nsq", f"pair_style {law.style()} {tail}",
                           f"pair_coeff 1 1 {law.coeff()}", f"pair_modify shift {'yes' if shift else 'no'}",
                           "compute p all pair/params 1 1",
                           "thermo_style custom step pe c_p[1]", "thermo_modify norm no",
                           "run 0 post no"])
        vec = dict(zip(NAMES, lmp.numpy.extract_compute("p", 0, 1)[:21].copy()))
        energy = lmp.get_thermo("pe")
    assert vec["vd0"] == pytest.approx(math.sqrt(2 * law.D / m), rel=1e-12)
    assert vec["vd"] == pytest.approx(math.sqrt(-2 * energy / m), rel=1e-10)
    if shift:     # the depth less |Pi(1.3 a)| of the base law
        assert vec["vd"] == pytest.approx(vec["vd0"] * math.sqrt(1 + law.pi(1.3 * law.a) / law.D),
                                          rel=1e-10)
    else:
        assert vec["vd"] == pytest.approx(vec["vd0"], rel=1e-12)


@pytest.mark.parametrize("units", ["lj", "si"])
@pytest.mark.parametrize("itype,jtype", [(1, 2), (2, 1), (2, 3), (3, 2), (3, 3)])
@pytest.mark.parametrize("path", ["analytic", "numeric"])
def test_each_type_pair_reads_its_own_law_cutoff_and_mass(path, itype, jtype, units):
    """Three types (masses m, 1.5 m, 2.5 m), each type pair its own Morse D, alpha, a, kappa and
    cutoff (test_pair_spline_types: morse/spline cut 1.2 with per-pair rc; numeric path: stock
    morse with alpha kappa and each pair's cutoff): compute pair/params I J gives the closed forms
    of pair I,J's law with the mass of type I (omega0, v0, vd, B* differ between I J and J I),
    and Rc, u_cr and u_cr,1D from that pair's cutoff; exact on the analytic path."""
    from test_pair_spline_types import CASES, PAIRS, RC, UNITS, laws
    s, _, mass = UNITS[units]
    case = CASES[0]
    lines = case.ours(units) if path == "analytic" else case.stock(units)
    with session() as lmp:
        lmp.commands_list([f"units {units}", f"region box block 0 {6 * s!r} 0 {6 * s!r} 0 "
                           f"{6 * s!r} units box", "create_box 3 box", f"mass 1 {mass!r}",
                           f"mass 2 {1.5 * mass!r}", f"mass 3 {2.5 * mass!r}",
                           f"neighbor {0.3 * s!r} bin", *lines,
                           f"compute p all pair/params {itype} {jtype} lattice fcc",
                           "thermo_style custom step c_p[1]", "run 0 post no"])
        values = dict(zip(NAMES, lmp.numpy.extract_compute("p", 0, 1)[:21].copy()))
    k = PAIRS.index((min(itype, jtype), max(itype, jtype)))
    law = laws("morse", units)[PAIRS[k]]
    m = mass * [1.0, 1.5, 2.5][itype - 1]
    expected = closed_form(law, m)
    del expected["k2"]    # cut before 2 a: Pi(2a) = 0
    rc = RC[k] or 1.2
    v0 = expected["v0"]
    expected.update(Rc=rc, ucr=1.35 * (rc - 1) * v0, ucr1d=(rc - 1) * v0 / (2 * math.sqrt(2)),
                    T0=2 * math.pi / expected["omega0"], vl=1.10 * v0,
                    vd0=math.sqrt(2 * law.D / m))
    if path == "analytic":
        check(values, expected, 1e-12, 1e-12)
        assert values["k2"] == math.inf
    else:
        check(values, expected, 1e-7, 1e-5)


def test_numeric_k2_of_a_law_cut_before_2a_is_inf():
    """doc/compute_pair_params.rst: k2 = Pi(a)/Pi(2a) of the law as the pair style computes it,
    inf when Pi(2a) = 0; stock morse cut at 1.2 a computes 0 at 2 a, as morse/spline cut 1.2
    (the numeric path read single() at 2 a beyond the cutoff, the uncut law's 202, until
    28 Nov 2026)."""
    ours, _ = params("morse/spline cut 1.2", "1.0 6.0 1.0")
    assert ours["k2"] == math.inf
    stock, _ = params("morse 1.2", "1.0 6.0 1.0")
    assert stock["k2"] == math.inf


def test_stock_style_vd0_is_its_vd():
    values, _ = params("morse 2.5", "1.0 6.0 1.0", commands=["pair_modify shift yes"])
    assert values["vd0"] == values["vd"]


def solve_y(law, u, c0):
    """y + (u/c0)/sqrt(Pi''(ya)/Pi''(a)) = 1 by bisection, Pi'' from the spec's force."""
    def pi2(r, h=1e-6):
        return -(law.f(r + h * law.a) - law.f(r - h * law.a)) / (2 * h * law.a)
    c = pi2(law.a)
    g = lambda y: y + (u / c0) / math.sqrt(pi2(y * law.a) / c) - 1
    lo, hi = 0.2, 1.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


@pytest.mark.parametrize("style", ["morse/spline cut 1.2", "morse 1.2e-5"])
def test_shock_table_solves_the_c_of_u_equation(style):
    law = Law("morse", 2.46e-6, 1e-5, alpha=3.76e5)
    m, speeds = 2.338e-12, [1000.0, 4000.0, 10000.0]
    coeff = law.coeff() if "spline" in style else "2.46e-6 3.76e5 1e-5 1.2e-5"
    values, table = params(style, coeff, "u " + " ".join(map(str, speeds)), mass=m)
    c0 = values["v0"]
    for row, u in zip(table, speeds):
        y = solve_y(law, u, c0)
        assert row[0] == u
        assert row[1] == pytest.approx(y, rel=1e-7)
        assert row[3] == pytest.approx(u / (1 - y), rel=1e-6)  # y = (c - u)/c
        assert row[2] * c0 == pytest.approx(row[3], rel=1e-12)
        assert row[4] == pytest.approx(math.pi * law.a / row[3], rel=1e-12)
        assert row[5] == pytest.approx(row[4] / 20, rel=1e-12)
    assert table[1][1] == pytest.approx(0.76, abs=0.005)  # the spec: u = 4 km/s gives y = 0.76


def exact_pi2(law, r):
    """Pi''(r) of the kappa-modified law in closed form."""
    x = law.s(r)
    if law.base == "morse":
        e = math.exp(-law.alpha * (x - law.a))
        base = 2 * law.alpha ** 2 * law.D * (2 * e * e - e)
    else:
        n, m = (12.0, 6.0) if law.base == "lj" else (law.n, law.m)
        q = law.a / x
        base = law.D * n * m / ((n - m) * law.a ** 2) * ((n + 1) * q ** (n + 2) -
                                                         (m + 1) * q ** (m + 2))
    return law.kappa ** 2 * base


@pytest.mark.parametrize("law,mass", [
    (Law("morse", 2.46e-6, 1e-5, alpha=3.76e5), 2.338e-12),
    (Law("morse", 1.3, 1.1, alpha=5.0, kappa=1.2), 2.0),
    (Law("lj", 1.0, 1.0, kappa=0.8), 1.0),
    (Law("mie", 1.3, 1.0, n=9, m=6, kappa=1.2), 1.5)], ids=["al", "morse-kappa", "lj", "mie"])
def test_shock_table_is_exact_on_the_analytic_path(law, mass):
    """The spline styles' analytic Pi'': y of y + (u/c0)/sqrt(Pi''(ya)/Pi''(a)) = 1 solved here
    by bisection to the last bit with Pi'' in closed form, c(u) = u/(1 - y), T_min = pi a/c(u)
    and the step T_min/20, to 1e-12 (the finite-difference check above holds 1e-7) at 0.1, 0.5
    and 1.2 c0."""
    values, _ = params(f"{law.style()} cut 1.3", law.coeff(), mass=mass)
    c0 = values["v0"]
    assert c0 == pytest.approx(law.a * math.sqrt(exact_pi2(law, law.a) / mass), rel=1e-14)
    speeds = [0.1 * c0, 0.5 * c0, 1.2 * c0]
    _, table = params(f"{law.style()} cut 1.3", law.coeff(),
                      "u " + " ".join(repr(u) for u in speeds), mass=mass)
    c = exact_pi2(law, law.a)
    for row, u in zip(table, speeds):
        g = lambda y: y + (u / c0) / math.sqrt(exact_pi2(law, y * law.a) / c) - 1
        lo, hi = 0.3, 1.0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if g(mid) < 0 else (lo, mid)
        y = 0.5 * (lo + hi)
        cu = u / (1 - y)
        assert row[0] == u
        assert row[1] == pytest.approx(y, rel=1e-13)
        assert row[2] == pytest.approx(cu / c0, rel=1e-12)
        assert row[3] == pytest.approx(cu, rel=1e-12)
        assert row[4] == pytest.approx(math.pi * law.a / cu, rel=1e-12)
        assert row[5] == pytest.approx(math.pi * law.a / cu / 20, rel=1e-12)


def test_harmonic_shock_table_is_linear():
    values, table = params("harmonic/spline cut 1.2", "1.0 5.0 1.0 ", "u 0.5 2.0")
    c0 = values["v0"]
    assert table[0][1] == pytest.approx(1 - 0.5 / c0, rel=1e-12)
    assert table[0][2] == pytest.approx(1.0, rel=1e-12)


def test_harmonic_shock_table_at_or_above_c0_is_a_nan_row():
    """No steady compression when u >= c0 for the harmonic well: the whole row after u is NaN
    (it was y NaN but a finite c(u), T_min and time step, which a script would have used)."""
    values, table = params("harmonic/spline cut 1.2", "1.0 5.0 1.0 ", "u 0.5 20.0")
    assert 20.0 >= values["v0"]
    assert table[1][0] == 20.0 and np.all(np.isnan(table[1][1:]))
    assert np.all(np.isfinite(table[0]))


BAD = [
    ("pair/params 1", "expected compute ID group pair/params I J"),
    ("pair/params 1 3", "atom type 3 is out of range 1-1"),
    ("pair/params 0 1", "atom type 0 is out of range"),
    ("pair/params 1 1 lattice hcp", "unknown lattice 'hcp'"),
    ("pair/params 1 1 u -5", "loading speed u must be a finite number > 0 \\(got -5\\)"),
    ("pair/params 1 1 u nan", "loading speed u must be a finite number > 0 \\(got nan\\)"),
    ("pair/params 1 1 u 1 inf", "loading speed u must be a finite number > 0 \\(got inf\\)"),
    ("pair/params 1 1 u", "keyword u needs at least one speed \\(got nothing\\)"),
    ("pair/params 1 1 u junk", "keyword u needs at least one speed \\(got 'junk'\\)"),
    ("pair/params 1 1 u 1 2 junk", "unknown keyword 'junk'"),
    ("pair/params 1 1 mass", "keyword mass needs a value"),
    ("pair/params 1 1 mass 0", "mass must be > 0"),
    ("pair/params 1 1 rc -1", "rc must be > 0"),
    ("pair/params 1 1 speed 3", "unknown keyword 'speed'"),
]


@pytest.mark.parametrize("args,message", BAD)
def test_bad_arguments(args, message):
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 6 0 6 0 6", "create_box 1 box"])
        with pytest.raises(Exception, match=message):
            lmp.command(f"compute p all {args}")


@pytest.mark.parametrize("pair,message", [
    ("pair_style zero 2.0\npair_coeff * *", "no minimum of the law"),
    ("pair_style soft 2.0\npair_coeff * * 1.0", "no minimum of the law"),
    ("pair_style none", "needs a pair style"),
])
def test_laws_without_parameters(pair, message):
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 6 0 6 0 6", "create_box 1 box",
                           "mass 1 1.0", *pair.split("\n"), "compute p all pair/params 1 1",
                           "thermo_style custom step c_p[1]"])
        with pytest.raises(Exception, match=message):
            lmp.command("run 0")


# ---------------------------------------------------------------- hostile input

INPUTS = InputTable()
row = INPUTS.row
row("nobox-compute-params", SCENE_NOBOX, "compute p all pair/params 1 1", r"box")
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
    row(f"params-{rid}", SCENE_MORSE, CP + args, expect, defect)

row("params-rc-0.5", SCENE_MORSE, [CP + "1 1 rc 0.5"] + PUSE, r"rc must be > 1",
    None)
row("params-mass-twice", SCENE_MORSE, CP + "1 1 mass 1 mass 2", r"keyword mass given twice",
    None)
row("params-u-twice", SCENE_MORSE, CP + "1 1 u 1 u 2", r"keyword u given twice",
    None)
row("params-no-pair", scene_dimer(), [CP + "1 1"] + PUSE, r"pair/params needs a pair style")
row("params-stock-lj", scene_dimer(), ["pair_style lj/cut 2.5", "pair_coeff * * 1.0 1.0",
                                       CP + "1 1 lattice fcc u 0.5 1"] + PUSE, OK)
row("params-pair-zero", scene_dimer(), ["pair_style zero 2.5", "pair_coeff * *", CP + "1 1"] + PUSE,
    r"pair/params.*(zero|no interaction|law|minimum|equilibrium)")
row("params-link", SCENE_LINKED, [CP + "1 1"] + PUSE, OK)
row("params-harmonic-u-beyond-c0", scene_dimer() + scene_pair("harmonic/spline"),
    [CP + "1 1 u 1e6"] + PUSE, OK)
row("params-zero-atoms", SCENE_BOX + scene_pair("mie/spline"),
    [CP + "1 2 mass 2 rc 1.3 u 1"] + PUSE, OK)
row("params-units-metal", scene_unit_dimer("metal", "lj/spline"), [CP + "1 1 lattice fcc u 100"] +
    PUSE, OK)

row("run-hybrid-pair-params", scene_dimer(), [
    "pair_style hybrid/overlay lj/cut 1.5 morse/spline cut 1.3 link 1.1",
    "pair_coeff * * lj/cut 0.1 1.0", "pair_coeff * * morse/spline 1.0 6.0 1.0",
    "compute c all pair/params 1 1"], r"pair style hybrid/overlay has no single\(\)")


@pytest.mark.parametrize("setup,cmds,expect,isolate", INPUTS.rows)
def test_hostile_input(setup, cmds, expect, isolate):
    check_input(setup, cmds, expect, isolate)
