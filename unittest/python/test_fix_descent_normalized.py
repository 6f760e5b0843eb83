"""fix descent/normalized (Chernyshev's quasi-static iteration): each step moves an atom by
exactly h along its force, h decays to Hmin, the inertia term follows its recurrence and
survives restart, converged states equal LAMMPS's minimize on the same linked neighbour sets
(in three unit styles), a wall stops an atom where the forces balance, 1 and 2 ranks agree,
fix halt stops the iteration, bad input stops with an error naming the argument.  Oracles:
the force direction and h (closed form), an independent recurrence, stock minimize, the
stock wall's balance point, serial against MPI runs."""
import math

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp, session

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
