"""Persistent pair state (links) under everything LAMMPS does to atoms, on 1 and 2 ranks: a
restart written right after a run, atom deletion and ID renumbering, minimization trial points,
rerun, empty processors, unfix of the internal fix, a re-issued pair_style, a linked pair that
leaves the neighbour list, and compute dust evaluated again at the same step; the pair
styles' cumulative totals (compute pair: links broken and formed, the energy of those changes,
pair mca's damage, plastic and friction work) across run boundaries and restart files.  Oracles:
the straight run against the split one, compute coord/atom at L a (the pairs a fresh setup
links), the Morse minimum, the original run's link counts frame by frame, the serial run, the
uninterrupted run's totals at the step of the boundary or the restart file."""
import os
import re
import subprocess

import numpy as np
import pytest
from conftest import (LMP, MCA_FCC_BLOCK, PLUGIN, carried_totals, morse_dimer, morse_fcc, run_lmp,
                      session)

LINKED = "pair_style morse/spline cut 1.2 link 1.05\npair_coeff * * 1.0 6.0 1.0\nneighbor 0.2 bin\n"
# the outputs of a linked fcc block: links, broken links and links unlike coord/atom's at L a
OUTPUTS = """compute p all pair morse/spline
compute l all links/atom
compute ls all reduce sum c_l
compute c all coord/atom cutoff 1.05
variable diff atom abs(c_l-c_c)
compute diff all reduce sum v_diff
thermo_style custom step pe c_ls c_p[1] c_diff
thermo_modify norm no format float %.15g
"""


def results(out):
    """The 'RESULT name value' lines a script printed, as floats."""
    return {m.group(1): float(m.group(2)) for m in re.finditer(r"^RESULT (\S+) (\S+)$", out, re.M)}


def block(atom_map=True):
    """A periodic fcc block of 256 atoms linked at L = 1.05 (cut 1.2), with the OUTPUTS."""
    lines = morse_fcc(4, "morse/spline cut 1.2 link 1.05", noise=0, skin=0.2, atom_map=atom_map)
    return "\n".join([f"plugin load {PLUGIN}", *lines, OUTPUTS])


REPORT = 'print "RESULT {tag}pe $(pe:%.15g)"\nprint "RESULT {tag}links $(c_ls)"\n' \
         'print "RESULT {tag}broken $(c_p[1])"\nprint "RESULT {tag}diff $(c_diff)"\n'


def report(tag):
    return REPORT.format(tag=tag)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_write_restart_right_after_a_run_keeps_links_and_a_split_run_equals_the_straight_one(
        tmp_path, nprocs):
    hot = "velocity all create 0.5 4711 loop geom\nfix 1 all nve\ntimestep 0.004\n"
    straight = block() + hot + "run 300\nrun 300\n" + report("s")
    split_a = block() + hot + "run 300\n" + report("a") + "write_restart split.restart\nrun 0\n" + \
        report("b")
    split_b = f"plugin load {PLUGIN}\nread_restart split.restart\nneighbor 0.2 bin\nfix 1 all nve\n" \
        + OUTPUTS + "run 0\n" + report("c") + "run 300\n" + report("d")
    s = results(run_lmp(tmp_path, straight, nprocs))
    r = results(run_lmp(tmp_path, split_a, nprocs))
    r.update(results(run_lmp(tmp_path, split_b, nprocs, name="in.b")))
    assert 0 < r["abroken"] and r["alinks"] < 12 * 256    # links broke, atoms crossed the box
    for tag in "bc":    # write_restart and read_restart change nothing
        assert r[tag + "links"] == r["alinks"] and r[tag + "broken"] == r["abroken"]
        assert r[tag + "pe"] == pytest.approx(r["ape"], rel=1e-13)
    assert r["dlinks"] == s["slinks"] and r["dbroken"] == s["sbroken"]
    assert r["dpe"] == pytest.approx(s["spe"], rel=1e-9)


def test_write_restart_noinit_keeps_the_totals_of_every_rank_and_refuses_unrestored_links(
        tmp_path):
    """write_restart noinit skips the init that gathers the broken-link totals onto processor
    0: the end of the run gathers them (2 ranks: was processor 0's share only).  Right after a
    read_restart the links are not yet restored: noinit then stops with an error (was: a file
    without them, broken links back by distance)."""
    hot = "velocity all create 2.0 4711 loop geom\nfix 1 all nve\ntimestep 0.002\n"
    write = block() + hot + "run 200\n" + report("a") + "write_restart n.restart noinit\n"
    read = f"plugin load {PLUGIN}\nread_restart n.restart\nneighbor 0.2 bin\n" \
        + OUTPUTS + "run 0\n" + report("b")
    r = results(run_lmp(tmp_path, write, 2))
    r.update(results(run_lmp(tmp_path, read, 1, name="in.read")))
    assert r["abroken"] > 0 and r["alinks"] < 12 * 256
    assert r["bbroken"] == r["abroken"] and r["blinks"] == r["alinks"]
    with session() as lmp:
        lmp.commands_list([f"read_restart {tmp_path / 'n.restart'}", "neighbor 0.2 bin"])
        with pytest.raises(Exception, match="write_restart noinit before the link state read"):
            lmp.command(f"write_restart {tmp_path / 'again.restart'} noinit")


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("atom_map", [True, False], ids=["atom_modify map array", ""])
def test_links_follow_renumbered_ids_and_end_with_deleted_atoms(tmp_path, nprocs, atom_map):
    script = block(atom_map) + """displace_atoms all random 0.02 0.02 0.02 991 units box
run 0
""" + report("a") + """reset_atoms id sort yes
run 0
""" + report("b") + """region hole sphere 2 2 2 0.8
delete_atoms region hole compress yes
run 0
""" + report("c") + 'print "RESULT natoms $(atoms)"\n'
    out = run_lmp(tmp_path, script, nprocs)
    r = results(out)
    assert r["alinks"] == 12 * 256 and r["adiff"] == 0    # links are the pairs within L a
    assert r["blinks"] == r["alinks"] and r["bdiff"] == 0 and r["bpe"] == pytest.approx(r["ape"])
    # the remaining atoms keep exactly their links to remaining atoms (coord/atom at L a)
    assert r["natoms"] < 256 and r["cdiff"] == 0 and 0 < r["clinks"] < r["blinks"]
    assert r["cbroken"] == 0 and "links ended with their deleted atoms" in out
    # every link with a deleted atom is counted once, whichever of its atoms kept its state (the
    # links/atom sums count each link at both atoms)
    ended = re.search(r"(\d+) links ended with their deleted atoms", out)
    assert 2 * int(ended.group(1)) == r["blinks"] - r["clinks"]


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("style", ["cg", "sd", "fire"])
def test_minimize_trial_points_never_break_links(tmp_path, nprocs, style):
    # a compressed linked dimer: the first line-search step (dmax) takes it to 1.4 a, beyond
    # Rc a (the list is rebuilt there): a trial point, which must not break the link.  A
    # minimizer never ends above its start; fire (no line search) reaches the Morse minimum.
    script = f"""plugin load {PLUGIN}
units lj
atom_modify map array
region box block -4 4 -4 4 -4 4
create_box 1 box
mass 1 1.0
create_atoms 1 single -0.5 0 0 units box
create_atoms 1 single 0.5 0 0 units box
pair_style morse/spline cut 1.3 link 1.05
pair_coeff * * 1.0 6.0 1.0
neighbor 0.3 bin
compute p all pair morse/spline
compute l all links/atom
compute ls all reduce sum c_l
thermo_modify norm no
run 0
set atom 1 x -0.4
set atom 2 x 0.4
run 0
print "RESULT pe_start $(pe:%.15g)"
min_style {style}
min_modify dmax 0.3
minimize 0 1e-10 2000 20000
print "RESULT pe $(pe:%.15g)"
print "RESULT r $(x[2]-x[1]:%.15g)"
print "RESULT broken $(c_p[1])"
print "RESULT links $(c_ls)"
run 0
print "RESULT pe0 $(pe:%.15g)"
"""
    r = results(run_lmp(tmp_path, script, nprocs))
    assert r["broken"] == 0 and r["links"] == 2 and r["pe0"] == r["pe"]
    assert r["pe"] <= r["pe_start"] and r["r"] < 1.3
    if style == "fire":
        assert r["pe"] == pytest.approx(-1.0, abs=1e-8) and r["r"] == pytest.approx(1.0, abs=1e-4)


def test_minimize_of_a_hot_block_breaks_only_links_beyond_rc_at_accepted_points(tmp_path):
    # cg on a block with broken and nearly broken links: after the minimization a run 0 at the
    # same positions finds the same energy and links (no phantom breaks at trial points)
    script = block() + """velocity all create 3.0 4928 loop geom
fix 1 all nve
timestep 0.002
run 300
unfix 1
run 0
""" + report("s") + "minimize 0 1e-8 200 2000\n" + report("m") + "run 0\n" + report("z")
    r = results(run_lmp(tmp_path, script))
    assert r["sbroken"] > 0    # the hot run broke links; the minimizer must never end higher
    assert r["mpe"] <= r["spe"]
    assert r["zlinks"] == r["mlinks"] and r["zbroken"] == r["mbroken"] and r["zpe"] == r["mpe"]


@pytest.mark.parametrize("nprocs", [1, 2])
def test_rerun_tracks_links_frame_by_frame(tmp_path, nprocs):
    run = block() + """velocity all create 3.0 4928 loop geom
fix 1 all nve
timestep 0.002
thermo 1
dump d all custom 1 frames.dump id x y z
dump_modify d format float %.17g sort id
run 60
"""
    rerun = block() + "thermo 1\nrerun frames.dump dump x y z\n"
    def rows(out):
        return np.array([[float(v) for v in l.split()] for l in out.splitlines()
                         if re.match(r"^\s*\d+(\s+\S+){4}\s*$", l)])
    a = rows(run_lmp(tmp_path, run, nprocs))
    b = rows(run_lmp(tmp_path, rerun, nprocs, name="in.rerun"))
    assert len(a) == len(b) == 61 and a[-1, 3] > 50    # links broke during the run
    assert np.array_equal(a[:, [0, 2, 3]], b[:, [0, 2, 3]])    # links and breaks, every frame
    assert np.allclose(a[:, 1], b[:, 1], rtol=1e-10)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_dust_links_with_an_empty_processor_and_an_empty_box(tmp_path, nprocs):
    script = f"""plugin load {PLUGIN}
units lj
processors * 1 1
lattice fcc 1.41421356
region box block 0 8 0 3 0 3
create_box 1 box
region left block 0 3 0 3 0 3
create_atoms 1 region left
mass 1 1.0
pair_style morse/spline cut 1.2 link 1.05
pair_coeff * * 1.0 6.0 1.0
neighbor 0.2 bin
compute d all dust links
compute l all links/atom
compute ls all reduce sum c_l
run 0
print "RESULT fragments $(c_d[6])"
print "RESULT largest $(c_d[5])"
print "RESULT links $(c_ls)"
print "RESULT natoms $(atoms)"
"""
    r = results(run_lmp(tmp_path, script, nprocs))
    assert r["fragments"] == 1 and r["largest"] == r["natoms"] > 0 and r["links"] > 0
    empty = f"""plugin load {PLUGIN}
units lj
region box block 0 4 0 4 0 4
create_box 1 box
mass 1 1.0
pair_style morse/spline cut 1.2 link 1.05
pair_coeff * * 1.0 6.0 1.0
compute d all dust links
run 0
print "RESULT fragments $(c_d[6])"
"""
    assert results(run_lmp(tmp_path, empty, nprocs, name="in.empty"))["fragments"] == 0


@pytest.mark.parametrize("nprocs", [1, 2])
def test_atoms_created_after_the_links_are_linked_at_the_next_setup(tmp_path, nprocs):
    # the left half is linked and strained so that its links differ from distances; new atoms
    # on the right link to their neighbours closer than L a (old ones included), the old links
    # stay as they were
    script = f"""plugin load {PLUGIN}
units lj
lattice fcc 1.41421356
region box block 0 8 0 4 0 4
create_box 1 box
region left block 0 3.99 INF INF INF INF
create_atoms 1 region left
mass 1 1.0
pair_style morse/spline cut 1.2 link 1.05
pair_coeff * * 1.0 6.0 1.0
neighbor 0.2 bin
compute l all links/atom
compute ls all reduce sum c_l
compute c all coord/atom cutoff 1.05
variable diff atom abs(c_l-c_c)
compute diff all reduce sum v_diff
run 0
print "RESULT alinks $(c_ls)"
region right block 4 8 INF INF INF INF
create_atoms 1 region right
run 0
print "RESULT blinks $(c_ls)"
print "RESULT bdiff $(c_diff)"
print "RESULT natoms $(atoms)"
"""
    r = results(run_lmp(tmp_path, script, nprocs))
    assert r["natoms"] == 512 and r["alinks"] < 12 * 256    # the left half's surfaces
    assert r["bdiff"] == 0 and r["blinks"] == 12 * 512    # a full periodic crystal now


@pytest.mark.parametrize("nprocs", [1, 2])
def test_a_restart_written_before_any_run_links_at_the_first_run_after_reading(tmp_path, nprocs):
    a = block() + "write_restart early.restart\n"
    b = f"plugin load {PLUGIN}\nread_restart early.restart\nneighbor 0.2 bin\n" + \
        OUTPUTS + "run 0\n" + report("r")
    run_lmp(tmp_path, a, nprocs)
    r = results(run_lmp(tmp_path, b, nprocs, name="in.b"))
    assert r["rlinks"] == 12 * 256 and r["rdiff"] == 0


@pytest.mark.parametrize("nprocs", [1, 2])
def test_compute_dust_after_displace_atoms_at_the_same_step_on_ranks(tmp_path, nprocs):
    script = f"""plugin load {PLUGIN}
units lj
boundary f p p
lattice fcc 1.41421356
region box block -1 9 0 4 0 4
create_box 1 box
region b block 0 4 0 4 0 4
create_atoms 1 region b
mass 1 1.0
pair_style morse/spline cut 1.2
pair_coeff * * 1.0 6.0 1.0
neighbor 0.2 bin
compute d all dust
thermo_style custom step c_d[5] c_d[6]
run 0
print "RESULT alargest $(c_d[5])"
region right block 2 4 INF INF INF INF
group right region right
displace_atoms right move 3 0 0 units box
run 0
print "RESULT blargest $(c_d[5])"
print "RESULT bfragments $(c_d[6])"
print "RESULT natoms $(atoms)"
"""
    r = results(run_lmp(tmp_path, script, nprocs))
    assert r["alargest"] == r["natoms"] and r["bfragments"] == 2 and r["blargest"] < r["natoms"]


def dimer_session(lmp, style="morse/spline cut 1.3 link 1.05", r=1.0):
    lmp.commands_list(morse_dimer(r, style) + ["compute l all links/atom",
                                                "compute ls all reduce sum c_l"])


def test_unfix_of_the_internal_fix_is_a_clear_error_and_the_host_survives():
    with session() as lmp:
        dimer_session(lmp)
        lmp.command("run 0")
        lmp.command("unfix NEIGH_HISTORY_LINK")
        with pytest.raises(Exception, match="link state \\(fix NEIGH_HISTORY_LINK\\) was deleted"):
            lmp.command("run 0")
        lmp.commands_list(["pair_style morse/spline cut 1.3 link 1.05", "run 0"])    # afresh
        assert lmp.extract_compute("ls", 0, 0) == 2


DIMER = "\n".join([f"plugin load {PLUGIN}", *morse_dimer(), "run 0", ""])


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("change,message", [
    ("unfix NEIGH_HISTORY_LINK", "its link state \\(fix NEIGH_HISTORY_LINK\\) was deleted by unfix"),
    ("neigh_modify exclude type 1 1", "1 links left the neighbour list unbroken \\(fix "
                                      "NEIGH_HISTORY_LINK\\): their atoms are farther apart")])
def test_unfix_and_lost_links_stop_every_rank_with_the_message(tmp_path, nprocs, change, message):
    (tmp_path / "in.test").write_text(DIMER + change + "\nrun 0\n")
    cmd = [LMP, "-in", "in.test", "-log", "none", "-nocite"]
    if nprocs > 1:
        cmd = ["mpirun", "-np", str(nprocs), "--oversubscribe"] + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    out = subprocess.run(cmd, cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    assert out.returncode != 0 and re.search(message, out.stdout + out.stderr)


def test_fix_pair_state_is_internal():
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block -4 4 -4 4 -4 4", "create_box 1 box",
                           "mass 1 1.0", "pair_style morse/spline cut 1.3",
                           "pair_coeff * * 1.0 6.0 1.0"])
        with pytest.raises(Exception, match="Unrecognized fix style 'PAIR_STATE'"):
            lmp.command("fix s all PAIR_STATE 1")
    with session() as lmp:
        dimer_session(lmp)    # after a linked style has made its fix: still not for users
        lmp.command("run 0")
        with pytest.raises(Exception, match="Unrecognized fix style 'PAIR_STATE'"):
            lmp.command("fix s all PAIR_STATE 1")


@pytest.mark.parametrize("nprocs", [1, 2])
def test_reissued_pair_style_links_afresh_with_the_new_l_and_says_so(tmp_path, nprocs):
    script = block() + """displace_atoms all random 0.04 0.04 0.04 991 units box
run 0
""" + report("a") + """pair_style morse/spline cut 1.2 link 1.02
pair_coeff * * 1.0 6.0 1.0
compute c2 all coord/atom cutoff 1.02
variable diff2 atom abs(c_l-c_c2)
compute diff2 all reduce sum v_diff2
run 0
print "RESULT bdiff2 $(c_diff2)"
""" + report("b") + """pair_style hybrid/overlay morse/spline cut 1.2 link 1.05 zero 1.0
pair_coeff * * morse/spline 1.0 6.0 1.0
pair_coeff * * zero
compute p2 all pair morse/spline
run 0
print "RESULT cbroken $(c_p2[1])"
""" + report("c")
    out = run_lmp(tmp_path, script, nprocs)
    r = results(out)
    assert r["adiff"] == 0 and r["bdiff2"] == 0 and r["blinks"] < r["alinks"]    # L = 1.02 now
    assert r["cdiff"] == 0 and r["clinks"] == r["alinks"] and r["cbroken"] == 0
    assert f"pair_style re-issued: the {r['alinks'] / 2:.0f} links of the last run are discarded" \
        in out


@pytest.mark.parametrize("nprocs", [1, 2])
def test_reissued_after_read_restart_links_afresh(tmp_path, nprocs):
    """pair_style re-issued after read_restart, before any run: the links the restart file
    carries are discarded as the log says (the fix made at the next init forgets them), and
    the pairs are linked afresh at the new L."""
    hot = "velocity all create 0.5 4711 loop geom\nfix 1 all nve\ntimestep 0.004\n"
    run_lmp(tmp_path, block() + hot + "run 300\n" + report("a") + "write_restart r.restart\n",
            nprocs)
    after = f"plugin load {PLUGIN}\nread_restart r.restart\n" + \
        (LINKED + OUTPUTS).replace("link 1.05", "link 1.02").replace(
            "cutoff 1.05", "cutoff 1.02") + "run 0\n" + report("b")
    out = run_lmp(tmp_path, after, nprocs, name="in.b")
    r = results(out)
    assert r["bdiff"] == 0 and r["bbroken"] == 0 and "are discarded" in out


def test_a_linked_pair_leaving_the_neighbour_list_is_an_error():
    with session() as lmp:
        lmp.command("atom_modify map array")
        dimer_session(lmp)
        lmp.command("run 0")
        assert lmp.extract_compute("ls", 0, 0) == 2
        lmp.command("neigh_modify exclude type 1 1")
        with pytest.raises(Exception, match="1 links left the neighbour list unbroken "
                                            "\\(fix NEIGH_HISTORY_LINK\\)"):
            lmp.command("run 0")


def test_deleting_a_linked_atom_is_no_error():
    with session() as lmp:
        dimer_session(lmp)
        lmp.command("run 0")
        lmp.command("group two id 2")
        lmp.command("delete_atoms group two compress no")
        lmp.command("run 0")
        assert lmp.get_natoms() == 1 and lmp.extract_compute("ls", 0, 0) == 0


@pytest.mark.parametrize("change", ["displace_atoms right move 3 0 0 units box",
                                    "delete_atoms group right"])
def test_compute_dust_is_evaluated_again_after_the_atoms_changed(change):
    with session() as lmp:
        lmp.commands_list(["units lj", "boundary f p p", "lattice fcc 1.41421356",
                           "region box block -1 9 0 4 0 4", "create_box 1 box",
                           "region b block 0 4 0 4 0 4", "create_atoms 1 region b", "mass 1 1.0",
                           "region right block 2 4 INF INF INF INF", "group right region right",
                           "pair_style morse/spline cut 1.2", "pair_coeff * * 1.0 6.0 1.0",
                           "neighbor 0.2 bin", "compute d all dust",
                           "thermo_style custom step c_d[5] c_d[6]", "run 0"])
        natoms = lmp.get_natoms()
        largest, fragments = lmp.extract_compute("d", 0, 1)[4], lmp.extract_compute("d", 0, 1)[5]
        assert largest == natoms and fragments == 1
        lmp.commands_list([change, "run 0"])
        largest, fragments = lmp.extract_compute("d", 0, 1)[4], lmp.extract_compute("d", 0, 1)[5]
        if change.startswith("delete"):
            assert largest == lmp.get_natoms() < natoms and fragments == 1
        else:
            assert fragments == 2 and largest < natoms


@pytest.mark.parametrize("between", ["run 0", ""])
def test_an_atom_created_with_a_deleted_atoms_id_is_not_linked(between):
    """Delete atom 2 of a linked dimer, create an atom that gets ID 2 again 1.15 a from atom 1
    (beyond L a = 1.05): no link, with or without a run between the commands (was, without:
    the new atom inherited the deleted atom's link)."""
    with session() as lmp:
        lmp.commands_list(morse_dimer(atom_map=True) + [
            "compute l all links/atom", "compute ls all reduce sum c_l", "run 0 post no",
            "group two id 2",
            "delete_atoms group two", between, "create_atoms 1 single 0 1.15 0 units box",
            "run 0 post no"])
        links = lmp.numpy.extract_compute("ls", 0, 0)
        ids = sorted(lmp.numpy.extract_atom("id")[:2])
    assert ids == [1, 2]
    assert links == 0


# ---------------------------------------------------------------- cumulative totals

# a hot periodic block of 108 elements in which links break and weld, damage and slide
MCA = """units lj
atom_style sphere
boundary p p p
comm_modify vel yes
lattice fcc $(sqrt(2.0))
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
set group all diameter 1.0
pair_style mca fraction 0.74048 tolerance 0.02
pair_coeff 1 1 young 1.0 poisson 0.3 {material}
set group all density 1.35
velocity all create 0.005 4711 loop geom
neighbor 0.2 bin
fix move all nve/sphere
timestep 0.02
compute pp all pair mca
"""
MCA_AGAIN = """comm_modify vel yes
neighbor 0.2 bin
fix move all nve/sphere
timestep 0.02
compute pp all pair mca
"""
# the elements' plastic strain lives in a fix property/atom that pair mca makes at its init
PLASTIC = """run 0 post no
compute ep all property/atom d_mca_plastic_strain
compute eps all reduce sum c_ep
"""
SPLINE = "\n".join(morse_fcc(3, "morse/spline cut 1.2 link 1.05 relink yes", noise=0, skin=0.2) + [
    "velocity all create 3.0 4928 loop geom", "fix 1 all nve", "timestep 0.002",
    "compute p all pair morse/spline", ""])
SPLINE_AGAIN = "neighbor 0.2 bin\nfix 1 all nve\ntimestep 0.002\ncompute p all pair morse/spline\n"
# every total, each nonzero in its scene: (input, the totals, what restart files do not carry,
# N, M, the tolerance of a run resumed from a restart file against the straight one: a setup
# after a change of state parts pair mca's runs, doc/pair_mca.rst, measured 6e-5)
TOTALS = {
    "mca-broken-formed-energy-damage-friction": (
        MCA.format(material="strength 0.02 damage 0.01 friction 0.3 weld 0.01"),
        ["c_pp[1]", "c_pp[2]", "c_pp[3]", "c_pp[4]", "c_pp[6]"], MCA_AGAIN, 200, 200, 1e-3),
    "mca-plastic": (MCA.format(material="yield 0.03") + PLASTIC, ["c_pp[5]", "c_eps"],
                    MCA_AGAIN + PLASTIC, 200, 200, 1e-12),
    "spline-broken-formed-energy": (SPLINE, ["c_p[1]", "c_p[2]", "c_p[3]"], SPLINE_AGAIN,
                                    150, 150, 1e-12),
}
EXACT = 1e-12    # the same sums in another order (2 ranks)


@pytest.fixture(scope="module")
def totals(tmp_path_factory):
    runs = {}

    def of(scene, nprocs):
        if (scene, nprocs) not in runs:
            runs[scene, nprocs] = carried_totals(tmp_path_factory.mktemp(scene), *TOTALS[scene][:5],
                                                 nprocs=nprocs)
        return runs[scene, nprocs]
    return of


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("scene", list(TOTALS))
def test_totals_carry_across_run_boundaries(totals, scene, nprocs):
    """run N + run M (pre no: no setup between, the straight run's steps) ends with the totals
    of run N+M, and a run 0 (a setup) at the boundary keeps them: each total is carried from
    one run to the next."""
    r = totals(scene, nprocs)
    assert np.all(r["straight_n"] != 0) and np.all(r["straight_nm"] != r["straight_n"])
    assert r["split_n"] == pytest.approx(r["straight_n"], rel=EXACT)
    assert r["split_nm"] == pytest.approx(r["straight_nm"], rel=EXACT)
    assert r["boundary"] == pytest.approx(r["split_nm"], rel=EXACT)


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("scene", list(TOTALS))
def test_totals_survive_restart_files(totals, scene, nprocs):
    """A restart file written between runs, or during one (restart N), read in a fresh
    instance: the totals read back are those of the uninterrupted run at that step, and the
    run that wrote a file mid-run keeps them too; a run resumed from the file ends with the
    uninterrupted run's totals."""
    r = totals(scene, nprocs)
    assert r["read_nm"] == pytest.approx(r["straight_nm"], rel=EXACT)
    assert r["mid_nm"] == pytest.approx(r["straight_nm"], rel=EXACT)
    assert r["read_n"] == pytest.approx(r["straight_n"], rel=EXACT)
    assert r["resumed_nm"] == pytest.approx(r["straight_nm"], rel=TOTALS[scene][5])


def memory_mb(out):
    """The ranks' mean of each 'Per MPI rank memory allocation' report of a run, MB."""
    return [float(m) for m in re.findall(
        r"Per MPI rank memory allocation \(min/avg/max\) = \S+ \| (\S+) \|", out)]


def mca_block(extra=""):
    return f"plugin load {PLUGIN}\n" + MCA_FCC_BLOCK.format(newton="on", dt=0.01) + extra


LINK_COUNT = "compute l all links/atom\ncompute ls all reduce sum c_l\n" \
    "thermo_style custom step pe c_ls\nthermo_modify norm no format float %.15g\n"


@pytest.mark.parametrize("nprocs", [1, 2])
def test_the_pair_states_pages_are_small(tmp_path, nprocs):
    """fix PAIR_STATE's pages hold 256 kB (or one atom's neigh_modify one pairs), not
    FixNeighHistory's neigh_modify page pairs (14.4 MB for pair mca's 18 saved doubles, two
    such kinds of page: 29 MB): the linked block of 256 elements reports at most 8 MB per rank
    more than the same block under pair_style zero (LAMMPS's atoms and list alone); its pages
    (six kinds, the slots' and the spare rows' pools), state and per-element arrays, ghosts
    included, are 5.5 MB."""
    zero = mca_block().replace("pair_style mca fraction ${phi} tolerance 0.02",
                               "pair_style zero 1.275").replace(
        "pair_coeff 1 1 young 1.0 poisson 0.4", "pair_coeff * *")
    assert "pair_style zero" in zero and "young" not in zero
    mca = memory_mb(run_lmp(tmp_path, mca_block("run 0\n"), nprocs))
    base = memory_mb(run_lmp(tmp_path, zero + "run 0\n", nprocs))
    assert len(mca) == len(base) == 1
    assert 0.3 < mca[0] - base[0] < 8.0


@pytest.mark.parametrize("nprocs", [1, 2])
def test_neigh_modify_between_runs_keeps_the_saved_pairs(tmp_path, nprocs):
    """neigh_modify one or page changed between runs makes FixNeighHistory free its pages and
    make new ones (it crashed, or lost links without a word, before the saved pairs were carried
    over): the split run equals the straight one to the last digit, every link kept; a `one`
    below what an atom keeps is refused, naming it, between runs and when a restart file is
    read."""
    hot = LINK_COUNT + "run 200\n"
    straight = mca_block(hot + "run 200\n" + report("s"))
    for change in ("neigh_modify one 3000", "neigh_modify page 200000", "neigh_modify one 1500 page 30000"):
        split = mca_block(hot + change + "\nrun 200\n" + report("a"))
        s = results(run_lmp(tmp_path, straight.replace("c_p[1]", "0").replace("c_diff", "0"),
                            nprocs))
        a = results(run_lmp(tmp_path, split.replace("c_p[1]", "0").replace("c_diff", "0"), nprocs))
        assert s["slinks"] > 3000 and a["alinks"] == s["slinks"], change
        assert a["ape"] == s["spe"], change
    tight = mca_block(hot + "neigh_modify one 3 page 300\nrun 0\n")
    err = subprocess.run([LMP, "-log", "none", "-nocite"], input=tight,
                         capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert "PAIR_STATE: an atom keeps" in err.stdout and "boost neigh_modify one" in err.stdout, \
        err.stdout[-2000:]
    assert "Segmentation" not in err.stdout + err.stderr
    # a restart file read with a `one` below what an atom keeps: refused, not written through a
    # null page
    restart = mca_block("run 20\nwrite_restart few.restart\nclear\n"
                        f"plugin load {PLUGIN}\nneigh_modify one 3 page 300\n"
                        "read_restart few.restart\nrun 0\n")
    err = subprocess.run([LMP, "-log", "none", "-nocite"], input=restart,
                         capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert "restart file keeps" in err.stdout and "boost neigh_modify one" in err.stdout, \
        err.stdout[-2000:]
