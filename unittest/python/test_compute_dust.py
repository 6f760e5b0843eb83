"""compute dust: the fragment partition equals compute cluster/atom (random and fractured
configurations, serial and MPI), constructed scenes with known answers, maxsize, masses,
groups, dump local, three types bonded at each type pair's cutoff atom by atom against a numpy
bond graph, bad input (and the table of hostile input, conftest.InputTable)."""
import numpy as np
import pytest
from conftest import (OK, PLUGIN, SCENE_BOX, SCENE_EMPTY, SCENE_LINKED, SCENE_MORSE, SCENE_NOBOX,
                      SI_CLUSTERS, InputTable, check_input, fcc_density, last_thermo, morse_fcc,
                      run_lmp, scene_dimer, scene_pair, scene_unit_dimer, session)

# an fcc block stretched to nearest neighbours at 1.3 and shaken (+-0.12): bonds (< 1.25)
# survive at random, leaving a body, fragments and loose atoms
FRACTURED = ["units lj", "atom_modify map array", f"lattice fcc {fcc_density(1.3)!r}",
             "region box block 0 8 0 8 0 8", "create_box 1 box", "create_atoms 1 box",
             "mass 1 1.0", "reset_atoms id sort yes",
             "displace_atoms all random 0.12 0.12 0.12 99 units box",
             "pair_style morse/spline cut 1.25", "pair_coeff * * 1.0 6.0 1.0", "neighbor 0.3 bin"]

VECTOR = ["dust", "dustfrag", "dustmass", "dustfrac", "body", "nfrag"]


def evaluate(lmp, extra="", cid="d"):
    lmp.commands_list([f"compute {cid} all dust {extra}".strip(), "run 0 post no"])
    vec = dict(zip(VECTOR, lmp.numpy.extract_compute(cid, 0, 1)[:6].copy()))
    per = np.array(lmp.gather(f"c_{cid}", 1, 3)).reshape(-1, 3)
    return vec, per


def gas(lmp, n=400, box=10.0, seed=7, mass="mass 1 1.0", atom_map=True):
    lmp.commands_list(without_map([
        "units lj", "atom_modify map array", f"region box block 0 {box} 0 {box} 0 {box}",
        "create_box 1 box", f"create_atoms 1 random {n} {seed} NULL overlap 0.5", mass,
        "pair_style lj/cut 1.4", "pair_coeff * * 1.0 1.0", "neighbor 0.3 bin"], atom_map))


def without_map(commands, atom_map):
    """The commands, without `atom_modify map array` unless atom_map: compute dust builds
    what it needs itself, as compute cluster/atom does."""
    return [c for c in commands if atom_map or c != "atom_modify map array"]


@pytest.mark.parametrize("atom_map", [True, False], ids=["map", "nomap"])
@pytest.mark.parametrize("scene", ["gas", "fractured"])
def test_partition_equals_cluster_atom(scene, atom_map):
    with session() as lmp:
        if scene == "gas":
            gas(lmp, atom_map=atom_map)
        else:
            lmp.commands_list(without_map(FRACTURED, atom_map))
        lmp.commands_list(["compute ca all cluster/atom 1.4" if scene == "gas"
                           else "compute ca all cluster/atom 1.25", "dump 1 all custom 1 /dev/null c_ca"])
        vec, per = evaluate(lmp)
        ca = np.array(lmp.gather("c_ca", 1, 1))
    assert np.array_equal(per[:, 0], ca)
    ids, sizes = np.unique(ca, return_counts=True)
    assert vec["nfrag"] == len(ids) > 2 and vec["body"] == sizes.max()
    assert vec["dust"] == len(ca) - sizes.max()
    body = ids[np.argmax(sizes)]
    assert np.array_equal(per[:, 2], (ca != body).astype(float))
    assert np.array_equal(per[:, 1], sizes[np.searchsorted(ids, ca)].astype(float))


def single_atoms(lmp, positions, box=(0, 10), boundary="p p p", masses=None):
    lo, hi = box
    lmp.commands_list(["units lj", "atom_modify map array", f"boundary {boundary}",
                       f"region box block {lo} {hi} {lo} {hi} {lo} {hi}", "create_box 2 box",
                       "mass 1 1.0", "mass 2 3.0", "pair_style zero 1.0", "pair_coeff * *",
                       "neighbor 0.3 bin"])
    for k, p in enumerate(positions):
        t = masses[k] if masses else 1
        lmp.command(f"create_atoms {t} single {p[0]} {p[1]} {p[2]} units box")


def test_isolated_particles_and_dimers():
    pos = [(1, 1, 1), (5, 5, 5), (8, 2, 2), (3, 7, 7), (3.9, 7, 7), (6, 1, 8), (6, 1.5, 8)]
    with session() as lmp:
        single_atoms(lmp, pos)
        vec, per = evaluate(lmp)
    # fragments: 3 singles, 2 dimers; the body is the first dimer (sizes tie: smallest ID)
    assert vec["nfrag"] == 5 and vec["body"] == 2
    assert vec["dust"] == 5 and vec["dustfrag"] == 4
    assert list(per[:, 0]) == [1, 2, 3, 4, 4, 6, 6]
    assert list(per[:, 1]) == [1, 1, 1, 2, 2, 2, 2]
    assert list(per[:, 2]) == [1, 1, 1, 0, 0, 1, 1]


def test_chain_across_the_periodic_boundary_is_one_fragment():
    # atoms at x = 7.5 ... 9.9 and 0.3 ... 2.7 (wrapped): bonded through the boundary at 10
    pos = [((7.5 + 0.8 * k) % 10, 5, 5) for k in range(7)] + [(5, 5, 5)]
    with session() as lmp:
        single_atoms(lmp, pos)
        vec, per = evaluate(lmp)
    assert vec["nfrag"] == 2 and vec["body"] == 7 and vec["dust"] == 1
    assert list(per[:7, 0]) == [1] * 7 and per[7, 0] == 8 and per[7, 2] == 1
    with session() as lmp:  # the same atoms without periodicity: two pieces of chain
        single_atoms(lmp, pos, boundary="f f f")
        vec, _ = evaluate(lmp)
    assert vec["nfrag"] == 3 and vec["body"] == 4


def test_body_with_dust_on_both_sides_maxsize_and_masses():
    # a 4x4x4 block in the middle, a single and a dimer on the left, a trimer on the right
    block = [(4 + i * 0.5, 4 + j * 0.5, 4 + k * 0.5) for i in range(4) for j in range(4) for k in range(4)]
    left = [(1, 5, 5), (2.0, 5, 5), (2.6, 5, 5)]   # (1), (2.0, 2.6)
    right = [(7.5, 5, 5), (8.2, 5, 5), (8.9, 5, 5)]
    pos = block + left + right
    types = [1] * 64 + [2, 2, 1, 1, 1, 2]           # type 2 has mass 3
    with session() as lmp:
        single_atoms(lmp, pos, masses=types)
        vec, per = evaluate(lmp)
        vec2, per2 = evaluate(lmp, "maxsize 2", "d2")
    assert vec["nfrag"] == 4 and vec["body"] == 64 and vec["dust"] == 6
    dust_mass = 3 + (3 + 1) + (1 + 1 + 3)
    assert vec["dustmass"] == dust_mass
    assert vec["dustfrac"] == pytest.approx(dust_mass / (64 + dust_mass), rel=1e-15)
    assert list(per[64:, 2]) == [1] * 6
    # maxsize 2: the trimer is not dust any more
    assert vec2["dust"] == 3 and vec2["dustfrag"] == 2 and vec2["dustmass"] == 3 + 3 + 1
    assert list(per2[64:, 2]) == [1, 1, 1, 0, 0, 0]


def test_per_atom_masses():
    with session() as lmp:
        lmp.command("atom_style sphere")
        single_atoms_cmds = ["units lj", "atom_modify map array", "region box block 0 10 0 10 0 10",
                             "create_box 1 box", "create_atoms 1 single 1 1 1",
                             "create_atoms 1 single 5 5 5", "create_atoms 1 single 5.5 5 5",
                             "set atom 1 mass 2.5", "set atom 2 mass 1.0", "set atom 3 mass 1.5",
                             "pair_style zero 1.0", "pair_coeff * *", "neighbor 0.3 bin"]
        lmp.commands_list(single_atoms_cmds)
        vec, _ = evaluate(lmp)
    assert vec["dust"] == 1 and vec["dustmass"] == 2.5 and vec["dustfrac"] == 0.5


def test_group_atoms_only_and_no_bonds_through_others():
    # a chain of 5 whose middle atom is not in the group: two fragments of 2
    pos = [(1 + 0.8 * k, 5, 5) for k in range(5)]
    with session() as lmp:
        single_atoms(lmp, pos)
        lmp.commands_list(["group some id 1 2 4 5"])
        lmp.commands_list(["compute d some dust", "run 0 post no"])
        vec = lmp.numpy.extract_compute("d", 0, 1)[:6].copy()
        per = np.array(lmp.gather("c_d", 1, 3)).reshape(-1, 3)
    assert list(vec) == [2, 1, 2, 0.5, 2, 2]
    assert list(per[:, 0]) == [1, 1, 0, 4, 4] and per[2, 1] == 0 and per[2, 2] == 0


def test_cutoff_keyword_overrides_the_pair_cutoffs():
    pos = [(1, 5, 5), (2.2, 5, 5), (3.4, 5, 5)]
    with session() as lmp:
        single_atoms(lmp, pos)  # pair zero 1.0: all apart
        vec, _ = evaluate(lmp)
        vec2, _ = evaluate(lmp, "cutoff 1.25", "d2")
    assert vec["nfrag"] == 3 and vec2["nfrag"] == 1


@pytest.mark.parametrize("nprocs", [2, 4])
def test_mpi_equals_serial_and_cluster_atom(tmp_path, nprocs):
    script = "\n".join([
        f"plugin load {PLUGIN}", *FRACTURED,
        "compute d all dust", "compute ca all cluster/atom 1.25",
        "variable diff atom abs(c_d[1]-c_ca)", "compute maxdiff all reduce max v_diff",
        "variable sid atom c_d[1]*c_d[3]", "compute idsum all reduce sum v_sid",
        "thermo_style custom step c_d[1] c_d[2] c_d[5] c_d[6] c_maxdiff c_idsum",
        "thermo_modify format float %.15g", "run 0"])
    cols = ["c_d[1]", "c_d[2]", "c_d[5]", "c_d[6]", "c_maxdiff", "c_idsum"]
    serial = last_thermo(run_lmp(tmp_path, script), cols)
    parallel = last_thermo(run_lmp(tmp_path, script, nprocs), cols)
    assert serial[3] > 10 and serial[4] == 0 and parallel[4] == 0
    assert parallel == serial


BAD = [
    ("cutoff 0", "cutoff must be > 0"),
    ("maxsize 0", "maxsize must be >= 1"),
    ("cutoff", "keyword cutoff needs a value"),
    ("size 3", "unknown keyword 'size'"),
    ("foo", "unknown keyword 'foo'"),    # last on the line: unknown, not "needs a value"
    ("links foo", "unknown keyword 'foo'"),
    ("rows body", "rows must be all or dust"),
]


@pytest.mark.parametrize("args,message", BAD)
def test_bad_arguments(args, message):
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 6 0 6 0 6", "create_box 1 box"])
        with pytest.raises(Exception, match=message):
            lmp.command(f"compute d all dust {args}")


def test_bad_setups():
    with session() as lmp:
        single_atoms(lmp, [(1, 1, 1)])
        lmp.commands_list(["compute d all dust cutoff 5.0", "thermo_style custom step c_d[1]"])
        with pytest.raises(Exception, match="exceeds the ghost atom range .* comm_modify cutoff"):
            lmp.command("run 0")
    with session() as lmp:
        lmp.commands_list(["units lj", "atom_modify map array", "region box block 0 6 0 6 0 6",
                           "create_box 1 box", "mass 1 1.0", "compute d all dust",
                           "thermo_style custom step c_d[1]"])
        with pytest.raises(Exception, match="needs a pair style"):
            lmp.command("run 0")


@pytest.mark.parametrize("atom_map", [True, False], ids=["map", "nomap"])
@pytest.mark.parametrize("nprocs", [1, 2, 4])
def test_ring_through_processor_and_periodic_boundaries_is_one_fragment(tmp_path, nprocs, atom_map):
    """A chain along x that crosses every processor boundary and closes through the periodic
    one, plus one loose atom: two fragments on any number of processors, with or without an
    atom map (images of one atom are joined by ID either way)."""
    lines = [f"plugin load {PLUGIN}", "units lj", "atom_modify map array" if atom_map else "",
             "processors * 1 1",
             "region box block 0 36 0 4 0 4", "create_box 1 box", "mass 1 1.0",
             "pair_style zero 1.0", "pair_coeff * *", "neighbor 0.3 bin"]
    lines += [f"create_atoms 1 single {0.45 + 0.9 * k!r} 2 2 units box" for k in range(40)]
    lines += ["create_atoms 1 single 18 3.5 2 units box", "compute d all dust",
              "variable one atom c_d[1]==1", "compute inring all reduce sum v_one",
              "thermo_style custom step c_d[5] c_d[6] c_d[1] c_inring", "thermo_modify norm no",
              "run 0"]
    body, nfrag, dust, inring = last_thermo(run_lmp(tmp_path, "\n".join(lines), nprocs),
                                            ["c_d[5]", "c_d[6]", "c_d[1]", "c_inring"])
    assert (body, nfrag, dust, inring) == (40, 2, 1, 40)


# the fractured block with two masses, shifted across the periodic boundaries (image flags),
# with random velocities: fragments with distinct masses, centres and velocities
MOVING = FRACTURED[:4] + ["create_box 2 box", "create_atoms 1 box", "mass 1 1.0", "mass 2 2.5",
                          "set type 1 type/fraction 2 0.3 5"] + FRACTURED[7:] + [
    "displace_atoms all move 3.3 1.7 -2.2 units box", "velocity all create 0.3 17 loop geom mom no"]
COLS = ["id", "size", "mass", "x", "y", "z", "vx", "vy", "vz", "dust"]


def local_rows(lmp, cid):
    rows = lmp.numpy.extract_compute(cid, 2, 2)
    return np.array(rows, dtype=float).reshape(-1, len(COLS))


def test_local_rows_equal_stock_chunk_computes():
    """One local row per fragment: ID, size, mass, centre of mass (unwrapped) and its velocity,
    dust flag, equal to compute cluster/atom chunks with com/chunk, vcm/chunk and
    property/chunk; `rows dust` keeps the dust rows only."""
    with session() as lmp:
        lmp.commands_list(MOVING)
        lmp.commands_list([
            "compute d all dust", "compute dd all dust rows dust",
            "compute ca all cluster/atom 1.25",
            "compute cc all chunk/atom c_ca compress yes nchunk every",
            "compute com all com/chunk cc", "compute vcm all vcm/chunk cc",
            "compute n all property/chunk cc count id",
            "variable m atom mass", "compute mass all reduce sum v_m",
            "fix f all ave/chunk 1 1 1 cc mass norm none",
            "thermo_style custom step c_d[1] c_dd[1]", "run 0 post no"])
        rows, dustrows = local_rows(lmp, "d"), local_rows(lmp, "dd")
        vec = lmp.numpy.extract_compute("d", 0, 1)[:6].copy()
        nchunk = lmp.extract_compute("cc", 0, 0)
        com = np.array([[lmp.extract_compute("com", 0, 2)[c][k] for k in range(3)]
                        for c in range(int(nchunk))])
        vcm = np.array([[lmp.extract_compute("vcm", 0, 2)[c][k] for k in range(3)]
                        for c in range(int(nchunk))])
        counts = np.array([lmp.extract_compute("n", 0, 2)[c][0] for c in range(int(nchunk))])
        ids = np.array([lmp.extract_compute("n", 0, 2)[c][1] for c in range(int(nchunk))])
        masses = np.array([lmp.extract_fix("f", 0, 2, c, 2) for c in range(int(nchunk))])
        boxmass = lmp.extract_compute("mass", 0, 0)
        images = np.array(lmp.gather_atoms("image", 0, 1))
    assert np.any(images != 512 * (1 + 1024 + 1024 ** 2))    # some atoms crossed a boundary
    assert len(rows) == nchunk == vec[5] > 10
    rows = rows[np.argsort(rows[:, 0])]
    assert np.array_equal(rows[:, 0], ids) and np.array_equal(rows[:, 1], counts)
    assert rows[:, 2] == pytest.approx(masses, rel=1e-14)
    assert rows[:, 3:6] == pytest.approx(com, rel=1e-12, abs=1e-12)
    assert rows[:, 6:9] == pytest.approx(vcm, rel=1e-12, abs=1e-14)
    assert len(np.unique(rows[:, 2])) > 3    # fragments of both masses
    body = np.argmax(rows[:, 1])
    assert rows[body, 9] == 0 and np.all(np.delete(rows[:, 9], body) == 1)
    assert rows[:, 2].sum() == pytest.approx(boxmass, rel=1e-14)
    assert np.array_equal(dustrows[np.argsort(dustrows[:, 0])], np.delete(rows, body, axis=0))
    assert dustrows[:, 2].sum() == pytest.approx(vec[2], rel=1e-14)


def test_local_rows_feed_stock_histograms():
    """The fragment size distribution and the dust's mass against velocity are stock one-liners:
    fix ave/histo on the size column, fix ave/histo/weight on vx weighted by mass."""
    with session() as lmp:
        lmp.commands_list(MOVING)
        lmp.commands_list([
            "compute d all dust", "compute dd all dust rows dust",
            "fix sizes all ave/histo 1 1 1 0.5 20.5 20 c_d[2] mode vector kind local",
            "fix spectrum all ave/histo/weight 1 1 1 -2 2 8 c_dd[7] c_dd[3] mode vector "
            "kind local", "run 0 post no"])
        rows, dustrows = local_rows(lmp, "d"), local_rows(lmp, "dd")
        sizes = [lmp.extract_fix("sizes", 0, 2, b, 1) for b in range(20)]
        spectrum = [lmp.extract_fix("spectrum", 0, 2, b, 1) for b in range(8)]
    expect, _ = np.histogram(rows[:, 1], bins=np.linspace(0.5, 20.5, 21))
    assert np.array_equal(sizes, expect) and sum(sizes) > 10
    mass, _ = np.histogram(dustrows[:, 6], bins=np.linspace(-2, 2, 9), weights=dustrows[:, 2])
    assert spectrum == pytest.approx(mass, rel=1e-12)


@pytest.mark.parametrize("nprocs", [1, 2, 4])
def test_local_rows_sum_to_group_mass_and_momentum(tmp_path, nprocs):
    """dump local of the fragments on 1, 2 and 4 ranks: the masses add to the group's mass,
    the momenta to its momentum, and the rows are the serial ones."""
    script = "\n".join([
        f"plugin load {PLUGIN}", *MOVING, "compute d all dust",
        "dump rows all local 1 rows.txt c_d[1] c_d[2] c_d[3] c_d[4] c_d[5] c_d[6] c_d[7] "
        "c_d[8] c_d[9] c_d[10]", "dump_modify rows format float %.17g",
        "variable M equal mass(all)",
        "variable px equal vcm(all,x)*v_M", "variable py equal vcm(all,y)*v_M",
        "variable pz equal vcm(all,z)*v_M",
        "thermo_style custom step v_M v_px v_py v_pz", "thermo_modify format float %.17g",
        "run 0"])
    M, *p = last_thermo(run_lmp(tmp_path, script, nprocs), ["v_M", "v_px", "v_py", "v_pz"])
    rows = np.loadtxt(tmp_path / "rows.txt", skiprows=9)
    assert len(rows) > 10 and len(np.unique(rows[:, 0])) == len(rows)
    assert rows[:, 2].sum() == pytest.approx(M, rel=1e-14)
    momentum = (rows[:, 2:3] * rows[:, 6:9]).sum(axis=0)
    assert momentum == pytest.approx(p, abs=1e-12 * M)
    assert np.abs(p).max() > 1e-3 * M    # not the trivial zero
    serial_file = tmp_path / f"serial{nprocs}.txt"
    if nprocs > 1:
        run_lmp(tmp_path, script.replace("rows.txt", serial_file.name))
        serial = np.loadtxt(serial_file, skiprows=9)
        order, sorder = np.argsort(rows[:, 0]), np.argsort(serial[:, 0])
        assert rows[order] == pytest.approx(serial[sorder], rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("units,length,mass,speed", [("si", 1e-5, 2.3e-12, 1e3),
                                                      ("metal", 2.5, 26.98, 10.0)])
def test_local_rows_carry_mass_position_velocity_units(units, length, mass, speed):
    """A dimer of two masses and a single atom, with velocities, in units si (aluminium
    clusters) and metal (aluminium atoms): the rows are the closed-form centre of mass and
    its velocity, in the style's own units."""
    with session() as lmp:
        lmp.commands_list([
            f"units {units}", "atom_modify map array",
            f"region box block 0 {10 * length!r} 0 {10 * length!r} 0 {10 * length!r} units box",
            "create_box 2 box", f"mass 1 {mass!r}", f"mass 2 {3 * mass!r}",
            f"pair_style zero {1.2 * length!r}", "pair_coeff * *",
            f"neighbor {0.2 * length!r} bin",
            f"create_atoms 1 single {2 * length!r} {2 * length!r} {2 * length!r} units box",
            f"create_atoms 2 single {3 * length!r} {2 * length!r} {2 * length!r} units box",
            f"create_atoms 1 single {7 * length!r} {7 * length!r} {7 * length!r} units box",
            "group first id 1", "group second id 2", "group third id 3",
            f"velocity first set {speed!r} 0 0 units box",
            f"velocity second set {-speed!r} {speed!r} 0 units box",
            f"velocity third set 0 0 {2 * speed!r} units box",
            "compute d all dust", "run 0 post no"])
        rows = local_rows(lmp, "d")
    rows = rows[np.argsort(rows[:, 0])]
    dimer = [1, 2, 4 * mass, 2.75 * length, 2 * length, 2 * length,
             -0.5 * speed, 0.75 * speed, 0.0, 0]
    single = [3, 1, mass, 7 * length, 7 * length, 7 * length, 0.0, 0.0, 2 * speed, 1]
    assert rows == pytest.approx(np.array([dimer, single]), rel=1e-14, abs=1e-14 * speed)


@pytest.mark.parametrize("units,unit,law", [("lj", 1.0, "1.0 6.0"),
                                             ("si", 1.0e-5, "2.46e-6 3.76e5")])
def test_bond_distances_follow_fix_adapt(units, unit, law):
    """Two atoms 1.2 a apart under morse/spline cut 1.3 (bond distance Rc a = 1.3 a): one
    fragment; fix adapt setting a = 0.9 makes the bond distance 1.17 a and the pair two
    fragments, as pair_coeff a = 0.9 does (the pair's cutoffs as they are at each evaluation)."""
    counts = {}
    for case, a, adapt in [("a 1", 1.0, False), ("a 0.9", 0.9, False), ("adapt 0.9", 1.0, True)]:
        with session() as lmp:
            lmp.commands_list([
                f"units {units}", "atom_modify map array",
                f"region box block 0 {10 * unit!r} 0 {10 * unit!r} 0 {10 * unit!r}",
                "create_box 1 box", "mass 1 1.0", f"neighbor {0.3 * unit!r} bin",
                f"create_atoms 1 single {unit!r} {5 * unit!r} {5 * unit!r} units box",
                f"create_atoms 1 single {2.2 * unit!r} {5 * unit!r} {5 * unit!r} units box",
                "pair_style morse/spline cut 1.3", f"pair_coeff * * {law} {a * unit!r}"])
            if adapt:
                lmp.commands_list([f"variable k equal {0.9 * unit!r}",
                                   "fix ad all adapt 1 pair morse/spline a * * v_k"])
            vec, _ = evaluate(lmp)
        counts[case] = vec["nfrag"]
    assert counts == {"a 1": 1, "a 0.9": 2, "adapt 0.9": 2}


def test_its_own_cutoff_checks_the_neighbor_skin():
    """the default skin of units si (1 mm) at cluster scale, with the compute's own cutoff"""
    with session() as lmp:
        lmp.commands_list(SI_CLUSTERS + ["pair_style zero 1.2e-5", "pair_coeff * *",
                                         "neighbor 1e-3 bin", "compute d all dust cutoff 1.2e-5",
                                         "fix nve all nve", "thermo_style custom step c_d[1]"])
        with pytest.raises(Exception, match="Compute dust: neighbor skin"):
            lmp.command("run 0")


def test_dump_local_names_the_ten_local_columns(tmp_path):
    """LAMMPS expands c_ID[*] of a compute that has per-atom and local outputs to its per-atom
    columns (3); doc/compute_dust.rst says to name the 10 local columns."""
    cols = " ".join(f"c_d[{k}]" for k in range(1, 11))
    block = morse_fcc(pair="morse/spline cut 1.2", noise=0)
    script = "\n".join([f"plugin load {PLUGIN}", *block]) + f"""
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


# ---------------------------------------------------------------- hostile input

INPUTS = InputTable()
row = INPUTS.row
row("nobox-compute-dust", SCENE_NOBOX, "compute d all dust",
    r"Run command before simulation box is defined")
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
    row(f"dust-{rid}", SCENE_MORSE, CD + args, expect, defect)

row("dust-rows-twice", SCENE_MORSE, CD + "rows all rows dust", r"keyword rows given twice")  # known
row("dust-cutoff-1e300", SCENE_MORSE, [CD + "cutoff 1e300"] + USE, r"exceeds the ghost atom range")
row("dust-links-no-link", SCENE_MORSE, [CD + "links"] + USE, r"links needs a pair style with link")
row("dust-no-pair", scene_dimer(), [CD.strip()] + USE,
    r"without the cutoff keyword it needs a pair style")
row("dust-no-pair-cutoff", scene_dimer(), [CD + "cutoff 1.2"] + USE, r"ghost|cutoff")
row("dust-empty-group", SCENE_MORSE, ["group none empty", "compute c none dust"] + USE, OK)
row("dust-zero-atoms", SCENE_BOX + scene_pair("morse/spline"), [CD.strip()] + USE, OK)
row("dust-links", SCENE_LINKED, [CD + "links maxsize 1 rows dust"] + USE, OK)
row("dust-units-si", scene_unit_dimer("si", "morse/spline"), [CD + "cutoff 1.2e-5"] + USE, OK)
row("run-link-to-lj-cut-dust", SCENE_LINKED, ["compute d all dust links",
                                              "thermo_style custom step pe press c_d[1]",
                                              "thermo_modify norm no", "run 0 post no",
                                              "pair_style lj/cut 1.5", "pair_coeff * * 1.0 1.0"],
    r"Compute dust links needs a pair style with link L")
# in an empty box
for rid, args, message in [
    ("unknown-keyword-foo", "foo", "unknown keyword 'foo'"),
    ("rows-twice-empty-box", "rows dust rows all", "Compute dust: keyword rows given twice"),
    ("links-twice-empty-box", "links links", "Compute dust: keyword links given twice"),
]:
    row(f"dust-{rid}", SCENE_EMPTY, "compute d all dust " + args, message)


@pytest.mark.parametrize("setup,cmds,expect,isolate", INPUTS.rows)
def test_hostile_input(setup, cmds, expect, isolate):
    check_input(setup, cmds, expect, isolate)


@pytest.mark.parametrize("units,scale", [("lj", 1.0), ("si", 1.0e-5)])
@pytest.mark.parametrize("first", [1, 2])
def test_two_types_bond_at_their_own_pair_cutoff(units, scale, first):
    """Three type pairs with three cutoffs (morse/spline cut 1.3: a = 1, 1.5, 2 for 1-1, 1-2,
    2-2: cutoffs 1.3, 1.95, 2.6): a type-1 and a type-2 atom 1.6 apart are one fragment by their
    own pair's cutoff, two atoms of type 1 1.6 apart are two (compute pair/params' oracle: the
    pair style's cutoffs; either type first)."""
    x = {first: 0.0, 3 - first: 1.6 * scale}
    with session() as lmp:
        lmp.commands_list([
            f"units {units}", "atom_modify map array",
            f"region box block {-5 * scale} {8 * scale} {-5 * scale} {5 * scale} {-5 * scale} "
            f"{5 * scale} units box", "create_box 2 box", "mass * 1.0",
            f"create_atoms {first} single {x[first]!r} 0 0 units box",
            f"create_atoms {3 - first} single {x[3 - first]!r} 0 0 units box",
            f"create_atoms 1 single {4.0 * scale!r} 0 0 units box",
            f"create_atoms 1 single {5.6 * scale!r} 0 0 units box",
            f"neighbor {0.3 * scale!r} bin", "pair_style morse/spline cut 1.3",
            f"pair_coeff 1 1 1.0 6.0 {scale!r}", f"pair_coeff 2 2 1.0 6.0 {2 * scale!r}",
            f"pair_coeff 1 2 1.0 6.0 {1.5 * scale!r}", "compute d all dust", "run 0 post no"])
        assert lmp.numpy.extract_compute("d", 0, 1)[5] == 3      # {1-2 pair}, {1}, {1}


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("units", ["lj", "si"])
@pytest.mark.parametrize("style", ["morse/spline cut 1.2", "lj/spline wagner"])
def test_three_types_per_atom_fragments_at_each_type_pairs_cutoff(tmp_path, style, units, nprocs):
    """Three types with masses m, 1.5 m, 2.5 m in a stretched, shaken block (nearest neighbours
    at 1.35 a, wagner 1.6 a, +- 0.12 a; the box 4.5 lattice periods + 0.3 a long): every type
    pair its own a,
    kappa and cutoff (cut: rc_ij a_ij from 1.17 a to 1.51 a; wagner: its end ac_ij, 1.40 a to 1.62
    a), so that the bond graph is cut at random and differently per type pair.  Atom by atom
    (by ID), the fragment ID, size and dust flag of compute dust, and of compute dust maxsize 3,
    against the components of the bond graph made in numpy at each type pair's distance; the
    global vector (counts, dust mass, its fraction of the group's) from the same components; on 1
    and 2 ranks."""
    from test_pair_spline_types import (PAIRS, RC, UNITS, block, dust_columns, fragments, laws,
                                        pairs_within)
    s, _, mass = UNITS[units]
    base = style.split("/")[0]
    law = laws(base, units)
    if "wagner" in style:
        cut = [law[p].wagner()[1] for p in PAIRS]
        extra = [""] * 6
    else:
        cut = [(RC[k] or 1.2) * law[p].a for k, p in enumerate(PAIRS)]
        extra = [f" rc {RC[k]}" if RC[k] else "" for k in range(6)]
    nn = 1.6 if "wagner" in style else 1.35
    script = [f"plugin load {PLUGIN}", *block(units, noise=0.12, nn=nn), f"pair_style {style}",
              *[f"pair_coeff {p[0]} {p[1]} {law[p].coeff()}{extra[k]}"
                for k, p in enumerate(PAIRS)],
              "compute d all dust", "compute d3 all dust maxsize 3",
              "thermo_style custom step " + " ".join(f"c_d[{k}] c_d3[{k}]" for k in range(1, 7)),
              "thermo_modify norm no format float %.17g", "run 0 post no",
              "write_dump all custom atoms.txt id type x y z c_d[1] c_d[2] c_d[3] c_d3[1] c_d3[2] "
              "c_d3[3] modify sort id format float %.17g", ""]
    out = run_lmp(tmp_path, "\n".join(script), nprocs)
    glob = last_thermo(out, [f"c_{c}[{k}]" for k in range(1, 7) for c in ("d", "d3")])
    rows = np.loadtxt(tmp_path / "atoms.txt", skiprows=9)
    lines = (tmp_path / "atoms.txt").read_text().splitlines()
    box = np.array([float(w[1]) - float(w[0]) for w in (l.split() for l in lines[5:8])])
    types, x = rows[:, 1].astype(int), rows[:, 2:5]
    i, j, _, r, k = pairs_within(x, types, box, max(cut))
    bonded = r < np.array(cut)[k]
    frag = fragments(len(x), i[bonded], j[bonded])
    expect = dust_columns(frag)
    assert np.array_equal(rows[:, 5:8], expect)
    ids, sizes = np.unique(frag, return_counts=True)
    assert len(ids) > 15 and sizes.max() > 100    # a cut graph: a body, fragments, single atoms
    size = expect[:, 1]
    assert np.array_equal(rows[:, 8:11], np.stack([frag, size, (size <= 3).astype(float)], axis=1))
    # the global vectors: dust atoms, dust fragments, dust mass, its fraction, body, fragments
    masses = mass * np.array([0.0, 1.0, 1.5, 2.5])[types]
    for flags, got in ((expect[:, 2], glob[0::2]), (size <= 3, glob[1::2])):
        flags = flags.astype(bool)
        want = [flags.sum(), len(np.unique(frag[flags])), masses[flags].sum(),
                masses[flags].sum() / masses.sum(), sizes.max(), len(ids)]
        assert got[:2] == want[:2] and got[4:] == want[4:]
        assert got[2:4] == pytest.approx(want[2:4], rel=1e-12)
    # one cutoff for all type pairs (pair 1 1's) would give other fragments
    one = r < cut[0]
    assert not np.array_equal(fragments(len(x), i[one], j[one]), frag)
