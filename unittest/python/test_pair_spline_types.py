"""The spline pair styles with three atom types, every type pair its own law parameters, kappa
and cutoff (pair_coeff 1 1, 1 2, 1 3, 2 2, 2 3 and 3 3 all differ), in a periodic box whose
length is not a whole multiple of the lattice period.  Atom by atom: forces, energies (compute
pe/atom) and virials (compute stress/atom) against stock LAMMPS styles given the same per-type-
pair cutoffs (morse, lj/cut, mie/cut; pair_style lepton with the spec's expression of each pair
for the tails and laws no stock style has; bond_style morse and harmonic for chain N), and
against a numpy oracle of the link rule (link L: links made at L a_ij, broken at Rc_ij a_ij,
unlinked pairs repelling below a_ij), with compute links/atom (stock compute coord/atom per type
at the setup that links) and compute dust links per atom; in units lj and si, the /omp variants
and 2 MPI ranks against the serial style."""
import math

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp, session
from spec_laws import Law

# the six type pairs and their parameters: D (units of E), a (units of s), alpha a, kappa, the
# per-pair rc (None: the style's Rc), the per-pair lagunov start rs (None: the style's), Mie n m
PAIRS = [(1, 1), (1, 2), (1, 3), (2, 2), (2, 3), (3, 3)]
DEPTH = [1.0, 0.8, 1.2, 1.3, 0.9, 0.7]
A = [1.0, 1.04, 0.97, 1.08, 1.02, 0.95]
ALPHA_A = [6.0, 5.0, 6.5, 5.5, 4.5, 7.0]
KAPPA = [1.0, 1.2, 0.9, 1.1, 1.3, 0.85]
RC = [None, 1.35, 1.25, 1.4, 1.15, 1.3]
RS = [None, 1.1, None, 1.12, 1.05, None]
MIE = [(12, 6), (10, 5), (9, 6), (14, 7), (8, 4), (20, 7)]
# unit styles: length s, energy E, mass of type 1 (types 2 and 3: 1.5 and 2.5 times it)
UNITS = {"lj": (1.0, 1.0, 1.0), "si": (1.0e-5, 2.46e-6, 2.338e-12)}
GAP = 0.3    # added to the box's x length (in s): 4.5 lattice periods + 0.3


def laws(base, units, kappa=True):
    """The Law of each type pair in the unit style."""
    s, e, _ = UNITS[units]
    return {p: Law(base, DEPTH[k] * e, A[k] * s, alpha=ALPHA_A[k] / (A[k] * s), n=MIE[k][0],
                   m=MIE[k][1], kappa=KAPPA[k] if kappa else 1.0) for k, p in enumerate(PAIRS)}


def block(units, noise=0.05, nn=1.0, skin=0.3, ntypes=3):
    """A periodic fcc block (nearest neighbours nn s) of 4.5 x 4 x 4 lattice periods with 0.3 s
    added along x: across the x boundary the planes face each other 1.007 s apart, not as in
    the lattice; three types at random (independent of the decomposition), shaken by noise s."""
    s, _, mass = UNITS[units]
    cell = math.sqrt(2) * nn * s
    lines = [f"units {units}", "atom_modify map array",
             f"lattice fcc {cell!r} origin 0.01 0.01 0.01" if units != "lj" else
             f"lattice fcc {4.0 / cell ** 3!r} origin 0.01 0.01 0.01",
             "region box block 0 4.5 0 4 0 4", f"create_box {ntypes} box", "create_atoms 1 box",
             f"mass 1 {mass!r}", *([f"mass 2 {1.5 * mass!r}", f"mass 3 {2.5 * mass!r}"]
                                   if ntypes == 3 else []), "reset_atoms id sort yes",
             f"change_box all x final 0 {4.5 * cell + GAP * s!r} units box"]
    if ntypes == 3:
        lines += ["set type 1 type/fraction 2 0.333 4811", "set type 1 type/fraction 3 0.5 4812"]
    return lines + [f"displace_atoms all random {noise * s!r} {noise * s!r} {noise * s!r} 4711 "
                    "units box", f"neighbor {skin * s!r} bin", "thermo_modify norm no"]


def tail_args(tail, rc, rs):
    return {"cut": f"cut {rc}", "wagner": "wagner",
            "lagunov": f"lagunov {rc}" + (f" start {rs}" if rs else "")}[tail]


class Case:
    """A law, its tail (style Rc, Rs), which per-pair keywords it gives, kappa or not, the
    oracle (stock or lepton) and pair_modify shift."""

    def __init__(self, base, tail, rc=None, rs=None, per_rc=True, per_rs=False, kappa=True,
                 oracle="lepton", shift="no"):
        self.base, self.tail, self.rc, self.rs = base, tail, rc, rs
        self.per_rc, self.per_rs, self.kappa, self.oracle, self.shift = (
            per_rc, per_rs, kappa, oracle, shift)

    def id(self):
        return (f"{self.base}-{self.tail}-{self.oracle}" + ("-kappa" if self.kappa else "") +
                ("-shift" if self.shift == "yes" else ""))

    def radii(self, k):
        """rc and rs of pair k in units of its a (None: the tail's own)."""
        rc = RC[k] if self.per_rc and RC[k] else self.rc
        rs = RS[k] if self.per_rs and RS[k] else self.rs
        return rc, rs

    def ours(self, units):
        """The plugin's pair_style and pair_coeff lines."""
        lines = [f"pair_style {self.base}/spline {tail_args(self.tail, self.rc, self.rs)}"]
        for k, (p, law) in enumerate(laws(self.base, units, self.kappa).items()):
            extra = (f" rc {RC[k]}" if self.per_rc and RC[k] else "") + \
                    (f" rs {RS[k]}" if self.per_rs and RS[k] else "")
            lines.append(f"pair_coeff {p[0]} {p[1]} {law.coeff()}{extra}")
        return lines + [f"pair_modify shift {self.shift}"]

    def stock(self, units):
        """The oracle's pair_style and pair_coeff lines, each pair with its own cutoff."""
        coeffs, cuts = [], []
        for k, (p, law) in enumerate(laws(self.base, units, self.kappa).items()):
            rc, rs = self.radii(k)
            if self.oracle == "lepton":
                expr, cut = law.lepton(self.tail, rc, rs)
                coeffs.append(f'pair_coeff {p[0]} {p[1]} "{expr}" {cut!r}')
            else:
                assert self.tail == "cut"
                cut = rc * law.a
                if self.base == "morse":
                    args = f"{law.D!r} {law.kappa * law.alpha!r} {law.a!r}"
                elif self.base == "lj":
                    assert law.kappa == 1.0
                    args = f"{law.D!r} {law.a * 2 ** (-1 / 6)!r}"
                else:
                    assert law.kappa == 1.0
                    sigma = law.a * (law.m / law.n) ** (1 / (law.n - law.m))
                    args = f"{law.D!r} {sigma!r} {law.n!r} {law.m!r}"
                coeffs.append(f"pair_coeff {p[0]} {p[1]} {args} {cut!r}")
            cuts.append(cut)
        style = {"lepton": "lepton", "stock": {"morse": "morse", "lj": "lj/cut",
                                               "mie": "mie/cut"}.get(self.base)}[self.oracle]
        return [f"pair_style {style} {max(cuts)!r}", *coeffs, f"pair_modify shift {self.shift}"]


CASES = [
    Case("morse", "cut", rc=1.2, oracle="stock"),
    Case("morse", "cut", rc=1.2, oracle="stock", shift="yes"),
    Case("lj", "cut", rc=1.25, kappa=False, oracle="stock"),                # no vector stage
    Case("mie", "cut", rc=1.25, kappa=False, oracle="stock", shift="yes"),
    Case("lj", "cut", rc=1.25),                                             # lj's kappa kernel
    Case("mie", "cut", rc=1.2, shift="yes"),
    Case("harmonic", "cut", rc=1.2),
    Case("harmonic", "lagunov", rc=1.3, rs=1.1, per_rs=True),
    Case("morse", "wagner", per_rc=False),
    Case("lj", "wagner", per_rc=False),
    Case("mie", "wagner", per_rc=False, kappa=False),
    Case("morse", "lagunov", rc=1.3, per_rs=True),                          # rs default: b_ij
    Case("lj", "lagunov", rc=1.35),
    Case("mie", "lagunov", rc=1.4, rs=1.05, per_rs=True),
]


def per_atom(lmp):
    """Forces, energies and virials (by atom ID) and the global pe and pressure tensor."""
    lmp.command("run 0 post no")
    f = np.array(lmp.gather_atoms("f", 1, 3)).reshape(-1, 3)
    pe = np.array(lmp.gather("c_epa", 1, 1))
    virial = np.array(lmp.gather("c_spa", 1, 6)).reshape(-1, 6)
    press = np.array([lmp.get_thermo(k) for k in ("pxx", "pyy", "pzz", "pxy", "pxz", "pyz")])
    return {"f": f, "pe": pe, "virial": virial, "pe_total": np.array([lmp.get_thermo("pe")]),
            "press": press}


def assert_same_per_atom(oracle, ours, rtol):
    """Each array atom by atom, to rtol of its largest entry (the virial column by column)."""
    for name, want in oracle.items():
        got = ours[name]
        assert got.shape == want.shape, name
        scale = np.max(np.abs(want), axis=0)
        assert np.all(scale > 0), name
        err = np.max(np.abs(got - want), axis=0)
        assert np.all(err <= rtol * scale), (name, err / scale)


def compare(case, units, suffix=None, newton="on"):
    """The oracle's per-atom values, then the plugin's (with suffix: its /omp variant on 2
    threads), in one instance on the same atoms."""
    with session() as lmp:
        if suffix:
            lmp.command("package omp 2")
        lmp.command(f"newton {newton}")
        lmp.commands_list(block(units) + ["compute epa all pe/atom",
                                          "compute spa all stress/atom NULL pair"])
        lmp.commands_list(case.stock(units))
        oracle = per_atom(lmp)
        if suffix:
            lmp.command(f"suffix {suffix}")
        lmp.commands_list(case.ours(units))
        ours = per_atom(lmp)
        types = np.array(lmp.gather_atoms("type", 0, 1))
    assert set(types) == {1, 2, 3}
    assert_same_per_atom(oracle, ours, 1e-12 if case.oracle == "stock" else 1e-10)


@pytest.mark.parametrize("units", list(UNITS))
@pytest.mark.parametrize("case", CASES, ids=[c.id() for c in CASES])
def test_three_types_per_atom_equal_the_oracle(case, units):
    compare(case, units)


@pytest.mark.parametrize("case", [CASES[0], CASES[2], CASES[4], CASES[7], CASES[10]],
                         ids=[CASES[k].id() for k in (0, 2, 4, 7, 10)])
def test_three_types_omp_variant_per_atom_equal_the_oracle(case):
    compare(case, "lj", suffix="omp")


@pytest.mark.parametrize("case", [CASES[1], CASES[9]], ids=[CASES[k].id() for k in (1, 9)])
def test_three_types_newton_off_per_atom_equal_the_oracle(case):
    compare(case, "si", newton="off")


def test_the_oracle_tells_the_type_pairs_apart():
    """The scene is not blind to the type pairs: pair 1 1's law and cutoff for all six moves
    the forces far beyond the tolerance, and so does the style's Rc for a pair that has rc."""
    case = CASES[0]
    with session() as lmp:
        lmp.commands_list(block("lj") + ["compute epa all pe/atom",
                                         "compute spa all stress/atom NULL pair"])
        lmp.commands_list(case.ours("lj"))
        right = per_atom(lmp)
        lmp.commands_list([case.ours("lj")[1].replace("pair_coeff 1 1", "pair_coeff * *")])
        same = per_atom(lmp)
        lmp.commands_list(case.ours("lj")[:-1])
        lmp.command(case.ours("lj")[4].split(" rc ")[0])    # pair 2 2 at the style's Rc
        global_rc = per_atom(lmp)
    for other in (same, global_rc):
        err = np.max(np.abs(other["f"] - right["f"]))
        assert err > 1e-3 * np.max(np.abs(right["f"]))


@pytest.mark.parametrize("case", [CASES[1], CASES[9], CASES[12]],
                         ids=[CASES[k].id() for k in (1, 9, 12)])
def test_two_ranks_give_the_serial_per_atom_values(tmp_path, case):
    """The same per-atom forces, energies and virials on 2 ranks (by atom ID), to round-off."""
    script = "\n".join([f"plugin load {PLUGIN}", *block("si"), *case.ours("si"),
                        "compute epa all pe/atom", "compute spa all stress/atom NULL pair",
                        "run 0 post no",
                        "write_dump all custom atoms.txt id fx fy fz c_epa c_spa[1] c_spa[2] "
                        "c_spa[3] c_spa[4] c_spa[5] c_spa[6] modify sort id format float %.17g",
                        ""])
    rows = {}
    for nprocs in (1, 2):
        folder = tmp_path / f"np{nprocs}"
        folder.mkdir()
        run_lmp(folder, script, nprocs)
        rows[nprocs] = np.loadtxt(folder / "atoms.txt", skiprows=9)
    assert np.array_equal(rows[1][:, 0], rows[2][:, 0])
    scale = np.max(np.abs(rows[1][:, 1:]), axis=0)
    assert np.all(np.max(np.abs(rows[2][:, 1:] - rows[1][:, 1:]), axis=0) <= 1e-12 * scale)


# ---------------------------------------------------------------- chain N against bonds

def chain_positions(units, count=26, seed=5):
    """Atoms in ID order along x, three types at random, consecutive spacings 0.9 to 1.3 of
    their pair's a (some first neighbours beyond their pair's cutoff), off the axis by up to
    0.15 s in y and z; returns positions and types."""
    s = UNITS[units][0]
    rng = np.random.default_rng(seed)
    types = rng.integers(1, 4, count)
    x = np.zeros((count, 3))
    for k in range(1, count):
        pk = PAIRS.index(tuple(sorted((types[k - 1], types[k]))))
        x[k, 0] = x[k - 1, 0] + A[pk] * rng.uniform(0.9, 1.3)
    x[:, 1:] = rng.uniform(-0.15, 0.15, (count, 2))
    return x * s, types


def data_file(path, x, types, units, bonds=None, nbondtypes=0):
    """A data file of the atoms (atom style atomic, or bond with the bonds (type, i, j))."""
    s = UNITS[units][0]
    lo, hi = x.min(axis=0) - 3 * s, x.max(axis=0) + 3 * s
    lines = ["chain", "", f"{len(x)} atoms", "3 atom types"]
    if bonds is not None:
        lines += [f"{len(bonds)} bonds", f"{nbondtypes} bond types"]
    lines += [f"{lo[k]!r} {hi[k]!r} {d}lo {d}hi" for k, d in enumerate("xyz")]
    mass = UNITS[units][2]
    lines += ["", "Masses", "", f"1 {mass!r}", f"2 {1.5 * mass!r}", f"3 {2.5 * mass!r}", "",
              "Atoms", ""]
    for k, (p, t) in enumerate(zip(x, types)):
        mol = "1 " if bonds is not None else ""
        lines.append(f"{k + 1} {mol}{t} {p[0]!r} {p[1]!r} {p[2]!r}")
    if bonds is not None:
        lines += ["", "Bonds", ""] + [f"{k + 1} {b[0]} {b[1]} {b[2]}" for k, b in enumerate(bonds)]
    path.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("units,suffix", [("lj", None), ("si", None), ("lj", "omp")])
@pytest.mark.parametrize("base,neighbours", [("morse", 2), ("morse", 3), ("harmonic", 2)])
def test_chain_per_atom_equals_bonds_of_the_nth_neighbours(tmp_path, units, suffix, base,
                                                          neighbours):
    """chain N: atoms n apart in ID interact through Pi_ij(r/n) up to n Rc_ij a_ij, which is
    bond_style morse with (D, kappa alpha / n, n a) (energy shifted by D per bond) or bond_style
    harmonic with (kappa^2 alpha^2 D / n^2, n a) on exactly those pairs (the /omp variant on 2
    threads too)."""
    x, types = chain_positions(units)
    law = laws(base, units)
    rc_style = 1.2
    bonds, coeffs, shift = [], {}, np.zeros(len(x))
    for i in range(len(x)):
        for n in range(1, neighbours + 1):
            j = i + n
            if j >= len(x):
                break
            k = PAIRS.index(tuple(sorted((types[i], types[j]))))
            lw = law[PAIRS[k]]
            rc = RC[k] or rc_style
            if np.linalg.norm(x[j] - x[i]) / n >= rc * lw.a:
                continue
            if (n, k) not in coeffs:
                if base == "morse":
                    args = f"{lw.D!r} {lw.kappa * lw.alpha / n!r} {n * lw.a!r}"
                else:
                    args = f"{(lw.kappa * lw.alpha) ** 2 * lw.D / n ** 2!r} {n * lw.a!r}"
                coeffs[(n, k)] = (len(coeffs) + 1, args)
            bonds.append((coeffs[(n, k)][0], i + 1, j + 1))
            shift[[i, j]] -= 0.5 * lw.D
    assert len(bonds) > len(x) and len({b[0] for b in bonds}) > 6
    # some chain pairs lie beyond their cutoff (skipped above)
    assert len(bonds) < sum(len(x) - n for n in range(1, neighbours + 1))
    data_file(tmp_path / "bonds.data", x, types, units, bonds, len(coeffs))
    data_file(tmp_path / "atoms.data", x, types, units)
    s = UNITS[units][0]
    outputs = ["compute epa all pe/atom", "compute spa all stress/atom NULL",
               "thermo_modify norm no"]
    with session() as lmp:
        lmp.commands_list([f"units {units}", "atom_style bond", "atom_modify map array",
                           f"bond_style {base}", f"read_data {tmp_path / 'bonds.data'}",
                           *[f"bond_coeff {t} {args}" for t, args in coeffs.values()],
                           "special_bonds lj 1 1 1", f"pair_style zero {2 * s!r}", "pair_coeff * *",
                           f"neighbor {0.3 * s!r} bin", *outputs])
        oracle = per_atom(lmp)
    oracle["pe"] = oracle["pe"] + shift
    oracle["pe_total"] = oracle["pe_total"] + shift.sum()
    with session() as lmp:
        lmp.commands_list([*(["package omp 2", "suffix omp"] if suffix else []),
                           f"units {units}", "atom_modify map array",
                           f"read_data {tmp_path / 'atoms.data'}",
                           f"pair_style {base}/spline cut {rc_style} chain {neighbours}",
                           *[f"pair_coeff {p[0]} {p[1]} {law[p].coeff()}" +
                             (f" rc {RC[k]}" if RC[k] else "") for k, p in enumerate(PAIRS)],
                           f"neighbor {0.3 * s!r} bin", *outputs])
        ours = per_atom(lmp)
    assert_same_per_atom(oracle, ours, 1e-11)


# ---------------------------------------------------------------- link L: a numpy oracle

def morse_np(r, law):
    """Energy and force (positive: repulsion) of the kappa-modified Morse law at r (arrays)."""
    e = np.exp(-law.alpha * law.kappa * (r - law.a))
    return law.D * (e * e - 2 * e), 2 * law.alpha * law.kappa * law.D * (e * e - e)


def pairs_within(x, types, box, reach):
    """All pairs i < j closer than reach (minimum image): i, j, separation x_i - x_j, r, pair
    index k."""
    i, j = np.triu_indices(len(x), 1)
    d = x[i] - x[j]
    d -= box * np.round(d / box)
    r = np.sqrt((d * d).sum(axis=1))
    keep = r < reach
    i, j, d, r = i[keep], j[keep], d[keep], r[keep]
    t1, t2 = np.minimum(types[i], types[j]), np.maximum(types[i], types[j])
    k = np.array([PAIRS.index((a, b)) for a, b in zip(t1, t2)], dtype=int)
    return i, j, d, r, k


def fragments(n, i, j):
    """Per atom: the smallest atom ID (1-based) of its connected component."""
    parent = list(range(n))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a
    for a, b in zip(i, j):
        ra, rb = find(a), find(b)
        if ra != rb:
            parent[max(ra, rb)] = min(ra, rb)
    roots = np.array([find(a) for a in range(n)])
    smallest = {}
    for a, root in enumerate(roots):
        smallest.setdefault(root, a + 1)
    return np.array([smallest[root] for root in roots], dtype=float)


def dust_columns(frag):
    """compute dust's per-atom columns from the fragment IDs: ID, size, dust flag (every
    fragment but the largest, the smallest ID among equally large ones)."""
    ids, sizes = np.unique(frag, return_counts=True)
    body = ids[np.argmax(sizes)]    # np.unique sorts: the first of the largest has the least ID
    size = sizes[np.searchsorted(ids, frag)].astype(float)
    return np.stack([frag, size, (frag != body).astype(float)], axis=1)


def state_of(lmp):
    order = np.argsort(np.array(lmp.gather_atoms("id", 0, 1)))
    x = np.array(lmp.gather_atoms("x", 1, 3)).reshape(-1, 3)[order]
    types = np.array(lmp.gather_atoms("type", 0, 1))[order]
    lo, hi = lmp.extract_box()[:2]
    return x, types, np.array(hi) - np.array(lo)


LINK = 1.03


@pytest.mark.parametrize("units,ntypes,suffix", [("lj", 1, None), ("si", 1, None), ("lj", 3, None),
                                                 ("si", 3, None), ("lj", 3, "omp")])
def test_link_per_type_pair_atom_by_atom(units, ntypes, suffix):
    """A stretched, shaken block (nearest neighbours at 1.12 a, +-0.1 a) under morse/spline cut
    1.3 link 1.03 with per-pair a, kappa and rc: the first run links the pairs closer than
    1.03 a_ij, a sparse link graph of many fragments (compute links/atom: stock compute coord/atom
    of each partner type within 1.03 a_ij; compute dust links: the graph's components, and with
    one type stock compute cluster/atom at 1.03 a).  The atoms then shaken again and run 0: links
    at or beyond rc_ij a_ij break, unlinked pairs closer than a_ij repel through Pi_ij(r) -
    Pi_ij(a_ij); forces, energies, links, fragments and the style's tally of breaks against the
    numpy oracle (the /omp variant on 2 threads too)."""
    s, e, _ = UNITS[units]
    law = laws("morse", units)
    if ntypes == 1:
        law = {p: law[(1, 1)] for p in PAIRS}
    rc = [(RC[k] or 1.3) if ntypes == 3 else 1.15 for k in range(6)]
    coeffs = [f"pair_coeff {p[0]} {p[1]} {law[p].coeff()} rc {rc[k]}"
              for k, p in enumerate(PAIRS) if max(p) <= ntypes]
    coord = []    # per (i type, j type): the count of j-type neighbours within L a_ij
    for ti, tj in PAIRS:
        if max(ti, tj) <= ntypes:
            reach = LINK * law[(ti, tj)].a
            coord.append(f"compute c{ti}{tj} all coord/atom cutoff {reach!r} {tj}")
            if ti != tj:
                coord.append(f"compute c{tj}{ti} all coord/atom cutoff {reach!r} {ti}")
    with session() as lmp:
        if suffix:
            lmp.commands_list(["package omp 2", f"suffix {suffix}"])
        lmp.commands_list(block(units, noise=0.1, nn=1.12, skin=0.4, ntypes=ntypes) + [
            f"pair_style morse/spline cut 1.3 link {LINK}", *coeffs,
            "compute epa all pe/atom", "compute spa all stress/atom NULL pair",
            "compute l all links/atom", "compute d all dust links",
            "compute p all pair morse/spline",
            *coord, f"compute ca all cluster/atom {LINK * law[(1, 1)].a!r}",
            "thermo_style custom step pe press pxx pyy pzz pxy pxz pyz c_p[1] c_d[1]",
            "thermo_modify norm no", "run 0 post no"])
        x_a, types, box_a = state_of(lmp)
        links_a = np.array(lmp.gather("c_l", 1, 1))
        dust_a = np.array(lmp.gather("c_d", 1, 3)).reshape(-1, 3)
        coord_a = {name: np.array(lmp.gather(f"c_{name}", 1, 1))
                   for name in (c.split()[1] for c in coord)}
        cluster_a = np.array(lmp.gather("c_ca", 1, 1))
        lmp.commands_list([f"displace_atoms all random {0.1 * s!r} {0.1 * s!r} {0.1 * s!r} 977 "
                           "units box", "change_box all x scale 1.04 y scale 1.04 z scale 1.04 "
                           "remap"])
        ours = per_atom(lmp)
        del ours["virial"]
        x_b, _, box_b = state_of(lmp)
        links_b = np.array(lmp.gather("c_l", 1, 1))
        dust_b = np.array(lmp.gather("c_d", 1, 3)).reshape(-1, 3)
        tally = [lmp.extract_compute("p", 0, 1)[k] for k in (0, 2)]
    n = len(x_a)
    # the links made: stock coord/atom per partner type
    expect = np.zeros(n)
    for name, counts in coord_a.items():
        ti = int(name[1])
        expect += np.where(types == ti, counts, 0.0)
    assert np.array_equal(links_a, expect)
    # the oracle's links at the first run, and its fragments
    reach = 1.5 * 1.08 * s
    i, j, d, r, k = pairs_within(x_a, types, box_a, reach)
    a_ij = np.array([law[PAIRS[q]].a for q in k])
    linked = r < LINK * a_ij
    made = set(zip(i[linked], j[linked]))
    frag_a = fragments(n, i[linked], j[linked])
    assert np.array_equal(dust_a, dust_columns(frag_a))
    assert len(np.unique(frag_a)) > 10    # a sparse graph: many fragments
    if ntypes == 1:
        assert np.array_equal(dust_a[:, 0], cluster_a)
    # after the second shake
    i, j, d, r, k = pairs_within(x_b, types, box_b, reach)
    a_ij = np.array([law[PAIRS[q]].a for q in k])
    rc_ij = np.array([rc[q] for q in k]) * a_ij
    was = np.array([(p, q) in made for p, q in zip(i, j)], dtype=bool)
    holds = was & (r < rc_ij)
    repels = ~was & (r < a_ij)
    broken = int(len(made) - holds.sum())
    assert broken > 0 and repels.sum() > 0 and holds.sum() > 0
    energy, force = np.zeros(len(r)), np.zeros(len(r))
    for q in range(6):
        lw = law[PAIRS[q]]
        on = k == q
        en, fo = morse_np(r[on], lw)
        energy[on] = np.where(holds[on], en, np.where(repels[on], en + lw.D, 0.0))
        force[on] = np.where(holds[on] | repels[on], fo, 0.0)
    f = np.zeros((n, 3))
    pe = np.zeros(n)
    np.add.at(f, i, d * (force / r)[:, None])
    np.add.at(f, j, -d * (force / r)[:, None])
    np.add.at(pe, i, 0.5 * energy)
    np.add.at(pe, j, 0.5 * energy)
    oracle = {"f": f, "pe": pe, "pe_total": np.array([energy.sum()])}
    assert_same_per_atom(oracle, ours, 1e-12)
    counts = np.zeros(n)
    np.add.at(counts, i[holds], 1)
    np.add.at(counts, j[holds], 1)
    assert np.array_equal(links_b, counts)
    assert np.array_equal(dust_b, dust_columns(fragments(n, i[holds], j[holds])))
    # the style's tally: links broken, and the jumps -Pi_ij(rc_ij a_ij) of the cut
    jumps, kept = 0.0, set(zip(i[holds], j[holds]))
    for p, q in made:
        if (p, q) not in kept:
            kk = PAIRS.index(tuple(sorted((types[p], types[q]))))
            jumps -= morse_np(np.array([rc[kk] * law[PAIRS[kk]].a]), law[PAIRS[kk]])[0][0]
    assert tally[0] == broken
    assert tally[1] == pytest.approx(jumps, rel=1e-12)
