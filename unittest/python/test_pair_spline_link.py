"""Linked pairs (pair_style ... link L [relink yes]): a link breaks exactly at Rc a and never
attracts again, unlinked pairs only repel (the law's branch r < a, zero at a), the state
follows atoms across 1/2/4 ranks, /omp and newton off, survives restart, and the energy of the
breaks closes the balance.  Oracles: the Morse closed form, compute coord/atom (stock) for the
links made, serial against MPI runs, the nearest-neighbour chain (chain 1).  The table of
hostile input (conftest.InputTable) of link L: its keywords, the link state under the commands
around it (unfix, replaced pair styles, hybrid, comm_style tiled, fix evaporate, fix adapt)."""
import math
import re
import os
import sys

import numpy as np
import pytest
from conftest import (OK, PLUGIN, SCENE_BOX, SCENE_EMPTY, SCENE_LINKED, SCENE_MORSE, InputTable,
                      check_input, lmp_error, run_lmp, scene_dimer, scene_pair, session)

D, ALPHA, A = 1.0, 6.0, 1.0    # Morse in lj units
# the same law (alpha a = 6) in other unit styles: energy D and length a of each
UNITS = {"lj": (1.0, 1.0), "metal": (0.3429, 2.866), "si": (2.46e-6, 1.0e-5),
         "real": (7.9, 2.866)}


def morse(r, d=D, a=A):
    """Energy and force (-dE/dr) of the Morse law (alpha a = 6)."""
    alpha = ALPHA / a
    e = math.exp(-alpha * (r - a))
    return d * (e * e - 2 * e), 2 * alpha * d * (e * e - e)


def dimer(lmp, style="morse/spline cut 1.3 link 1.05", r=1.0, units="lj"):
    d, a = UNITS[units]
    lmp.commands_list([f"units {units}", "atom_modify map array",
                       f"region box block {-5 * a} {5 * a} {-5 * a} {5 * a} {-5 * a} {5 * a} units box",
                       "create_box 1 box", "mass 1 1.0", "create_atoms 1 single 0 0 0 units box",
                       f"create_atoms 1 single {r * a} 0 0 units box", f"pair_style {style}",
                       f"pair_coeff * * {d} {ALPHA / a} {a}", f"neighbor {0.3 * a} bin"])
    if "link" in style:
        lmp.commands_list(["compute p all pair morse/spline", "compute l all links/atom",
                           "thermo_style custom step pe c_p[1] c_p[2] c_p[3]",
                           "thermo_modify norm no"])


def at(lmp, r):
    """Move atom 2 to distance r (absolute) and evaluate (run 0: setup, the state updates)."""
    lmp.command(f"set atom 2 x {r!r}")
    lmp.command("run 0")
    f = lmp.numpy.extract_atom("f")[:2].copy()
    ids = lmp.numpy.extract_atom("id")[:2]
    fx2 = f[list(ids).index(2), 0]
    links = lmp.numpy.extract_compute("l", 1, 1)[:2].copy()
    return lmp.get_thermo("pe"), fx2, links, [lmp.extract_compute("p", 0, 1)[k] for k in range(3)]


@pytest.mark.parametrize("units", list(UNITS))
def test_link_holds_up_to_rc_and_breaks_exactly_there(units):
    d, a = UNITS[units]
    with session() as lmp:
        dimer(lmp, units=units)
        for x in (1.0, 1.1, 1.2, 1.3 * (1 - 1e-12)):
            pe, fx, links, tally = at(lmp, x * a)
            e, f = morse(x * a, d, a)
            assert pe == pytest.approx(e, rel=1e-12) and fx == pytest.approx(f, rel=1e-12)
            assert list(links) == [1, 1] and tally == [0, 0, 0]
        pe, fx, links, tally = at(lmp, 1.3 * a)    # r = Rc a exactly: broken
        assert pe == 0 and fx == 0 and list(links) == [0, 0]
        assert tally[0] == 1 and tally[1] == 0
        assert tally[2] == pytest.approx(-morse(1.3 * a, d, a)[0], rel=1e-12)    # the jump at Rc a


def test_broken_link_never_attracts_and_repels_on_contact():
    with session() as lmp:
        dimer(lmp)
        at(lmp, 1.0)
        at(lmp, 1.5)    # break
        for r in (1.29, 1.1, 1.04, 1.0 + 1e-9):
            pe, fx, links, _ = at(lmp, r)
            assert pe == 0 and fx == 0 and list(links) == [0, 0]
        for r in (0.99, 0.95, 0.9):    # contact: the law's repulsive branch, zero energy at a
            pe, fx, links, tally = at(lmp, r)
            e, f = morse(r)
            assert fx == pytest.approx(f, rel=1e-12) and fx > 0
            assert pe == pytest.approx(e + D, rel=1e-10) and list(links) == [0, 0]
        assert tally[0] == 1


def test_pairs_never_linked_only_repel():
    with session() as lmp:
        dimer(lmp, r=1.1)    # beyond L a = 1.05 a at the first run: never linked
        pe, fx, links, _ = at(lmp, 1.1)
        assert pe == 0 and fx == 0 and list(links) == [0, 0]
        pe, fx, _, _ = at(lmp, 0.97)
        assert fx == pytest.approx(morse(0.97)[1], rel=1e-12) and pe == pytest.approx(morse(0.97)[0] + D)


def test_relink_welds_closer_than_l_and_tallies_the_jump():
    with session() as lmp:
        dimer(lmp, "morse/spline cut 1.3 link 1.05 relink yes")
        at(lmp, 1.0)
        at(lmp, 1.4)
        pe, fx, links, tally = at(lmp, 1.06)    # unlinked beyond L a: nothing
        assert pe == 0 and list(links) == [0, 0]
        pe, fx, links, tally = at(lmp, 1.04)    # welded
        e, f = morse(1.04)
        assert list(links) == [1, 1] and pe == pytest.approx(e) and fx == pytest.approx(f)
        assert tally[0] == 1 and tally[1] == 1
        assert tally[2] == pytest.approx(-morse(1.3)[0] + e, rel=1e-12)


OUTPUTS = """compute p all pair morse/spline
compute l all links/atom
compute d all dust links
variable e equal ke+pe-c_p[3]
thermo_style custom step ke pe v_e c_p[1] c_p[2] c_p[3] c_d[6]
thermo_modify norm no format float %.15g
thermo 100
"""
HOT = """units lj
atom_modify map array
{newton}
lattice fcc 1.41421356
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
mass 1 1.0
pair_style morse/spline cut 1.2 link 1.05 {relink}
pair_coeff * * 1.0 6.0 1.0
{shift}
velocity all create 3.0 4928 loop geom
neighbor 0.2 bin
fix 1 all nve
timestep 0.002
{outputs}run {steps}
write_dump all custom links.dump id c_l x y z modify sort id format float %.12g
"""


def numeric_rows(out, ncols=8):
    """The thermo rows of the output: lines of ncols numbers."""
    rows = []
    for line in out.splitlines():
        try:
            row = [float(v) for v in line.split()]
        except ValueError:
            continue
        if len(row) == ncols:
            rows.append(row)
    return np.array(rows)


def hot(tmp_path, nprocs=1, args=(), **kw):
    fields = dict(dict(newton="", relink="", shift="", steps=500, outputs=OUTPUTS), **kw)
    out = run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + HOT.format(**fields), nprocs, args=args)
    return numeric_rows(out), np.loadtxt(tmp_path / "links.dump", skiprows=9)


def test_break_energy_closes_the_balance_and_equals_the_count_times_the_jump(tmp_path):
    rows, _ = hot(tmp_path, steps=1000)
    broken, jumps = rows[-1, 4], rows[-1, 6]
    assert broken > 300
    assert jumps == pytest.approx(-broken * morse(1.2)[0], rel=1e-12)
    drift = abs(rows[-1, 3] - rows[0, 3])
    assert drift < 1e-3 * jumps    # measured 4e-4: ke + pe alone moves by the whole jump


def test_shifted_cut_tail_breaks_without_energy_jump(tmp_path):
    rows, _ = hot(tmp_path, shift="pair_modify shift yes")
    assert rows[-1, 4] > 100 and rows[-1, 6] == 0


@pytest.mark.parametrize("variant", [dict(nprocs=2), dict(nprocs=4), dict(newton="newton off", nprocs=2),
                                     dict(args=("-sf", "omp", "-pk", "omp", "2")),
                                     dict(nprocs=2, relink="relink yes")])
def test_link_state_is_the_same_on_1_2_4_ranks_newton_off_and_omp(tmp_path, variant):
    relink = variant.get("relink", "")
    serial_rows, serial = hot(tmp_path, relink=relink)
    rows, dump = hot(tmp_path, **variant)
    assert serial_rows[-1, 4] > 100    # links did break
    assert np.array_equal(rows[:, [0, 4, 5, 7]], serial_rows[:, [0, 4, 5, 7]])
    assert np.allclose(rows[:, 1:4], serial_rows[:, 1:4], rtol=1e-9, atol=1e-9)
    # atom IDs follow the decomposition (create_atoms): match the atoms by position
    def by_position(rows):
        return rows[np.lexsort(np.round(rows[:, 2:5], 5).T)]
    dump, serial = by_position(dump), by_position(serial)
    assert np.allclose(dump[:, 2:], serial[:, 2:], atol=1e-8)
    assert np.array_equal(dump[:, 1], serial[:, 1])    # links of every atom


RESTART_A = HOT.replace("run {steps}", "run 300\nwrite_restart links.restart\nrun 300")
RESTART_B = """read_restart links.restart
neighbor 0.2 bin
fix 1 all nve
"""  + OUTPUTS + """run 300
write_dump all custom links.dump id c_l x y z modify sort id format float %.12g
"""


@pytest.mark.parametrize("nprocs", [1, 2])
def test_restart_keeps_links_and_counts(tmp_path, nprocs):
    fields = dict(newton="", relink="", shift="", steps=0, outputs=OUTPUTS)
    out_a = run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + RESTART_A.format(**fields), nprocs)
    dump_a = np.loadtxt(tmp_path / "links.dump", skiprows=9)
    out_b = run_lmp(tmp_path, f"plugin load {PLUGIN}\n" + RESTART_B, 1, name="in.b")    # written on nprocs, read on 1
    dump_b = np.loadtxt(tmp_path / "links.dump", skiprows=9)

    a, b = numeric_rows(out_a)[-1], numeric_rows(out_b)[-1]
    assert a[0] == b[0] == 600
    assert a[4] > 100 and a[4] == b[4] and a[7] == b[7]
    assert np.allclose(b[1:4], a[1:4], rtol=1e-9)
    assert np.array_equal(dump_a[:, :2], dump_b[:, :2])


def test_write_data_keeps_no_links_and_the_next_run_links_by_distance(tmp_path):
    script = f"plugin load {PLUGIN}\n" + HOT.format(newton="", relink="", shift="", steps=300, outputs=OUTPUTS) + f"""write_data links.data
clear
plugin load {PLUGIN}
atom_modify map array
pair_style morse/spline cut 1.2 link 1.05
read_data links.data
neighbor 0.2 bin
compute l all links/atom
compute c all coord/atom cutoff 1.05
variable diff atom abs(c_l-c_c)
compute diff all reduce sum v_diff
compute ls all reduce sum c_l
thermo_style custom step c_ls c_diff
thermo_modify norm no
run 0
"""
    out = run_lmp(tmp_path, script)
    row = numeric_rows(out, 3)[-1]
    assert row[1] > 1000 and row[2] == 0


def test_dust_links_counts_fragments_of_the_link_graph_not_of_distances():
    # two fcc blocks whose closest pairs across the gap are 1.1 a apart: within Rc a = 1.2 a
    # (one fragment by distance), beyond L a = 1.05 a (two on the link graph)
    with session() as lmp:
        lmp.commands_list(["units lj", "atom_modify map array", "boundary f p p",
                           "lattice fcc 1.41421356", "region box block -1 9 0 3 0 3",
                           "create_box 1 box", "region left block 0 3.99 0 3 0 3",
                           "region right block 4 8 0 3 0 3", "create_atoms 1 region left",
                           "create_atoms 1 region right", "mass 1 1.0", "group right region right",
                           f"displace_atoms right move {(1.1 ** 2 - 0.5) ** 0.5 - 0.5 ** 0.5!r} 0 0 units box",
                           "pair_style morse/spline cut 1.2 link 1.05",
                           f"pair_coeff * * {D} {ALPHA} {A}", "neighbor 0.3 bin",
                           "compute links all dust links", "compute dist all dust",
                           "compute cl all cluster/atom 1.05", "compute nc all reduce max c_cl",
                           "run 0"])
        assert lmp.extract_compute("links", 0, 1)[5] == 2 and lmp.extract_compute("dist", 0, 1)[5] == 1
        assert lmp.extract_compute("nc", 0, 0) > 1    # cluster/atom at L a: two clusters too


CHAIN = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "examples", "chain-1d"))


@pytest.mark.parametrize("var", [dict(u=2000, damp="relative"), dict(u=500, transits=0.9)])
def test_1d_chain_with_link_105_is_the_nearest_neighbour_chain(var):
    sys.path.insert(0, CHAIN)
    os.environ["LAMMPS_PLUGIN_PATH"] = os.path.dirname(PLUGIN)
    import run_study
    chain, link = run_study.run(**var), run_study.run(link=1.05, **var)
    assert np.array_equal(chain["x"], link["x"]) and np.array_equal(chain["v"], link["v"])
    assert chain["detached"] == link["detached"]


def test_no_link_no_history():
    with session() as lmp:
        dimer(lmp, "morse/spline cut 1.3")
        lmp.command("run 0")
        assert not lmp.has_id("fix", "NEIGH_HISTORY_LINK")
        lmp.command("pair_style morse/spline cut 1.3 link 1.05")
        lmp.commands_list([f"pair_coeff * * {D} {ALPHA} {A}", "run 0"])
        assert lmp.has_id("fix", "NEIGH_HISTORY_LINK")


BAD = [
    ("pair_style morse/spline cut 1.2 link 0.9", "link L must be >= 1 in units of a \\(got 0.9\\)"),
    ("pair_style morse/spline cut 1.2 link", "keyword link needs a value"),
    ("pair_style morse/spline cut 1.2 relink yes", "relink needs link L"),
    ("pair_style morse/spline cut 1.2 link 1.05 relink maybe", "relink must be yes or no \\(got 'maybe'\\)"),
    ("pair_style morse/spline cut 1.2 chain 2 link 1.05", "link and chain N do not combine"),
    ("pair_style morse/spline cut 1.2 link 1.3\npair_coeff * * 1.0 6.0 1.0",
     "link L = 1.3 is beyond the tail end of types 1 1 \\(1.2 a\\)"),
    ("pair_style morse/spline wagner link 1.5\npair_coeff * * 1.0 6.0 1.0",
     "link L = 1.5 is beyond the tail end of types 1 1"),
    ("pair_style morse/spline cut 1.2 link 1.05\npair_style morse/spline cut 1.2",
     "link cannot be switched off once set"),
    ("pair_style hybrid morse/spline cut 1.2 link 1.05 morse/spline cut 1.3 link 1.05",
     "another pair style already keeps links"),
    ("pair_style morse/spline cut 1.2\npair_coeff * * 1.0 6.0 1.0\ncompute d all dust links\nrun 0",
     "Compute dust links needs a pair style with link L"),
    ("compute d all dust links cutoff 1.2", "links and cutoff exclude each other"),
]


@pytest.mark.parametrize("commands,message", BAD)
def test_bad_link_input_is_a_clear_error(commands, message):
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 4 0 4 0 4", "create_box 1 box",
                           "mass 1 1.0", "create_atoms 1 single 1 1 1"])
        *first, last = commands.split("\n")
        lmp.commands_list(first)
        with pytest.raises(Exception, match=message):
            lmp.command(last)


def test_link_needs_atom_ids():
    with session() as lmp:
        lmp.commands_list(["units lj", "atom_modify id no", "region box block 0 4 0 4 0 4",
                           "create_box 1 box", "mass 1 1.0"])
        with pytest.raises(Exception, match="link needs atom IDs"):
            lmp.command("pair_style morse/spline cut 1.2 link 1.05")


def test_replicate_with_links_is_refused_and_replicate_before_linking_works():
    """LAMMPS's own check refuses every fix with per-atom arrays before any style can speak;
    doc/pair_spline.rst says what to do (replicate, then link)."""
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


# ---------------------------------------------------------------- hostile input

INPUTS = InputTable()
row = INPUTS.row
P = "pair_style morse/spline "
for rid, args, expect, defect in [
    ("link-0.5", "cut 1.3 link 0.5", r"link L must be >= 1 in units of a \(got 0.5\)", None),
    ("link--0", "cut 1.3 link -0", r"link L must be >= 1 in units of a \(got -0\)", None),
    ("link-nan", "cut 1.3 link nan", r"link.*nan", None),
    ("link-nothing", "cut 1.3 link", r"keyword link needs a value", None),
    ("relink-maybe", "cut 1.3 link 1.05 relink maybe", r"relink must be yes or no \(got 'maybe'\)",
     None),
    ("relink-without-link", "cut 1.3 relink yes", r"relink needs link L", None),
    ("link-with-chain", "cut 1.3 link 1.05 chain 2", r"link and chain N do not combine", None),
]:
    row(f"style-{rid}", SCENE_BOX, P + args, expect, defect)
row("style-link-twice", SCENE_BOX, P + "cut 1.3 link 1.05 link 1.1", r"keyword link given twice")
row("style-relink-twice", SCENE_BOX, P + "cut 1.3 link 1.05 relink yes relink no",
    r"keyword relink given twice")
row("style-link-beyond-tail", SCENE_MORSE[:-2], [P + "cut 1.3 link 5", "pair_coeff * * 1.0 6.0 1.0"],
    r"link L .*(tail|Rc|1\.3)")
row("style-switch-link-off", SCENE_LINKED, ["run 0 post no", "pair_style morse/spline cut 1.3"],
    r"link cannot be switched off once set")
row("run-link", SCENE_LINKED, [], OK)
row("run-hybrid-two-links", scene_dimer(), "pair_style hybrid/overlay morse/spline cut 1.3 link 1.05 "
    "lj/spline cut 1.3 link 1.05", r"another pair style already keeps links")
row("run-unfix-link-state", SCENE_LINKED, ["run 0 post no", "unfix NEIGH_HISTORY_LINK"],
    r"link state \(fix NEIGH_HISTORY_LINK\) was deleted by unfix")
row("run-pair-local-link", SCENE_LINKED, "compute pl all pair/local dist eng",
    r"does not support compute pair/local")
row("run-born-matrix-link", SCENE_LINKED, "compute b all born/matrix",
    r"morse/spline does not support compute born/matrix")
row("run-pair-write-link", SCENE_LINKED, "pair_write 1 1 10 r 0.5 1.3 /dev/null X",
    r"does not support pair_write")
row("run-minimize-link", SCENE_LINKED, "minimize 0 0 10 100", OK)
# replacing a pair style with link L: the link state must not outlive it
row("run-link-to-lj-cut", SCENE_LINKED, ["run 0 post no", "pair_style lj/cut 1.5",
                                         "pair_coeff * * 1.0 1.0", "run 3 post no"], OK)
row("run-link-to-none", SCENE_LINKED, ["run 0 post no", "pair_style none", "run 3 post no"], OK)
row("run-link-to-other-spline", SCENE_LINKED, ["run 0 post no", "pair_style lj/spline cut 1.3",
                                               "pair_coeff * * 1.0 1.0", "run 3 post no"], OK)
row("run-link-to-hybrid", SCENE_LINKED, ["run 0 post no",
                                         "pair_style hybrid/overlay lj/cut 1.5 morse/spline cut 1.3",
                                         "pair_coeff * * lj/cut 1.0 1.0",
                                         "pair_coeff * * morse/spline 1.0 6.0 1.0", "run 3 post no"],
    OK)
row("run-link-to-lj-cut-viscous", SCENE_LINKED, ["fix n all nve", "fix v all viscous/relative gamma 1",
                                                 "run 0 post no", "pair_style lj/cut 1.5",
                                                 "pair_coeff * * 1.0 1.0", "run 3 post no"], OK)
row("run-hybrid-link-computes", scene_dimer(), [
    "pair_style hybrid/overlay lj/cut 1.5 morse/spline cut 1.3 link 1.1",
    "pair_coeff * * lj/cut 0.1 1.0", "pair_coeff * * morse/spline 1.0 6.0 1.0",
    "compute l all links/atom", "compute n all reduce sum c_l", "compute d all dust links",
    "fix n all nve", "fix v all viscous/relative J 50",
    "thermo_style custom step pe press c_n c_d[1]", "thermo_modify norm no", "run 3 post no"], OK)
row("run-delete-all-linked", SCENE_LINKED, [
    "compute l all links/atom", "compute d all dust links", "compute n all reduce sum c_l",
    "thermo_style custom step pe press c_n c_d[1] c_d[4]", "thermo_modify norm no", "run 0 post no",
    "delete_atoms group all", "run 3 post no"], OK)

# the link state is kept by partner ID: what it needs from the box and the commands around it
row("link-thin-periodic-box", ["units lj", "region box block 0 2.25 -4 4 -4 4", "create_box 1 box",
                               "mass 1 1.0", "create_atoms 1 single 0.2 0 0 units box",
                               "create_atoms 1 single 1.2 0 0 units box", "neighbor 0.3 bin"]
    + scene_pair("morse/spline", "cut 1.3 link 1.05"),
    [], r"the periodic box is 2\.25 wide along x, not more than twice")
row("link-tiled-newton-on", SCENE_LINKED, ["comm_style tiled", "fix n all nve", "run 5 post no"],
    OK)
row("link-tiled-newton-off", scene_dimer() + ["newton off on", "comm_style tiled"]
    + scene_pair("morse/spline", "cut 1.3 link 1.1"), ["fix n all nve", "run 5 post no"], OK)
row("link-evaporate-before-pair-style", scene_dimer() + [
    "region r block INF INF INF INF INF INF", "fix ev all evaporate 1 1 r 4711"]
    + scene_pair("morse/spline", "cut 1.3 link 1.1"), ["fix n all nve"],
    r"fix ev \(evaporate\) adds or deletes atoms before the link state")
row("link-evaporate-after-pair-style", SCENE_LINKED, [
    "region r block INF INF INF INF INF INF", "fix ev all evaporate 1 1 r 4711", "fix n all nve",
    "run 3 post no"], OK)

row("adapt-pair_state", SCENE_LINKED, ["variable k equal 1",
                                       "fix a all adapt 1 pair morse/spline pair_state * * v_k"],
    r"Pair style parameter pair_state is not compatible with fix adapt", isolate=True)

# in an empty box: keywords given twice; the link state's fix IDs are reserved
row("style-link-twice-empty-box", SCENE_EMPTY, P + "cut 1.2 link 1.05 link 1.1",
    r"Pair style morse/spline \(after tail cut\): keyword link given twice")
row("style-relink-twice-empty-box", SCENE_EMPTY, P + "cut 1.2 link 1.05 relink yes relink no",
    "keyword relink given twice")
row("link-fix-id-taken-before-pair-style", SCENE_EMPTY,
    ["fix NEIGH_HISTORY_LINK all nve", P + "cut 1.2 link 1.05"],
    "Pair style morse/spline: fix ID NEIGH_HISTORY_LINK is reserved for the link state")
row("link-fix-id-taken-after-pair-style", SCENE_EMPTY,
    [P + "cut 1.2 link 1.05", "pair_coeff * * 1.0 6.0 1.0", "fix NEIGH_HISTORY_LINK all nve",
     "run 0"], "fix ID NEIGH_HISTORY_LINK is reserved")
row("link-fix-id-prefix-taken", SCENE_EMPTY,
    ["fix NEIGH_HISTORY_LINK_DUMMY all nve", P + "cut 1.2 link 1.05"],
    "fix ID NEIGH_HISTORY_LINK_DUMMY is reserved")


@pytest.mark.parametrize("setup,cmds,expect,isolate", INPUTS.rows)
def test_hostile_input(setup, cmds, expect, isolate):
    check_input(setup, cmds, expect, isolate)


@pytest.mark.parametrize("units,scale", [("lj", 1.0), ("si", 1.0e-5)])
def test_links_moved_away_between_runs_are_named_as_a_move(tmp_path, units, scale):
    """One atom of a linked block displaced by 3 a between two runs: the error says the atoms
    were moved since the last run, not that the skin is too small."""
    a = scale
    lines = [f"units {units}", "atom_modify map array", f"lattice fcc {1.41421356 * a}",
             "region box block 0 3 0 3 0 3", "create_box 1 box", "create_atoms 1 box",
             "mass 1 1.0", "pair_style morse/spline cut 1.3 link 1.1",
             f"pair_coeff * * 1.0 6.0 {a}", f"neighbor {0.3 * a} bin", "fix 1 all nve",
             f"timestep {0.002 * (1.0 if units == 'lj' else 1e-8)}", "run 10",
             "group one id 1", f"displace_atoms one move {3.0 * a} 0 0 units box", "run 10"]
    out = lmp_error(tmp_path, lines)
    assert re.search(r"links left the neighbour list unbroken \(fix \S+\): their atoms are farther "
                     r"apart than the list's cutoff before this run: atoms were moved since the "
                     r"last run", out), out[-1500:]
