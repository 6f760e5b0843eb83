r"""The cluster lattices of the calibration: their cells, sites, neighbour shells, impact
directions and volume per site, with lengths in units of the nearest-neighbour distance d
(the cluster size --size).  tools/cd_uniaxial.py puts a pair law on them.

* chain, tri (triangular, 2D) and fcc: one site per cell, nearest neighbours only (the cut
  between the first and the second shell);
* bcc: nearest neighbours alone leave C11 = C12 (no resistance to the shear C' =
  (C11 - C12)/2): the model bonds the first two shells (8 at d, 6 at 2/sqrt(3) d = 1.1547 d),
  the cut between the second and the third (sqrt(8/3) d = 1.633 d);
* hcp with the ideal c/a = sqrt(8/3) (LAMMPS's ``lattice hcp``: x along [2-1-10], y along
  [01-10], z along c = [0001]): two sites per primitive cell, nearest neighbours (12 at d,
  the next at sqrt(2) d), the second site free to shift (internal strain).

doc/compute_pair_params.rst, "Calibration to a metal".
"""
import functools
import itertools
import math

import numpy as np

SQ3 = math.sqrt(3.0)
C_HCP = math.sqrt(8.0 / 3.0)


def cubic_directions():
    return {k: np.array([float(c) for c in k]) for k in ("100", "110", "111")}


# cell vectors (rows), sites (cartesian), the shells the model bonds, the impact directions
LATTICES = {
    "chain": dict(cell=[[1.0]], sites=[[0.0]], shells=1, directions={"row": [1.0]}),
    "tri": dict(cell=[[1.0, 0.0], [0.5, SQ3 / 2]], sites=[[0.0, 0.0]], shells=1,
                directions={"row": [1.0, 0.0], "across": [0.0, 1.0]}),
    "fcc": dict(cell=np.array([[0, 1, 1], [1, 0, 1], [1, 1, 0]]) / math.sqrt(2),
                sites=[[0.0, 0.0, 0.0]], shells=1, directions=cubic_directions()),
    "bcc": dict(cell=np.array([[-1, 1, 1], [1, -1, 1], [1, 1, -1]]) / SQ3,
                sites=[[0.0, 0.0, 0.0]], shells=2, directions=cubic_directions()),
    "hcp": dict(cell=[[1.0, 0.0, 0.0], [0.5, SQ3 / 2, 0.0], [0.0, 0.0, C_HCP]],
                sites=[[0.0, 0.0, 0.0], [0.0, 1 / SQ3, C_HCP / 2]], shells=1,
                directions={"0001": [0.0, 0.0, 1.0], "2-1-10": [1.0, 0.0, 0.0],
                            "01-10": [0.0, 1.0, 0.0]}),
}
# the pairs listed once per lattice (twice the cut of a chain: compression to half its length)
PAIR_RADIUS = 4.0 + 1e-6
# the impact direction a calibration takes when --orientation is not given
DEFAULT_ORIENTATION = {"chain": "row", "tri": "row", "fcc": "100", "bcc": "100", "hcp": "0001"}

# LAMMPS's lattice command for an impact along x: its scale in d, its orient keywords (the
# cubic cell's axes, or hcp's x = [2-1-10], y = [01-10], z = [0001] of ``lattice hcp``) and
# the spacings (in the scale) of the shortest lattice translations along x, y and z: boxes
# of whole spacings are periodic (LAMMPS's own spacings, the rotated cell's extent, are not
# on fcc and bcc [111] or bcc [110])
R2, R3, R6, RC = math.sqrt(2.0), math.sqrt(3.0), math.sqrt(6.0), math.sqrt(8.0 / 3.0)
CUBIC_ORIENT = {"100": "orient x 1 0 0 orient y 0 1 0 orient z 0 0 1",
                "110": "orient x 1 1 0 orient y -1 1 0 orient z 0 0 1",
                "111": "orient x 1 1 1 orient y -1 1 0 orient z -1 -1 2"}
SPACINGS = {("fcc", "100"): (1, 1, 1), ("fcc", "110"): (1 / R2, 1 / R2, 1),
            ("fcc", "111"): (R3, 1 / R2, R6 / 2), ("bcc", "100"): (1, 1, 1),
            ("bcc", "110"): (R2, R2, 1), ("bcc", "111"): (R3 / 2, R2, R6),
            ("hcp", "0001"): (RC, 1, R3), ("hcp", "2-1-10"): (1, R3, RC),
            ("hcp", "01-10"): (R3, RC, 1)}
HCP_ORIENT = {"0001": "orient x 0 0 1 orient y 1 0 0 orient z 0 1 0",
              "2-1-10": "orient x 1 0 0 orient y 0 1 0 orient z 0 0 1",
              "01-10": "orient x 0 1 0 orient y 0 0 1 orient z 1 0 0"}
# atoms and volume (in its scale cubed) of LAMMPS's unit cell: in units lj the lattice
# command takes a number density, n / (volume scale^3), instead of the scale
LAMMPS_CELL = {"fcc": (4, 1.0), "bcc": (2, 1.0), "hcp": (4, math.sqrt(8.0))}
LAMMPS_LATTICE = {
    (lat, k): (scale, f"{orient[k]} spacing {' '.join(f'{x!r}' for x in SPACINGS[(lat, k)])}")
    for lat, scale, orient in (("fcc", R2, CUBIC_ORIENT), ("bcc", 2 / R3, CUBIC_ORIENT),
                               ("hcp", 1.0, HCP_ORIENT))
    for k in orient}


@functools.lru_cache(maxsize=None)
def crystal(name):
    """The Crystal of a lattice's name (made once)."""
    return Crystal(name)


class Crystal:
    """One of LATTICES: geometry only (cd_uniaxial.py adds the law)."""

    def __init__(self, name):
        if name not in LATTICES:
            raise ValueError(f"unknown lattice '{name}' (expected {', '.join(LATTICES)})")
        spec = LATTICES[name]
        self.name = name
        self.cell = np.array(spec["cell"], dtype=float)
        self.sites = np.array(spec["sites"], dtype=float)
        self.dim = self.cell.shape[0]
        self.volume = float(abs(np.linalg.det(self.cell))) / len(self.sites)
        self.directions = {k: np.array(v, dtype=float) / np.linalg.norm(v)
                           for k, v in spec["directions"].items()}
        self.model_shells = spec["shells"]
        self.shells = self.distances(3.0)

    def direction(self, orientation):
        """The unit vector along the impact for an orientation name."""
        if orientation not in self.directions:
            raise ValueError(f"orientation '{orientation}' is not one of {self.name}'s: "
                             f"{', '.join(self.directions)}")
        return self.directions[orientation]

    def pairs(self, radius):
        """Every pair of a site of the cell with a site closer than radius: (i, j, R) with
        R the reference vector from site i to site j (arrays)."""
        i, j, vec = self._pairs(max(radius, PAIR_RADIUS))
        keep = np.linalg.norm(vec, axis=1) < radius
        return i[keep], j[keep], vec[keep]

    @functools.lru_cache(maxsize=8)
    def _pairs(self, radius):
        heights = 1 / np.linalg.norm(np.linalg.inv(self.cell), axis=0)     # cell layer spacings
        reach = [int(math.ceil(radius / h)) + 1 for h in heights]
        shifts = np.array(list(itertools.product(*(range(-r, r + 1) for r in reach))),
                          dtype=float) @ self.cell
        first, second, vectors = [], [], []
        for i, j in itertools.product(range(len(self.sites)), repeat=2):
            vec = shifts + self.sites[j] - self.sites[i]
            length = np.linalg.norm(vec, axis=1)
            keep = (length > 1e-9) & (length < radius)
            first += [i] * int(keep.sum())
            second += [j] * int(keep.sum())
            vectors.append(vec[keep])
        return np.array(first, dtype=int), np.array(second, dtype=int), np.concatenate(vectors)

    def distances(self, radius):
        """The distinct neighbour distances (shells) below radius, ascending."""
        lengths = np.sort(np.linalg.norm(self.pairs(radius)[2], axis=1))
        return [float(x) for x in lengths[np.concatenate(([True], np.diff(lengths) > 1e-9))]]

    def model_radius(self):
        """The distance of the last shell the model bonds."""
        return self.shells[self.model_shells - 1]

    def next_shell(self):
        """The first shell the model does not bond: the cut stays below it."""
        return self.shells[self.model_shells]
