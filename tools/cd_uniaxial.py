#!/usr/bin/python3
r"""A cluster lattice in uniaxial strain along the impact: what a plate impact loads.

A pair law Pi(r) = D phi(r) on a lattice of tools/cd_crystal.py (chain, tri, fcc, bcc, hcp),
stretched or compressed along a unit vector n with the lateral size fixed: a pair vector R
becomes F R with F = I + eps n n.  With E(eps) the energy per site (half its pairs' sum; the
second site of hcp shifted to its minimum, the internal strain) and V0 the volume per site:

* longitudinal speed along n: c^2 = E''(0) / m;
* weak-shock slope of the Hugoniot us = c + s up: s = -E'''(0) / (4 E''(0))  (the Rayleigh
  line's expansion; fcc [100]: s = (Gamma - 3/2)/4, chain: Gamma/2, Gamma the chain's
  Grueneisen coefficient -a Pi'''(a) / (2 Pi''(a)));
* cold Hugoniot: us^2 = sigma(eps) / (rho eps), up = us eps in compression eps (no shock heat);
* ideal tensile strength: the largest sigma(eps) = E'(eps) / V0, pairs at or beyond the cut
  Rc r0 carrying nothing;
* the elastic constants at eps = 0 (lattice sums with the internal strain relaxed) and the
  Born stability of the lattice: all eigenvalues of the Voigt matrix positive (cubic:
  C11 > |C12|, C11 + 2 C12 > 0, C44 > 0; hexagonal: C11 > |C12|, (C11 + C12) C33 > 2 C13^2,
  C44 > 0).

Which pairs: without a cut (law.rc None) the shells the lattice's model bonds (cd_crystal.py:
the first; bcc the first two) with the whole law; with a cut, every pair shorter than Rc r0.
Lengths in units of the nearest-neighbour distance d, the law's minimum at r0 (bcc: above d,
chosen so that the lattice is at zero pressure, balanced()), energies in D (stress D / d^dim,
speeds sqrt(D / m)).  doc/compute_pair_params.rst, "Calibration to a metal".
"""
import math

import numpy as np

from cd_crystal import crystal

GRID = 2001           # strains of the tensile curve's first scan
PEAKS = 3             # its largest local maxima refined
SHIFT_REACH = 0.5     # how much closer a pair of different sites may come by the shift (d)
RELAX_STEPS = 60      # Newton steps of the internal relaxation


def solve(f, lo, hi, target, xtol=1e-14):
    """x in [lo, hi] with f(x) = target for f increasing and continuous (f(lo) < target <
    f(hi)): regula falsi with the Illinois rule, which converges as fast as the secant on a
    smooth f and keeps the bracket on a kinked one; it stops when x moves by less than
    xtol |x| or the bracket is that narrow."""
    flo, fhi = f(lo) - target, f(hi) - target
    side, last = 0, None
    for _ in range(200):
        x = hi - fhi * (hi - lo) / (fhi - flo)
        if not lo < x < hi:
            x = 0.5 * (lo + hi)
        fx = f(x) - target
        if fx == 0 or (last is not None and abs(x - last) <= xtol * abs(x)):
            return x
        last = x
        if fx < 0:
            lo, flo = x, fx
            fhi = fhi / 2 if side == -1 else fhi     # the same end twice: halve the other's
            side = -1
        else:
            hi, fhi = x, fx
            flo = flo / 2 if side == 1 else flo
            side = 1
        if hi - lo <= xtol * abs(x):
            return x
    return x


class Law:
    """Pi(r) / D and its derivatives with r in units of d: Morse (shape alpha r0) or Mie (n, m;
    LJ is 12-6, shape Krivtsov's kappa K: Pi_K(r) = Pi(K (r - r0) + r0)) with the minimum at
    r0, cut at rc r0 (rc None: no cut), as pair_style */spline cut rc with pair_coeff's a = r0."""

    def __init__(self, name, shape, n=12.0, m=6.0, rc=None, r0=1.0):
        self.name, self.shape, self.n, self.m, self.rc, self.r0 = name, shape, n, m, rc, r0

    def with_shape(self, shape, rc=None, r0=None):
        return Law(self.name, shape, self.n, self.m, rc, self.r0 if r0 is None else r0)

    def with_r0(self, r0):
        return Law(self.name, self.shape, self.n, self.m, self.rc, r0)

    def derivatives(self, r):
        """(Pi, dPi/dr, d2Pi/dr2) at r (arrays, r in d); zero at and beyond the cut."""
        y = r / self.r0
        if self.name == "morse":
            k = self.shape
            e = np.exp(-k * (y - 1))
            out = [e * e - 2 * e, -2 * k * (e * e - e) / self.r0,
                   2 * k * k * (2 * e * e - e) / self.r0 ** 2]
        else:
            n, m, k = self.n, self.m, self.shape
            x = k * (y - 1) + 1
            out = [(m * x ** -n - n * x ** -m) / (n - m),
                   k * n * m * (x ** (-m - 1) - x ** (-n - 1)) / (n - m) / self.r0,
                   k * k * n * m * ((n + 1) * x ** (-n - 2) - (m + 1) * x ** (-m - 2))
                   / (n - m) / self.r0 ** 2]
        if self.rc is not None:
            inside = y < self.rc
            out = [np.where(inside, f, 0.0) for f in out]
        return out

    def core(self):
        """The smallest r / r0 at which the law is defined (Mie with kappa K > 1: where
        K (r/r0 - 1) + 1 reaches 0; Morse: none, 0)."""
        return 0.0 if self.name == "morse" or self.shape <= 1 else 1 - 1 / self.shape

    def gamma(self):
        """The chain's Grueneisen coefficient -r0 Pi'''(r0) / (2 Pi''(r0))."""
        if self.name == "morse":
            return 1.5 * self.shape
        return self.shape * (self.n + self.m + 3) / 2


class Uniaxial:
    """The lattice `lattice` with a law, strained along `orientation`: the pairs closer than
    radius (default: the model's shells without a cut; with a cut, twice the cut, which
    compression to half the length may bring inside it)."""

    def __init__(self, lattice, orientation, law, radius=None):
        self.crystal = crystal(lattice)
        self.n = self.crystal.direction(orientation)
        self.lattice, self.orientation = lattice, orientation
        self.law, self.volume, self.dim = law, self.crystal.volume, self.crystal.dim
        if radius is None:
            radius = (self.crystal.model_radius() * (1 + 1e-9) if law.rc is None
                      else 2.0 * law.rc * law.r0 + 1e-9)   # compression to half the length
        self.i, self.j, self.R = self.crystal.pairs(radius)
        self.sites = len(self.crystal.sites)
        self.cross = [(a, b, (self.i == a) & (self.j == b)) for a in range(self.sites)
                      for b in range(self.sites) if a != b]

    @classmethod
    def balanced(cls, lattice, orientation, law):
        """The lattice with the law's r0 at which it is at zero pressure (bcc: between d and
        the second shell; one-shell lattices: r0 = d)."""
        if crystal(lattice).model_shells == 1:
            return cls(lattice, orientation, law.with_r0(1.0))
        hi = crystal(lattice).model_radius()
        if law.core() > 0:       # the nearest neighbours d / r0 inside the law's domain
            hi = min(hi, (1 - 1e-12) / law.core())
        pressure = lambda r0: cls(lattice, orientation, law.with_r0(r0)).pressure()
        if not pressure(1.0) < 0 < pressure(hi):
            raise ValueError(f"no r0 between d and {hi:.4g} d puts {lattice} at zero pressure")
        return cls(lattice, orientation, law.with_r0(solve(pressure, 1.0, hi, 0.0)))

    # ---- the energy per site as a function of the deformation F and the site shifts u
    def _vectors(self, F, u):
        """Pair vectors F R + u_j - u_i for deformations F (k, dim, dim), shifts u (k, s, dim)."""
        return np.einsum("kab,pb->kpa", F, self.R) + u[:, self.j] - u[:, self.i]

    def _relax(self, F):
        """Site shifts u (k, sites, dim) that minimise the energy at each F (site 0 fixed):
        Newton's method on the shifts of the other sites (none for one-site lattices)."""
        k = F.shape[0]
        u = np.zeros((k, self.sites, self.dim))
        if self.sites == 1:
            return u
        free = (self.sites - 1) * self.dim
        for _ in range(RELAX_STEPS):
            g, h = self._shift_derivatives(F, u)
            h = h + 1e-12 * np.eye(free)            # no pairs left between the sublattices
            step = np.linalg.solve(h, -g[..., None])[..., 0]
            size = np.max(np.abs(step), axis=1, keepdims=True)
            step *= np.minimum(1.0, 0.02 / np.maximum(size, 1e-300))   # no step beyond 0.02 d
            u[:, 1:] += step.reshape(k, self.sites - 1, self.dim)
            if np.max(np.abs(step)) < 1e-12:     # Newton's next step: below 1e-24 d
                break
        return u

    def _shift_derivatives(self, F, u):
        """Gradient (k, f) and Hessian (k, f, f) of the energy per site in the free shifts
        (the pairs between different sites: the others do not feel a shift)."""
        k, s, dim = F.shape[0], self.sites, self.dim
        grad = np.zeros((k, s, dim))
        hess = np.zeros((k, s, s, dim, dim))
        for a, b, pick in self.cross:
            d = np.einsum("kab,pb->kpa", F, self.R[pick]) + (u[:, b] - u[:, a])[:, None]
            r = np.linalg.norm(d, axis=-1)
            _, d1, d2 = self.law.derivatives(r)
            e = d / r[..., None]
            force = np.einsum("kp,kpa->ka", d1, e) / (2 * s)
            kab = (np.einsum("kp,kpa,kpb->kab", d2 - d1 / r, e, e)
                   + np.sum(d1 / r, axis=1)[:, None, None] * np.eye(dim)) / (2 * s)
            grad[:, b] += force
            grad[:, a] -= force
            hess[:, a, a] += kab
            hess[:, b, b] += kab
            hess[:, a, b] -= kab
            hess[:, b, a] -= kab
        hess = hess[:, 1:, 1:].transpose(0, 1, 3, 2, 4).reshape(k, (s - 1) * dim, (s - 1) * dim)
        return grad[:, 1:].reshape(k, -1), hess

    def _stress_tensor(self, F):
        """Nominal stress dE/dF / V0 (k, dim, dim) in D / d^dim and the pairs inside the cut,
        the shifts relaxed."""
        u = self._relax(F)
        d = self._vectors(F, u)
        r = np.linalg.norm(d, axis=-1)
        _, d1, _ = self.law.derivatives(r)
        p = np.einsum("kp,kpa,pb->kab", d1 / r, d, self.R) / (2 * self.sites * self.volume)
        inside = np.sum(r < (np.inf if self.law.rc is None else self.law.rc * self.law.r0),
                        axis=1)
        return p, inside

    def _uniaxial(self, eps):
        eps = np.atleast_1d(np.asarray(eps, dtype=float))
        return np.eye(self.dim) + eps[:, None, None] * np.outer(self.n, self.n)

    # ---- what a plate impact loads
    def stress(self, eps):
        """sigma(eps) along n in D / d^dim, tension positive (eps a number or an array)."""
        p = self._stress_tensor(self._uniaxial(eps))[0] @ self.n @ self.n
        return float(p[0]) if np.ndim(eps) == 0 else p.reshape(np.shape(eps))

    def pressure(self):
        """The pressure of the unstrained lattice, -trace(stress) / dim, in D / d^dim."""
        return -float(np.trace(self._stress_tensor(np.eye(self.dim)[None])[0][0])) / self.dim

    def moduli(self, h=5e-4):
        """(M, M2): d sigma / d eps and the second derivative in compression at eps = 0
        (five-point differences)."""
        s = self.stress(np.array([-2, -1, 0, 1, 2]) * h)
        m = (s[0] - 8 * s[1] + 8 * s[3] - s[4]) / (12 * h)
        m2 = -(-s[0] + 16 * s[1] - 30 * s[2] + 16 * s[3] - s[4]) / (12 * h * h)
        return m, m2

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
            us = math.sqrt(max(-self.stress(-eps), 0.0) * self.volume / eps)
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
        """The ideal tensile strength in D / d^dim: the largest stress of the stretch, pairs at
        or beyond the cut carrying nothing."""
        return self.peak()[1]

    def peak(self):
        """(strain, stress) of the ideal strength: the largest stress of a scan of the stretch,
        refined in the scan's neighbouring intervals (to just below a pair's break, or to the
        smooth maximum)."""
        if self.law.rc is None:
            return self._peak()
        # a stretch brings no pair closer, but for the shift of another site
        reach = self.law.rc * self.law.r0 + (SHIFT_REACH if self.sites > 1 else 1e-9)
        return Uniaxial(self.lattice, self.orientation, self.law, reach)._peak()

    def _peak(self):
        grid = np.linspace(0.0, self._last_break(), GRID)
        stress, inside = self._scan(grid)
        best = (0.0, float(stress[0]))
        tops = [k for k in range(len(grid)) if (k == 0 or stress[k] >= stress[k - 1]) and
                (k == len(grid) - 1 or stress[k] >= stress[k + 1])]
        for k in sorted(tops, key=lambda k: -stress[k])[:PEAKS]:
            best = max(best, (float(grid[k]), float(stress[k])), key=lambda x: x[1])
            for a, b in ((k - 1, k), (k, k + 1)):
                if 0 <= a and b < len(grid):
                    found = (self._before_break(grid[a], grid[b], inside[a])
                             if inside[a] != inside[b] else self._smooth_max(grid[a], grid[b]))
                    best = max(best, found, key=lambda x: x[1])
        return best

    def _scan(self, eps):
        p, inside = self._stress_tensor(self._uniaxial(eps))
        return p @ self.n @ self.n, inside

    def _last_break(self):
        """The strain at which the last pair inside the cut and stretched by eps breaks
        (without a cut: eps = 1); a tenth more for the internal shifts."""
        if self.law.rc is None:
            return 1.0
        rn2 = (self.R @ self.n) ** 2
        length2 = np.sum(self.R ** 2, axis=1)
        cut2 = (self.law.rc * self.law.r0) ** 2
        held = (rn2 > 1e-12) & (length2 < cut2)
        return 1.1 * float(np.max(np.sqrt(1 + (cut2 - length2[held]) / rn2[held]) - 1))

    def _before_break(self, a, b, count):
        """(strain, stress) just below the first break in (a, b): bisection on the pair count."""
        for _ in range(40):
            mid = 0.5 * (a + b)
            a, b = (mid, b) if self._scan(np.array([mid]))[1][0] == count else (a, mid)
        return float(a), float(self._scan(np.array([a]))[0][0])

    def _smooth_max(self, a, b):
        """(strain, stress) of the largest stress in [a, b] by golden-section search."""
        g = (math.sqrt(5) - 1) / 2
        for _ in range(30):
            x1, x2 = b - g * (b - a), a + g * (b - a)
            s1, s2 = self._scan(np.array([x1, x2]))[0]
            a, b = (a, x2) if s1 > s2 else (x1, b)
        x = 0.5 * (a + b)
        return x, float(self._scan(np.array([x]))[0][0])

    # ---- the elastic constants and the lattice's stability
    def stiffness(self, h=1e-3):
        """The Voigt matrix of elastic constants in D / d^dim at zero strain (engineering shear
        strains; the crystal's axes: cubic axes, hcp x [2-1-10], y [01-10], z [0001]; five-point
        differences of the stress, the internal shifts relaxed)."""
        voigt = {1: [(0, 0)], 2: [(0, 0), (1, 1), (0, 1)],
                 3: [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]}[self.dim]
        steps = (-2, -1, 1, 2)
        strains = []
        for a, b in voigt:
            for k in steps:
                e = np.zeros((self.dim, self.dim))
                e[a, b] += k * h / (1 if a == b else 2)
                e[b, a] = e[a, b]
                strains.append(np.eye(self.dim) + e)
        p = self._stress_tensor(np.array(strains))[0]
        sigma = 0.5 * (p + p.transpose(0, 2, 1))
        rows = np.array([[s[a, b] for a, b in voigt] for s in sigma]).reshape(len(voigt), 4, -1)
        c = (rows[:, 0] - 8 * rows[:, 1] + 8 * rows[:, 2] - rows[:, 3]).T / (12 * h)
        return 0.5 * (c + c.T)

    def unstable(self):
        """Why the unstrained lattice is not stable (Born: a Voigt matrix with an eigenvalue
        <= 0; or the internal shift not at a minimum), or None when it is."""
        c = self.stiffness()
        low = float(np.min(np.linalg.eigvalsh(c)))
        if low <= 1e-6 * float(np.max(np.abs(c))):
            text = ", ".join(f"{k} = {v:.4g}" for k, v in self.constants().items())
            return (f"its elastic constants are not Born-stable ({text} D/d^{self.dim}: the "
                    f"Voigt matrix's smallest eigenvalue is {low:.3g})")
        if self.sites > 1:
            hess = self._shift_derivatives(np.eye(self.dim)[None],
                                           self._relax(np.eye(self.dim)[None]))[1][0]
            if np.min(np.linalg.eigvalsh(hess)) <= 0:
                return "its sites are not at a minimum against a shift of one sublattice"
        return None

    def constants(self):
        """The independent elastic constants of the lattice's symmetry {name: D / d^dim}
        (Voigt indices; the triangular lattice's shear is C66)."""
        c = self.stiffness()
        at = {"C11": (0, 0), "C12": (0, 1), "C13": (0, 2), "C33": (2, 2), "C44": (3, 3),
              "C66": (5, 5) if self.dim == 3 else (2, 2)}
        names = {"chain": ("C11",), "tri": ("C11", "C12", "C66"),
                 "hcp": ("C11", "C12", "C13", "C33", "C44", "C66")}.get(self.lattice,
                                                                        ("C11", "C12", "C44"))
        return {k: float(c[at[k]]) for k in names}
