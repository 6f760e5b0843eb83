"""Krivtsov & Krivtsova's Table 2 (wave speeds, E/K and Poisson's ratio of close-packed lattices
with nearest-neighbour bonds) from the elastic constants LAMMPS computes (compute born/matrix in
in.pulse), next to the speeds of simulated small-amplitude pulses (in.pulse) and the paper.

    source ../../build/env.sh
    /usr/bin/python3 table2.py [--pot lj-reduced]      # table2.md and pulses.png, about 1 min

Every quantity is dimensionless: the Born matrix of N atoms (energy units) over N C a^2 is
c = C_IJ V_atom / (C a^2), so that (v / v0)^2 is an eigenvalue of the Christoffel matrix
c_iklj n_k n_l (v0 = a sqrt(C/m), density m / V_atom).  The bulk modulus of a d-dimensional
lattice is K = c_iijj / d^2; Young's modulus along n is 1 / (n n : s : n n) and Poisson's ratio
for the lateral direction t is -(t t : s : n n) / (n n : s : n n), s the compliance.
"""
import argparse
import itertools
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import script  # noqa: E402

# the paper's Table 2: v_l/v0, v_s/v0, E/K, Poisson (None: not defined)
PAPER = {
    "chain": (1.00, None, 1.00, None),
    "tri": (1.06, 0.61, 1.33, 0.33),
    "fcc0": (1.10, 0.63, 1.50, 0.25),
    "fcc 100": (1.00, 0.71, 1.00, 0.33),
    "fcc [1-10], isotropy plane": (1.12, 0.65, 1.61, 0.23),
    "fcc 111": (1.15, 0.58, 1.80, 0.20),
}
VOIGT = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
# compute born/matrix's order of the 21 components (doc page of compute born/matrix)
BORN_ORDER = [(0, 0), (1, 1), (2, 2), (3, 3), (4, 4), (5, 5), (0, 1), (0, 2), (0, 3), (0, 4),
              (0, 5), (1, 2), (1, 3), (1, 4), (1, 5), (2, 3), (2, 4), (2, 5), (3, 4), (3, 5),
              (4, 5)]
DIMENSION = {"chain": 1, "tri": 2, "fcc": 3}
# the pulse runs: lattice, dir, polarization (x longitudinal; y, z shear)
PULSES = [("chain", "100", "x"), ("tri", "100", "x"), ("tri", "100", "y"),
          ("fcc", "100", "x"), ("fcc", "100", "y"), ("fcc", "111", "x"), ("fcc", "111", "y"),
          ("fcc", "110", "x"), ("fcc", "110", "y"), ("fcc", "110", "z")]


def run(lattice, direction="100", pol="none", pot="lj-reduced", **var):
    """in.pulse: the dimensionless stiffness tensor c (3x3x3x3, lab frame) and, for a pulse
    run, its measured speed / v0."""
    var = dict(lattice=lattice, dir=direction, pol=pol, pot=pot, **var)
    with script(os.path.join(HERE, "in.pulse"), var) as lmp:
        born = np.array([lmp.extract_compute("born", 0, 1)[i] for i in range(21)])
        natoms = lmp.get_natoms()
        stiff = lmp.extract_variable("C")
        a = lmp.extract_variable("a")
        speed = lmp.extract_variable("speed") / lmp.extract_variable("v0") if pol != "none" else None
    voigt = np.zeros((6, 6))
    for (i, j), value in zip(BORN_ORDER, born):
        voigt[i, j] = voigt[j, i] = value / (natoms * stiff * a * a)
    return tensor(voigt), speed


def tensor(voigt):
    c = np.zeros((3, 3, 3, 3))
    for (i, j), (k, l) in itertools.product(VOIGT, VOIGT):
        I, J = VOIGT.index((i, j)), VOIGT.index((k, l))
        for p, q, r, s in ((i, j, k, l), (j, i, k, l), (i, j, l, k), (j, i, l, k)):
            c[p, q, r, s] = voigt[I, J]
    return c


def compliance(c, d):
    """The compliance of the d-dimensional tensor (the first d axes) as a 4th-order tensor."""
    sub = c[:d, :d, :d, :d].reshape(d * d, d * d)
    return np.linalg.pinv(sub).reshape(d, d, d, d)


def bulk(c, d):
    return np.einsum("iijj", c[:d, :d, :d, :d]) / d ** 2


def speeds(c, n):
    """Sorted speeds / v0 (Christoffel eigenvalues) and their polarizations along n."""
    gamma = np.einsum("iklj,k,l->ij", c, n, n)
    w, vec = np.linalg.eigh(gamma)
    return np.sqrt(np.clip(w, 0, None)), vec


def properties(c, d, n, lateral):
    """v_l, v_s (the shear speeds), E/K and Poisson's ratios for the lateral directions."""
    n = np.asarray(n, float) / np.linalg.norm(n)
    w, _ = speeds(c, np.pad(n, (0, 3 - d)))
    s = compliance(c, d)
    snn = np.einsum("i,j,k,l,ijkl", n, n, n, n, s)
    nus = [-np.einsum("i,j,k,l,ijkl", t, t, n, n, s) / snn
           for t in (np.asarray(t, float) / np.linalg.norm(t) for t in lateral)]
    shear = [v for v in w[3 - d:-1]] if d > 1 else []
    return w[-1], shear, 1.0 / snn / bulk(c, d), nus


def rotation(axis, angle):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * kx + (1 - np.cos(angle)) * kx @ kx


def rotate(c, r):
    return np.einsum("ia,jb,kc,ld,abcd->ijkl", r, r, r, r, c)


def isotropic_part(c):
    """Projection on isotropic tensors: 9K = c_iijj, 10G = c_ijij - c_iijj / 3."""
    k = np.einsum("iijj", c) / 9
    g = (np.einsum("ijij", c) - np.einsum("iijj", c) / 3) / 10
    delta = np.eye(3)
    return (k * np.einsum("ij,kl->ijkl", delta, delta)
            + g * (np.einsum("ik,jl->ijkl", delta, delta) + np.einsum("il,jk->ijkl", delta, delta)
                   - 2 / 3 * np.einsum("ij,kl->ijkl", delta, delta)))


def transversely_isotropic_part(c, axis):
    """The average over rotations about axis (12 angles: exact for a 4th-order tensor)."""
    angles = np.arange(12) * np.pi / 6
    return sum(rotate(c, rotation(axis, t)) for t in angles) / len(angles)


def table(pot="lj-reduced"):
    """Rows name -> (v_l, [v_s...], E/K, [nu...]) from born/matrix, paper's Table 2 rows."""
    chain, _ = run("chain", pot=pot)
    tri, _ = run("tri", pot=pot)
    fcc, _ = run("fcc", "100", pot=pot)
    axis = np.array([1, 1, 1]) / np.sqrt(3)
    in_plane, lateral_in_plane = np.array([1, -1, 0]), np.array([1, 1, -2])
    return {
        "chain": properties(chain, 1, [1], []),
        "tri": properties(tri, 2, [1, 0], [[0, 1]]),
        "fcc0": properties(isotropic_part(fcc), 3, [1, 0, 0], [[0, 1, 0]]),
        "fcc 100": properties(fcc, 3, [1, 0, 0], [[0, 1, 0]]),
        "fcc [1-10], isotropy plane": properties(fcc, 3, in_plane, [axis, lateral_in_plane, [0, 0, 1], [1, 1, 0]]),
        "fcc [1-10], transversely isotropic part":
            properties(transversely_isotropic_part(fcc, axis), 3, in_plane,
                       [axis, lateral_in_plane]),
        "fcc 111": properties(fcc, 3, axis, [[1, -1, 0], [1, 1, -2]]),
    }, {"chain": chain, "tri": tri, "fcc": fcc}


def pulses(pot="lj-reduced", cases=PULSES, **var):
    """(lattice, dir, pol, born/matrix speed along x for that polarization, pulse speed)."""
    rows = []
    for lattice, direction, pol in cases:
        c, measured = run(lattice, direction, pol, pot=pot, **var)
        p = "xyz".index(pol)
        rows.append((lattice, direction, pol, np.sqrt(c[p, 0, 0, p]), measured))
    return rows


def fmt(x, digits=3):
    if x is None or (isinstance(x, list) and not x):
        return "-"
    if isinstance(x, list):
        return " / ".join(f"{v:.{digits}f}" for v in x)
    return f"{x:.{digits}f}"


def write(rows, pulse_rows, pot, path):
    lines = [f"# Table 2 from compute born/matrix ({pot}, nearest neighbours only)", "",
             "| lattice, direction | v_l/v0 paper | ours | v_s/v0 paper | ours | E/K paper | ours "
             "| Poisson paper | ours |", "|---|---|---|---|---|---|---|---|---|"]
    for name, (vl, vs, ek, nus) in rows.items():
        paper = PAPER.get(name, (None,) * 4)
        lines.append(f"| {name} | {fmt(paper[0], 2)} | {vl:.3f} | {fmt(paper[1], 2)} | {fmt(vs)} | "
                     f"{fmt(paper[2], 2)} | {ek:.3f} | {fmt(paper[3], 2)} | {fmt(nus)} |")
    lines += ["", "# Pulse speeds (in.pulse) against born/matrix", "",
              "| lattice | direction | polarization | born/matrix v/v0 | pulse v/v0 | difference |",
              "|---|---|---|---|---|---|"]
    for lattice, direction, pol, theory, measured in pulse_rows:
        lines.append(f"| {lattice} | {direction} | {pol} | {theory:.4f} | {measured:.4f} | "
                     f"{100 * (measured / theory - 1):+.2f} % |")
    open(path, "w").write("\n".join(lines) + "\n")


def plot(pulse_rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    paper = {("chain", "100", "x"): 1.00, ("tri", "100", "x"): 1.06, ("tri", "100", "y"): 0.61,
             ("fcc", "100", "x"): 1.00, ("fcc", "100", "y"): 0.71, ("fcc", "111", "x"): 1.15,
             ("fcc", "111", "y"): 0.58, ("fcc", "110", "x"): 1.12, ("fcc", "110", "y"): 0.65,
             ("fcc", "110", "z"): 0.65}
    shear = {("tri", "100", "y"): "shear", ("fcc", "100", "y"): "shear [010]",
             ("fcc", "111", "y"): "shear [-110]", ("fcc", "110", "y"): "shear [001]",
             ("fcc", "110", "z"): "shear [1-10]"}
    labels = [(f"{r[0]} [{r[1]}]" if r[0] == "fcc" else r[0]) + "\n"
              + ("long." if r[2] == "x" else shear[r[:3]]) for r in pulse_rows]
    xs = np.arange(len(pulse_rows))
    fig, ax = plt.subplots(figsize=(10, 4.2))
    ax.plot(xs, [r[3] for r in pulse_rows], "s", ms=11, mfc="none", color="C0",
            label="compute born/matrix (Christoffel)")
    ax.plot(xs, [r[4] for r in pulse_rows], "o", ms=5, color="C3", label="simulated pulse")
    ax.plot(xs, [paper[r[:3]] for r in pulse_rows], "_", ms=22, mew=2, color="k",
            label="Krivtsov & Krivtsova, Table 2")
    ax.set_xticks(xs, labels, fontsize=8)
    ax.set_ylabel("wave speed / v0")
    ax.set_ylim(0.4, 1.25)
    ax.grid(axis="y", alpha=0.3)
    ax.legend(loc="lower left", fontsize=8)
    ax.set_title("Close-packed lattices, nearest-neighbour bonds: wave speeds "
                 "(fcc [110]: the paper's row is the transversely isotropic part)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--pot", default="lj-reduced")
    args = ap.parse_args()
    rows, _ = table(args.pot)
    pulse_rows = pulses(args.pot)
    write(rows, pulse_rows, args.pot, os.path.join(HERE, "table2.md"))
    plot(pulse_rows, os.path.join(HERE, "pulses.png"))
    print(open(os.path.join(HERE, "table2.md")).read())


if __name__ == "__main__":
    main()
