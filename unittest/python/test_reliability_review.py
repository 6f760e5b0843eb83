"""The rest of the reliability review (issue 25): crashes, non-finite output, wrong results,
silently accepted and unclear input, one test each, table-driven where the case is an input
and its clear error.  Oracles: closed forms (free flight: no force, no damping), the same
scene without the keyword, LAMMPS's own errors."""
import re

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp, session


def results(out):
    return {m.group(1): float(m.group(2)) for m in re.finditer(r"^RESULT (\S+) (\S+)$", out, re.M)}


# 1. fix descent/normalized: a restart written with inertia, read by a fix without it

@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("first,second", [("inertia 3 0.5", ""), ("", "inertia 3 0.5"),
                                          ("inertia 3 0.5", "inertia 5 0.5")])
def test_descent_restart_read_by_a_fix_with_other_inertia(tmp_path, nprocs, first, second):
    setup = f"""plugin load {PLUGIN}
units lj
atom_modify map array
lattice fcc 1.41421356
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
mass 1 1.0
displace_atoms all random 0.05 0.05 0.05 4711 units box
pair_style morse/spline cut 1.3
pair_coeff * * 1.0 6.0 1.0
neighbor 0.3 bin
"""
    run_lmp(tmp_path, setup + f"fix d all descent/normalized h 0.002 {first}\nrun 20\n"
            "write_restart d.restart\n", nprocs)
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\nread_restart d.restart\nneighbor 0.3 bin\n"
                  f"fix d all descent/normalized h 0.002 {second}\nrun 20\n"
                  'print "RESULT pe $(pe)"\n', nprocs, name="in.b")
    assert np.isfinite(results(out)["pe"])


# 2-4, 9: bad input is a clear error naming the argument (the host survives each)

BAD = [
    ("fix d all descent/normalized h 0.1 inertia 2147483647 0.5",
     "inertia M must be an integer <= 1000 \\(got 2147483647\\)"),
    ("fix d all descent/normalized h 0.1 inertia 1e8 0.5", "inertia M must be an integer <= 1000"),
    ("fix d all descent/normalized h 0.1 inertia 2.5 0.5", "inertia M must be an integer"),
    ("pair_style morse/spline cut 1.3\npair_coeff * * 1.0 6.75 1.0 kappa 1e300",
     "law of types 1 1 with kappa 1e\\+300 overflows at r = 0.5 a"),
    ("pair_style harmonic/spline cut 1.3\npair_coeff * * 1.0 6.75 1.0 kappa 1e300",
     "law of types 1 1 with kappa 1e\\+300 overflows"),
    ("pair_style morse/spline cut 1.3\npair_coeff * * 1.0 6.75 1.0 kappa 200",
     "law of types 1 1 with kappa 200 overflows at r = 0.5 a \\(alpha a must"),
    ("pair_style lj/spline cut 1.3\npair_coeff * * 1.0 1.0 kappa 1e300",
     "with kappa 1e\\+300 overflows"),
    ("compute d all dust foo", "unknown keyword 'foo'"),
    # 8. a keyword given twice: the last value would win silently
    ("pair_style morse/spline cut 1.2 link 1.05 link 1.1", "Pair style morse/spline: keyword link given twice"),
    ("pair_style morse/spline cut 1.2 link 1.05 relink yes relink no", "keyword relink given twice"),
    ("pair_style morse/spline cut 1.2 chain 2 chain 3", "keyword chain given twice"),
    ("pair_style morse/spline cut 1.2\npair_coeff * * 1.0 6.0 1.0 kappa 1.1 kappa 1.2",
     "Pair morse/spline pair_coeff: keyword kappa given twice"),
    ("compute d all dust rows dust rows all", "Compute dust: keyword rows given twice"),
    ("compute d all dust links links", "Compute dust: keyword links given twice"),
    ("fix v all viscous/relative gamma 1.0 mode normal mode full", "keyword mode given twice"),
    ("fix d all descent/normalized h 0.1 decay 0.5 decay 0.9", "keyword decay given twice"),
    # 10. the link state's fix IDs are reserved
    ("fix NEIGH_HISTORY_LINK all nve\npair_style morse/spline cut 1.2 link 1.05",
     "Pair style morse/spline: fix ID NEIGH_HISTORY_LINK is reserved for the link state"),
    ("pair_style morse/spline cut 1.2 link 1.05\npair_coeff * * 1.0 6.0 1.0\n"
     "fix NEIGH_HISTORY_LINK all nve\nrun 0", "fix ID NEIGH_HISTORY_LINK is reserved"),
    ("fix NEIGH_HISTORY_LINK_DUMMY all nve\npair_style morse/spline cut 1.2 link 1.05",
     "fix ID NEIGH_HISTORY_LINK_DUMMY is reserved"),
    # 12. cutoffs and steps that LAMMPS cannot bin or integrate: bounded, named
    ("pair_style morse/spline cut 1e300", "Pair style morse/spline cut: Rc must be <= 100 in units"),
    ("pair_style morse/spline lagunov 1e300", "lagunov: Rc must be > 1 and <= 100"),
    ("pair_style morse/spline cut 1.2\npair_coeff * * 1.0 6.0 1.0 rc 1e300",
     "rc must be > 1 and <= 100 in units of a \\(got 1e300\\)"),
    ("pair_style morse/spline cut 1.2\npair_coeff * * 1.0 6.0 1.0\n"
     "fix d all descent/normalized h 1e308\nrun 1", "h = 1e\\+308 must be smaller than the box"),
    # 7. the styles that are not for rRESPA refuse it
    ("pair_style morse/spline cut 1.2\npair_coeff * * 1.0 6.0 1.0\nrun_style respa 2 2\nrun 1",
     "Pair morse/spline is not for run_style respa"),
    ("pair_style morse/spline cut 1.2\npair_coeff * * 1.0 6.0 1.0\n"
     "fix d all descent/normalized h 0.01\nrun_style respa 2 2\nrun 1",
     "Pair morse/spline is not for run_style respa"),
]


@pytest.mark.parametrize("commands,message", BAD)
def test_bad_input_is_a_clear_error(commands, message):
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block -2 2 -2 2 -2 2", "create_box 1 box",
                           "mass 1 1.0"])
        *first, last = commands.split("\n")
        lmp.commands_list(first)
        with pytest.raises(Exception, match=message):
            lmp.command(last)
        lmp.command("variable alive equal 1")    # the instance still takes commands


def test_kappa_within_the_bound_keeps_finite_energies():
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block -2 2 -2 2 -2 2", "create_box 1 box",
                           "mass 1 1.0", "create_atoms 1 single 0 0 0",
                           "create_atoms 1 single 0.5 0 0", "pair_style morse/spline cut 1.3",
                           "pair_coeff * * 1.0 6.75 1.0 kappa 100", "run 0"])
        assert np.isfinite(lmp.get_thermo("pe")) and lmp.get_thermo("pe") > 0


def test_descent_with_inertia_and_timestep_0_is_an_error():
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block -2 2 -2 2 -2 2", "create_box 1 box",
                           "mass 1 1.0", "create_atoms 1 single 0 0 0",
                           "create_atoms 1 single 1.1 0 0", "pair_style morse/spline cut 1.3",
                           "pair_coeff * * 1.0 6.0 1.0",
                           "fix d all descent/normalized h 0.01 inertia 3 0.5", "timestep 0"])
        with pytest.raises(Exception, match="inertia needs a time step > 0 \\(got 0\\)"):
            lmp.command("run 1")


# 5. fix viscous/relative damps exactly the pairs the pair style holds bonded

UNITS = {"lj": (1.0, 1.0, 1.0, 0.001), "metal": (0.3429, 2.866, 26.98, 0.0005)}    # D, a, m, dt


def dimer_ke(style, r, v, units="lj", steps=40, damp="gamma 5.0"):
    """ke after `steps` of two atoms r a apart moving with -v and +v (a per time unit) along
    their axis, Morse alpha a = 6 in the given unit style."""
    d, a, m, dt = UNITS[units]
    rate = float(damp.split()[1]) / (1.0 if units == "lj" else 0.1)    # G per time unit
    with session() as lmp:
        lmp.commands_list([f"units {units}",
                           f"region box block {-5 * a} {5 * a} {-5 * a} {5 * a} {-5 * a} {5 * a} units box",
                           "create_box 1 box", f"mass 1 {m}", "create_atoms 1 single 0 0 0 units box",
                           f"create_atoms 1 single {r * a} 0 0 units box", f"pair_style {style}",
                           f"pair_coeff * * {d} {6.0 / a} {a}", f"neighbor {0.3 * a} bin",
                           "group one id 1", "group two id 2",
                           f"velocity one set {-v * a} 0 0 units box",
                           f"velocity two set {v * a} 0 0 units box",
                           "fix 1 all nve", f"fix 2 all viscous/relative gamma {rate}",
                           f"timestep {dt}", "thermo_modify norm no", "run 0"])
        ke0 = lmp.get_thermo("ke")
        lmp.command(f"run {steps}")
        return ke0, lmp.get_thermo("ke"), lmp.get_thermo("pe")


@pytest.mark.parametrize("units", list(UNITS))
def test_viscous_relative_leaves_unlinked_pairs_alone(units):
    # 1.2 a apart: beyond L a = 1.05 a (never linked), inside Rc a = 1.3 a; moving apart
    ke0, ke, pe = dimer_ke("morse/spline cut 1.3 link 1.05", 1.2, 0.1, units)
    assert pe == 0 and ke == ke0    # no force, no damping: free flight
    ke0_d, ke_d, pe_d = dimer_ke("morse/spline cut 1.3", 1.2, 0.1, units)
    assert pe_d < 0 and ke_d != ke0_d    # by distance the same pair is bonded: it interacts


@pytest.mark.parametrize("units", list(UNITS))
def test_viscous_relative_damps_linked_pairs_as_distance_bonds(units):
    a = dimer_ke("morse/spline cut 1.3 link 1.05", 1.0, 0.05, units)
    b = dimer_ke("morse/spline cut 1.3", 1.0, 0.05, units)
    assert a[1] < 0.9 * a[0] and a[1] == pytest.approx(b[1], rel=1e-12)


def test_viscous_relative_cutoff_does_not_apply_under_link():
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block -5 5 -5 5 -5 5", "create_box 1 box",
                           "mass 1 1.0", "create_atoms 1 single 0 0 0",
                           "pair_style morse/spline cut 1.3 link 1.05", "pair_coeff * * 1.0 6.0 1.0",
                           "fix 2 all viscous/relative gamma 1.0 cutoff 1.2"])
        with pytest.raises(Exception, match="keyword cutoff does not apply under a pair style "
                                            "with link L"):
            lmp.command("run 0")


# 11. replicate with links: LAMMPS's own check refuses every fix with per-atom arrays before
# any style can speak; doc/pair_spline.rst says what to do (replicate, then link)

def test_replicate_with_links_is_refused_and_replicate_before_linking_works():
    with session() as lmp:
        lmp.commands_list(["units lj", "lattice fcc 1.41421356", "region box block 0 2 0 2 0 2",
                           "create_box 1 box", "create_atoms 1 box", "mass 1 1.0",
                           "pair_style morse/spline cut 1.2 link 1.05",
                           "pair_coeff * * 1.0 6.0 1.0", "neighbor 0.2 bin", "run 0"])
        with pytest.raises(Exception, match="Cannot replicate with fixes that store per-atom"):
            lmp.command("replicate 2 1 1")
    with session() as lmp:
        lmp.commands_list(["units lj", "lattice fcc 1.41421356", "region box block 0 2 0 2 0 2",
                           "create_box 1 box", "create_atoms 1 box", "mass 1 1.0",
                           "replicate 2 1 1", "pair_style morse/spline cut 1.2 link 1.05",
                           "pair_coeff * * 1.0 6.0 1.0", "neighbor 0.2 bin",
                           "compute l all links/atom", "compute ls all reduce sum c_l", "run 0"])
        assert lmp.extract_compute("ls", 0, 0) == 12 * 64


# 6. dump local with a wildcard: LAMMPS expands c_ID[*] of a compute that has per-atom and
# local outputs to its per-atom columns (3); the doc says to name the 10 local columns

def test_dump_local_names_the_ten_local_columns(tmp_path):
    cols = " ".join(f"c_d[{k}]" for k in range(1, 11))
    script = f"""plugin load {PLUGIN}
units lj
lattice fcc 1.41421356
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
mass 1 1.0
pair_style morse/spline cut 1.2
pair_coeff * * 1.0 6.0 1.0
compute d all dust
dump rows all local 1 rows.txt {cols}
dump wild all local 1 wild.txt c_d[*]
run 0
"""
    run_lmp(tmp_path, script)
    rows = np.loadtxt(tmp_path / "rows.txt", skiprows=9, ndmin=2)
    wild = np.loadtxt(tmp_path / "wild.txt", skiprows=9, ndmin=2)
    assert rows.shape == (1, 10) and rows[0, 1] == 108    # one fragment of all 108 atoms
    assert wild.shape == (1, 3)    # LAMMPS's expansion, documented
