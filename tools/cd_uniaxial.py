#!/usr/bin/python3
r"""A cluster lattice in uniaxial strain along the impact: what a plate impact loads.

Nearest-neighbour bonds of a pair law Pi(r) = D phi(r / a) on a close-packed lattice (chain,
tri, fcc) stretched or compressed along a unit vector n with the lateral size fixed: a bond
vector b becomes b + eps (b.n) n.  With E(eps) the energy per particle (half its bonds' sum)
and V0 its volume (area, length):

* longitudinal speed along n: c^2 = E''(0) / m;
* weak-shock slope of the Hugoniot us = c + s up: s = -E'''(0) / (4 E''(0))  (the Rayleigh
  line's expansion; fcc [100]: s = (Gamma - 3/2)/4, chain: Gamma/2, Gamma the chain's
  Grueneisen coefficient -a Pi'''(a) / (2 Pi''(a)));
* cold Hugoniot: us^2 = sigma(eps) / (rho eps), up = us eps in compression eps (no shock heat);
* ideal tensile strength: the largest sigma(eps) = E'(eps) / V0, bonds at or beyond the cut
  Rc a carrying nothing.

Lengths in units of a, energies of D (stress D / a^d, speeds sqrt(D / m)).  doc/plate_impact.rst.
"""
import itertools
import math

import numpy as np

# dimension and volume per particle in a^d of each close-packed lattice
VOLUME = {"chain": 1.0, "tri": math.sqrt(3) / 2, "fcc": 1 / math.sqrt(2)}
# impact directions: a lattice direction in the cubic cell (fcc) or along a row (tri: x along
# a close-packed row, y across it)
ORIENTATIONS = {"chain": ("row",), "tri": ("row", "across"), "fcc": ("100", "110", "111")}


def bonds(lattice):
    """The nearest-neighbour bond vectors (length 1)."""
    if lattice == "chain":
        return np.array([[1.0], [-1.0]])
    if lattice == "tri":
        return np.array([[math.cos(k * math.pi / 3), math.sin(k * math.pi / 3)] for k in range(6)])
    if lattice == "fcc":
        out = []
        for i, j in itertools.combinations(range(3), 2):
            for si, sj in itertools.product((1, -1), repeat=2):
                b = np.zeros(3)
                b[i], b[j] = si / math.sqrt(2), sj / math.sqrt(2)
                out.append(b)
        return np.array(out)
    raise ValueError(f"unknown lattice '{lattice}' (expected chain, tri or fcc)")


def direction(lattice, orientation):
    """The unit vector along the impact."""
    if orientation not in ORIENTATIONS.get(lattice, ()):
        raise ValueError(f"orientation '{orientation}' is not one of {lattice}'s: "
                         f"{', '.join(ORIENTATIONS.get(lattice, ()))}")
    if lattice == "chain":
        return np.array([1.0])
    if lattice == "tri":
        return np.array([1.0, 0.0]) if orientation == "row" else np.array([0.0, 1.0])
    n = np.array([float(c) for c in orientation])
    return n / np.linalg.norm(n)


class Law:
    """Pi(r) / D and its derivative with r in units of a: Morse (alpha a) or Mie (n, m; LJ is
    12-6) with Krivtsov's kappa, Pi_K(r) = Pi(K (r - 1) + 1), cut at rc (None: no cut)."""

    def __init__(self, name, shape, n=12.0, m=6.0, rc=None):
        self.name, self.shape, self.n, self.m, self.rc = name, shape, n, m, rc

    def with_shape(self, shape, rc=None):
        return Law(self.name, shape, self.n, self.m, rc)

    def energy_force(self, r):
        """(Pi, dPi/dr) at r (arrays)."""
        if self.name == "morse":
            e = np.exp(-self.shape * (r - 1))
            pi, dpi = e * e - 2 * e, -2 * self.shape * (e * e - e)
        else:
            x = self.shape * (r - 1) + 1
            n, m = self.n, self.m
            pi = (m * x ** -n - n * x ** -m) / (n - m)
            dpi = self.shape * n * m * (x ** (-m - 1) - x ** (-n - 1)) / (n - m)
        if self.rc is not None:
            pi, dpi = np.where(r < self.rc, pi, 0.0), np.where(r < self.rc, dpi, 0.0)
        return pi, dpi

    def gamma(self):
        """The chain's Grueneisen coefficient -Pi'''(1) / (2 Pi''(1))."""
        if self.name == "morse":
            return 1.5 * self.shape
        return self.shape * (self.n + self.m + 3) / 2

    def inflection(self):
        """The inflection (break) distance b / a of the uncut law."""
        if self.name == "morse":
            return 1 + math.log(2) / self.shape
        b0 = ((self.n + 1) / (self.m + 1)) ** (1 / (self.n - self.m))
        return 1 + (b0 - 1) / self.shape


class Uniaxial:
    """The lattice `lattice` with a law, strained along `orientation`."""

    def __init__(self, lattice, orientation, law):
        self.b, self.n, self.law = bonds(lattice), direction(lattice, orientation), law
        self.volume = VOLUME[lattice]
        self.bn = self.b @ self.n

    def stress(self, eps):
        """sigma(eps) = E'(eps) / V0 in D / a^d, tension positive (eps a number or an array)."""
        eps = np.asarray(eps, dtype=float)[..., None]
        r = np.sqrt(1 + self.bn ** 2 * ((1 + eps) ** 2 - 1))        # the bonds' lengths
        terms = self.law.energy_force(r)[1] * self.bn ** 2 * (1 + eps) / r
        return 0.5 * np.sum(terms, axis=-1) / self.volume

    def moduli(self, h=1e-5):
        """(M, M2): d sigma / d eps and the second derivative in compression at eps = 0."""
        s = [self.stress(k * h) for k in (-1, 0, 1)]
        return (s[2] - s[0]) / (2 * h), -(s[2] - 2 * s[1] + s[0]) / h ** 2

    def speed(self):
        """Longitudinal speed along n in sqrt(D / m)."""
        return math.sqrt(self.moduli()[0] * self.volume)

    def slope(self):
        """s of us = c + s up for weak shocks."""
        m, m2 = self.moduli()
        return m2 / (4 * m)

    def hugoniot(self, up):
        """The cold Hugoniot's shock speed at particle speed up (both in sqrt(D / m))."""
        def speeds(eps):
            us = math.sqrt(-self.stress(-eps) * self.volume / eps)
            return us, us * eps
        lo, hi = 1e-9, 0.5
        if speeds(hi)[1] < up:
            raise ValueError(f"up = {up:.4g} sqrt(D/m) compresses the lattice beyond half its "
                             "length")
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if speeds(mid)[1] < up else (lo, mid)
        return speeds(0.5 * (lo + hi))[0]

    def strength(self):
        """The ideal tensile strength in D / a^d: the largest stress of the stretch, bonds at
        or beyond the cut carrying nothing."""
        return self.peak()[1]

    def peak(self):
        """(strain, stress) of the ideal strength (on a fine grid and just below each bond
        family's breaking strain)."""
        rc = self.law.rc
        end = 1.0 if rc is None else math.sqrt(1 + (rc ** 2 - 1) / np.max(self.bn ** 2)) - 1
        grid = list(np.linspace(0.0, end, 4001))
        if rc is not None:
            stretched = self.bn[np.abs(self.bn) > 1e-12] ** 2
            grid += [(math.sqrt(1 + (rc ** 2 - 1) / q) - 1) * (1 - 1e-12) for q in stretched]
        stresses = self.stress(np.array(grid))
        k = int(np.argmax(stresses))
        return grid[k], float(stresses[k])
