"""fix descent/normalized (Chernyshev's quasi-static iteration): each step moves an atom by
exactly h along its force, h decays to Hmin, the inertia term follows its recurrence and
survives restart, the velocity is the mean displacement / dt of the steps so far while the memory
fills, converged states equal LAMMPS's minimize on the same linked neighbour sets
(in three unit styles), a wall stops an atom where the forces balance, 1 and 2 ranks agree,
fix halt stops the iteration, bad input stops with an error naming the argument.  Oracles:
the force direction and h (closed form), an independent recurrence, stock minimize, the
stock wall's balance point, serial against MPI runs.  A restart read by a fix with other
inertia starts the memory afresh; the table of hostile input (conftest.InputTable)."""
import math
import re

import numpy as np
import pytest
from conftest import (OK, PLUGIN, SCENE_BOX, SCENE_EMPTY, SCENE_MORSE, SCENE_NOBOX, InputTable,
                      carried_totals, check_input, morse_fcc, run_lmp, scene_dimer, scene_pair,
                      scene_unit_dimer, session)

# the law of the paper (mie/spline n = 4k, m = 2k, k = 0.25) in three unit styles: D, a
UNITS = {"lj": (0.25, 1.0), "metal": (0.25, 2.0), "si": (2.5e-9, 1.0e-3)}


def two_atoms(lmp, units="lj", r=(1.1, 0.0, 0.0), fix="h 0.01"):
    """Atom 1 at the origin (moved by the fix), atom 2 at r a (held): a Mie k = 0.25 pair."""
    d, a = UNITS[units]
    lmp.commands_list([f"units {units}", "atom_modify map array",
                       f"region box block {-5 * a} {5 * a} {-5 * a} {5 * a} {-5 * a} {5 * a} units box",
                       "create_box 1 box", "mass 1 1.0", "create_atoms 1 single 0 0 0 units box",
                       "create_atoms 1 single {} {} {} units box".format(*(c * a for c in r)),
                       "pair_style mie/spline cut 1.5", f"pair_coeff * * {d} {a} 1 0.5",
                       f"neighbor {0.3 * a} bin", "group one id 1",
                       f"fix d one descent/normalized {fix}"])


def positions(lmp, n):
    x = lmp.numpy.extract_atom("x")[:n].copy()
    ids = lmp.numpy.extract_atom("id")[:n]
    return x[np.argsort(ids)]


@pytest.mark.parametrize("units", list(UNITS))
def test_each_step_is_h_along_the_force_and_h_decays_to_min(units):
    d, a = UNITS[units]
    h = 0.01 * a
    with session() as lmp:
        two_atoms(lmp, units, r=(0.66, 0.88, 0.0), fix=f"h {h} decay 0.5 min {h / 5}")
        lmp.command("run 0")
        f0 = lmp.numpy.extract_atom("f")[:2].copy()[0]
        assert np.linalg.norm(f0) > 0
        lmp.command("run 1")
        step = positions(lmp, 2)[0]
        assert step == pytest.approx(h * f0 / np.linalg.norm(f0), rel=1e-12, abs=1e-15 * a)
        assert lmp.extract_fix("d", 0, 1, 2) == pytest.approx(h, rel=1e-12)     # last displacement
        hs = [lmp.extract_fix("d", 0, 0)]
        for _ in range(3):
            lmp.command("run 1")
            hs.append(lmp.extract_fix("d", 0, 0))
        assert hs == pytest.approx([h / 2, h / 4, h / 5, h / 5], rel=1e-12)
        v = lmp.numpy.extract_atom("v")[:2]
        assert not v.any()


def test_vector_is_max_and_mean_force_of_the_group():
    with session() as lmp:
        two_atoms(lmp)
        lmp.commands_list(["create_atoms 1 single 3 3 3 units box", "group one id 1 3",
                           "unfix d", "fix d one descent/normalized h 0.01", "run 0"])
        lone = positions(lmp, 3)[2].copy()
        f = lmp.numpy.extract_atom("f")[:3]
        ids = lmp.numpy.extract_atom("id")[:3]
        fmag = np.linalg.norm(f[np.argsort(ids)][[0, 2]], axis=1)
        assert lmp.extract_fix("d", 0, 1, 0) == pytest.approx(fmag.max(), rel=1e-12)
        assert lmp.extract_fix("d", 0, 1, 1) == pytest.approx(fmag.mean(), rel=1e-12)
        lmp.command("run 5")
        assert (positions(lmp, 3)[2] == lone).all()     # no force: it stays


def inertia_recurrence(h, m, k, n):
    """Displacements along a constant force: d_j = h + K mean(d of the last min(j, M))."""
    d = []
    for _ in range(n):
        last = d[-m:]
        d.append(h + (k * sum(last) / len(last) if last else 0.0))
    return d


def test_inertia_adds_k_times_the_mean_of_the_last_m_displacements():
    h, m, k, n = 0.01, 3, 0.6, 12
    with session() as lmp:
        two_atoms(lmp, r=(4.0, 0.0, 0.0), fix=f"h {h} inertia {m} {k}")
        lmp.commands_list(["fix push one addforce 0.0 -2.0 0.0", "timestep 0.5", f"run {n}"])
        d = inertia_recurrence(h, m, k, n)
        x = positions(lmp, 2)[0]
        assert x[1] == pytest.approx(-sum(d), rel=1e-12) and x[0] == 0.0
        v = lmp.numpy.extract_atom("v")[:2]
        ids = lmp.numpy.extract_atom("id")[:2]
        assert v[list(ids).index(1), 1] == pytest.approx(-np.mean(d[-m:]) / 0.5, rel=1e-12)


@pytest.mark.parametrize("units", ["metal", "si"])
def test_velocity_is_the_mean_of_the_displacements_so_far_while_the_memory_fills(units):
    """With inertia M the velocity is the mean of the last min(j, M) displacements / dt: after
    the first step d_1 / dt (the memory holds one displacement), after the second
    (d_1 + d_2) / (2 dt), from the M-th on the mean of the last M.  Oracle: the recurrence of
    inertia_recurrence() along a constant force, in the style's length and time."""
    a = UNITS[units][1]
    h, m, k, dt = 0.01 * a, 3, 0.6, {"metal": 0.002, "si": 1.0e-9}[units]
    disp = inertia_recurrence(h, m, k, 6)
    with session() as lmp:
        two_atoms(lmp, units, r=(4.0, 0.0, 0.0), fix=f"h {h} inertia {m} {k}")
        lmp.commands_list(["fix push one addforce 0.0 -2.0 0.0", f"timestep {dt}", "run 0"])
        for j in range(1, 7):
            lmp.command("run 1")
            ids = list(lmp.numpy.extract_atom("id")[:2])
            v = lmp.numpy.extract_atom("v")[:2][ids.index(1)]
            expect = -np.mean(disp[max(0, j - m):j]) / dt
            assert v[1] == pytest.approx(expect, rel=1e-12), j
            assert v[0] == 0.0 and v[2] == 0.0
            assert positions(lmp, 2)[0][1] == pytest.approx(-sum(disp[:j]), rel=1e-12)


STRIP = """units {units}
dimension 2
boundary s s p
atom_style atomic
atom_modify map array
lattice hex {scale}
region box block 0 8 0 10 -0.5 0.5
create_box 1 box
create_atoms 1 box
mass 1 1.0
neighbor {skin} bin
pair_style mie/spline cut 1.3 link 1.05
pair_coeff 1 1 {d} {a} 1 0.5
region rtop block INF INF $(bound(all,ymax)-{tol}) INF INF INF units box
region rbot block INF INF INF $(bound(all,ymin)+{tol}) INF INF units box
group top region rtop
group bot region rbot
group clamp union top bot
group free subtract all clamp
fix e all enforce2d
fix s clamp setforce 0 0 0
run 0
displace_atoms top move {shift} {squeeze} 0 units box
"""


def strip(units, **kw):
    d, a = UNITS[units]
    scale = 2 / (math.sqrt(3) * a * a) if units == "lj" else a    # lj: a number density
    return STRIP.format(units=units, a=a, d=d, scale=scale, skin=0.3 * a, tol=0.1 * a, shift=0.05 * a,
                        squeeze=-0.15 * a, **kw)


def dump_sorted(name):
    return f"write_dump all custom {name} id x y modify sort id format float %.17g\n"


def read_dump(path):
    return np.loadtxt(path, skiprows=9)[:, 1:]


@pytest.mark.parametrize("units", list(UNITS))
def test_converged_state_is_minimize_on_the_same_links(tmp_path, units):
    d, a = UNITS[units]
    hmin = 1e-7 * a
    script = f"plugin load {PLUGIN}\n" + strip(units) + f"""
fix d free descent/normalized h {0.01 * a} decay 0.999 min {hmin}
thermo_style custom step f_d f_d[1]
thermo 5000
run 20000
{dump_sorted('descent.txt')}
unfix d
thermo_style custom step pe fmax
min_modify norm max
minimize 0 {1e-13 * d / a} 100000 1000000
{dump_sorted('minimize.txt')}"""
    run_lmp(tmp_path, script)
    x_descent, x_min = read_dump(tmp_path / "descent.txt"), read_dump(tmp_path / "minimize.txt")
    assert np.abs(x_descent - x_min).max() < 3 * hmin


def test_two_ranks_give_the_one_rank_iterations_and_equilibrium(tmp_path):
    """Iterations agree to round-off until a neighbour-list rebuild changes the order of the
    force sums; near equilibrium h F/|F| amplifies that round-off (|F| is small), so later
    iterates differ while both converge to one equilibrium (to 1e-6 a here, 100 Hmin: see the doc on accuracy)."""
    script = f"plugin load {PLUGIN}\n" + strip("lj") + """
fix d free descent/normalized h 0.01 decay 0.99 inertia 4 0.5
run 100
""" + dump_sorted("early_${np}.txt") + """
unfix d
fix d free descent/normalized h 0.01 decay 0.999 min 1e-8
run 20000
""" + dump_sorted("late_${np}.txt")
    run_lmp(tmp_path, script, args=["-var", "np", "1"])
    run_lmp(tmp_path, script, nprocs=2, args=["-var", "np", "2"])
    for name, tol in (("early", 1e-12), ("late", 1e-6)):
        assert read_dump(tmp_path / f"{name}_2.txt") == pytest.approx(
            read_dump(tmp_path / f"{name}_1.txt"), abs=tol)


def test_restart_continues_the_inertia_history(tmp_path):
    head = f"plugin load {PLUGIN}\n"
    fix = "fix d free descent/normalized h 0.01 inertia 5 0.7\n"
    run_lmp(tmp_path, head + strip("lj") + fix + "run 40\n" + dump_sorted("straight.txt"))
    run_lmp(tmp_path, head + strip("lj") + fix + "run 20\nwrite_restart mid.restart\n",
            nprocs=2)
    run_lmp(tmp_path, head + "read_restart mid.restart\nneighbor 0.3 bin\nfix e all enforce2d\n"
            "fix s clamp setforce 0 0 0\n" + fix + "run 20\n" + dump_sorted("resumed.txt"))
    assert read_dump(tmp_path / "resumed.txt") == pytest.approx(
        read_dump(tmp_path / "straight.txt"), abs=1e-12)


ITERATION = "fix d all descent/normalized h 0.01 decay 0.99 inertia 3 0.5\n"


@pytest.mark.parametrize("nprocs", [1, 2])
def test_step_length_carries_across_run_boundaries_and_restart_files(tmp_path, nprocs):
    """h, decayed over the iterations so far: run N + run M (with or without a setup between)
    ends at run N+M's h, and a restart file written between runs or during one (restart N),
    read by a fix with the same ID, goes on from the uninterrupted run's h at that step."""
    r = carried_totals(tmp_path, "\n".join(morse_fcc()) + "\n" + ITERATION, ["f_d"],
                       "neighbor 0.3 bin\n" + ITERATION, 50, 50, nprocs)
    assert 0.01 > r["straight_n"][0] > r["straight_nm"][0] > 0
    for name in ("split_nm", "boundary", "read_nm", "mid_nm", "resumed_nm"):
        assert r[name] == pytest.approx(r["straight_nm"], rel=1e-12), name
    for name in ("split_n", "read_n"):
        assert r[name] == pytest.approx(r["straight_n"], rel=1e-12), name


def test_wall_stops_the_atom_where_the_forces_balance():
    eps, cut, push, hmin = 5.0, 1.0, 2.0, 1e-8
    with session() as lmp:
        two_atoms(lmp, r=(4.0, 0.0, 0.0), fix=f"h 0.01 decay 0.995 min {hmin}")
        lmp.commands_list(["change_box all boundary p f p", "fix push one addforce 0.0 -2.0 0.0",
                           f"fix w one wall/harmonic ylo -1.0 {eps} 0.0 {cut}", "run 6000"])
        y = positions(lmp, 2)[0][1]
        # wall/harmonic: F = 2 eps (cut - (y - ylo)) balances the push
        assert y == pytest.approx(-1.0 + cut - push / (2 * eps), abs=2 * hmin)


def test_driven_end_with_fix_move_and_halt_on_residual_force(tmp_path):
    script = f"plugin load {PLUGIN}\n" + strip("lj") + """
fix d free descent/normalized h 0.005 decay 0.999 min 1e-9
fix m top move linear 0 -0.0001 0
variable fmax equal f_d[1]
run 100
unfix m
fix stop all halt 10 v_fmax < 1e-6 error continue
run 50000
print "halted $(step) $(v_fmax:%.6g)"
"""
    out = run_lmp(tmp_path, script)
    step, fmax = [l.split()[1:] for l in out.splitlines() if l.startswith("halted")][0]
    step, fmax = int(step), float(fmax)
    assert fmax < 1e-6 and 100 < step < 50100


BAD = [
    ("", "expected fix ID group descent/normalized h H"),
    ("step 0.1", "expected fix ID group descent/normalized h H"),
    ("h 0", "h must be > 0 \\(got 0\\)"),
    ("h -0.1", "h must be > 0"),
    ("h 0.1 decay 0", "decay F must be in \\(0,1\\] \\(got 0\\)"),
    ("h 0.1 decay 1.5", "decay F must be in \\(0,1\\]"),
    ("h 0.1 min 0.2", "min Hmin must be in \\[0,h\\] \\(got 0.2\\)"),
    ("h 0.1 inertia 0 0.5", "inertia M must be >= 1 \\(got 0\\)"),
    ("h 0.1 inertia 3 1.0", "inertia K must be in \\[0,1\\) \\(got 1.0\\)"),
    ("h 0.1 inertia 3", "keyword inertia needs 2 values"),
    ("h 0.1 decay", "keyword decay needs 1 value"),
    ("h 0.1 rate 2", "unknown keyword 'rate'"),
]


@pytest.mark.parametrize("args, message", BAD)
def test_bad_arguments(args, message):
    with session() as lmp:
        lmp.commands_list(["region box block -2 2 -2 2 -2 2", "create_box 1 box"])
        with pytest.raises(Exception, match=message):
            lmp.command(f"fix d all descent/normalized {args}")


@pytest.mark.parametrize("other", ["nve", "move linear 0 0 0"])
def test_a_second_time_integrator_on_the_same_atoms_is_an_error(other):
    with session() as lmp:
        two_atoms(lmp)
        lmp.command(f"fix n all {other}")
        with pytest.raises(Exception, match="Fix descent/normalized d and time integrator fix n"):
            lmp.command("run 1")


def printed(out):
    """The 'RESULT name value' lines a script printed, as floats."""
    return {m.group(1): float(m.group(2)) for m in re.finditer(r"^RESULT (\S+) (\S+)$", out, re.M)}


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("first,second", [("inertia 3 0.5", ""), ("", "inertia 3 0.5"),
                                          ("inertia 3 0.5", "inertia 5 0.5")])
def test_restart_read_by_a_fix_with_other_inertia(tmp_path, nprocs, first, second):
    setup = "\n".join([f"plugin load {PLUGIN}", *morse_fcc(), ""])
    run_lmp(tmp_path, setup + f"fix d all descent/normalized h 0.002 {first}\nrun 20\n"
            "write_restart d.restart\n", nprocs)
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\nread_restart d.restart\nneighbor 0.3 bin\n"
                  f"fix d all descent/normalized h 0.002 {second}\nrun 20\n"
                  'print "RESULT pe $(pe)"\n', nprocs, name="in.b")
    assert np.isfinite(printed(out)["pe"])


def test_inertia_with_timestep_0_is_an_error():
    with session() as lmp:
        lmp.commands_list(SCENE_EMPTY + ["create_atoms 1 single 0 0 0",
                                         "create_atoms 1 single 1.1 0 0",
                                         "pair_style morse/spline cut 1.3",
                                         "pair_coeff * * 1.0 6.0 1.0",
                                         "fix d all descent/normalized h 0.01 inertia 3 0.5",
                                         "timestep 0"])
        with pytest.raises(Exception, match="inertia needs a time step > 0 \\(got 0\\)"):
            lmp.command("run 1")


# ---------------------------------------------------------------- hostile input

INPUTS = InputTable()
row = INPUTS.row
row("nobox-fix-descent", SCENE_NOBOX, "fix d all descent/normalized h 0.1",
    "Fix descent/normalized command before simulation box is defined")
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
    row(f"descent-{rid}", SCENE_MORSE, D + args, expect, defect)

row("descent-h-1e308", SCENE_MORSE, [D + "h 1e308", "run 2 post no"],
    r"h = 1e\+308 must be smaller than the box", isolate=True)    # known, fixed
row("descent-inertia-3.0", SCENE_MORSE, [D + "h 0.01 inertia 3.0 0.5", "run 3 post no"], OK)
row("descent-h-tiny", SCENE_MORSE, [D + "h 1e-300 decay 1e-300", "run 3 post no"], OK)
row("descent-with-nve", SCENE_MORSE, ["fix n all nve", D + "h 0.01"], r"nve|descent/normalized.*n\b")
row("descent-empty-group", SCENE_MORSE, ["group none empty", "fix d none descent/normalized h 0.01",
                                         "run 3 post no"], OK)
row("descent-zero-atoms", SCENE_BOX + scene_pair("morse/spline"), [D + "h 0.01", "run 3 post no"], OK)
row("descent-respa", scene_dimer(), ["run_style respa 2 2", D + "h 0.01"],
    r"[Ff]ix descent/normalized.*(respa|verlet)")
row("descent-fix_modify", SCENE_MORSE, [D + "h 0.01", "fix_modify d energy yes"],
    r"descent/normalized does not support fix_modify energy")
row("descent-minimize", SCENE_MORSE, [D + "h 0.01", "minimize 0 0 10 100"], OK)
row("descent-no-pair", scene_dimer(), [D + "h 0.01", "run 3 post no"], OK)
row("descent-overlap", scene_dimer(r=0.0) + scene_pair("morse/spline"), [D + "h 0.01"],
    r"atoms 1 and 2 are 0 apart")
row("descent-units-si", scene_unit_dimer("si", "morse/spline"), [D + "h 1e-8 decay 0.9 min 1e-12",
                                                                 "run 3 post no"], OK)
row("descent-omp", scene_dimer(omp=True) + scene_pair("lj/spline", omp=True),
    [D + "h 0.01 inertia 2 0.5", "run 3 post no"], OK)
# in an empty box
for rid, cmds, message in [
    ("inertia-M-int-max", [D + "h 0.1 inertia 2147483647 0.5"],
     "inertia M must be an integer <= 1000 \\(got 2147483647\\)"),
    ("inertia-M-1e8", [D + "h 0.1 inertia 1e8 0.5"], "inertia M must be an integer <= 1000"),
    ("inertia-M-2.5", [D + "h 0.1 inertia 2.5 0.5"], "inertia M must be an integer"),
    ("decay-twice-empty-box", [D + "h 0.1 decay 0.5 decay 0.9"], "keyword decay given twice"),
    ("h-1e308-empty-box", ["pair_style morse/spline cut 1.2", "pair_coeff * * 1.0 6.0 1.0",
                           D + "h 1e308", "run 1"], "h = 1e\\+308 must be smaller than the box"),
]:
    row(f"descent-{rid}", SCENE_EMPTY, cmds, message)


@pytest.mark.parametrize("setup,cmds,expect,isolate", INPUTS.rows)
def test_hostile_input(setup, cmds, expect, isolate):
    check_input(setup, cmds, expect, isolate)
