"""The laws' formulas (Krivtsov & Krivtsova 2002, restated in doc/pair_spline.rst) written out
independently of the plugin: base laws, the kappa modification, the inflection point,
the Wagner and Lagunov tails, and the same law as a `pair_style lepton` expression."""
import math
from dataclasses import dataclass


@dataclass
class Law:
    base: str           # morse | lj | mie | harmonic
    D: float
    a: float
    alpha: float = 0.0  # morse, harmonic
    n: float = 12.0     # mie
    m: float = 6.0
    kappa: float = 1.0

    # pair_coeff arguments of the plugin's style
    def style(self):
        return f"{self.base}/spline"

    def coeff(self):
        args = {"morse": f"{self.D!r} {self.alpha!r} {self.a!r}",
                "harmonic": f"{self.D!r} {self.alpha!r} {self.a!r}",
                "lj": f"{self.D!r} {self.a!r}",
                "mie": f"{self.D!r} {self.a!r} {self.n!r} {self.m!r}"}[self.base]
        return args + f" kappa {self.kappa!r}"

    # the unmodified base: Pi(s) and f(s) = -Pi'(s)
    def pi0(self, s):
        D, a = self.D, self.a
        if self.base == "morse":
            e = math.exp(-self.alpha * (s - a))
            return D * (e * e - 2 * e)
        if self.base == "harmonic":
            return self.alpha ** 2 * D * (s - a) ** 2 - D
        n, m = (12.0, 6.0) if self.base == "lj" else (self.n, self.m)
        return D / (n - m) * (m * (a / s) ** n - n * (a / s) ** m)

    def f0(self, s):
        D, a = self.D, self.a
        if self.base == "morse":
            e = math.exp(-self.alpha * (s - a))
            return 2 * self.alpha * D * (e * e - e)
        if self.base == "harmonic":
            return -2 * self.alpha ** 2 * D * (s - a)
        n, m = (12.0, 6.0) if self.base == "lj" else (self.n, self.m)
        return n * m * D / ((n - m) * a) * ((a / s) ** (n + 1) - (a / s) ** (m + 1))

    # the kappa-modified base
    def s(self, r):
        return self.kappa * (r - self.a) + self.a

    def pi(self, r):
        return self.pi0(self.s(r))

    def f(self, r):
        return self.kappa * self.f0(self.s(r))

    def b(self):
        a = self.a
        if self.base == "morse":
            b0 = a + math.log(2) / self.alpha
        elif self.base == "lj":
            b0 = a * (13 / 7) ** (1 / 6)
        elif self.base == "mie":
            b0 = a * ((self.n + 1) / (self.m + 1)) ** (1 / (self.n - self.m))
        else:
            return None
        return a + (b0 - a) / self.kappa

    def wagner(self):
        """(b, ac, a2, a3) of the Wagner-Holian-Voter tail."""
        b = self.b()
        fs = abs(self.f(b))
        ac2 = b * b * (5 - math.sqrt(16 + 24 * self.pi(b) / (b * fs)))
        a2 = (5 * b * b - ac2) * fs / (8 * b ** 3 * (ac2 - b * b))
        a3 = (3 * b * b - ac2) * fs / (12 * b ** 3 * (ac2 - b * b) ** 2)
        return b, math.sqrt(ac2), a2, a3

    # the law with a tail: energy at r (r may be a float)
    def energy(self, tail, r, rc=None, rs=None):
        if tail == "cut":
            return self.pi(r) if r < rc * self.a else 0.0
        if tail == "wagner":
            b, ac, a2, a3 = self.wagner()
            if r <= b:
                return self.pi(r)
            w = ac * ac - r * r
            return -a2 * w * w + a3 * w ** 3 if r < ac else 0.0
        rs = rs * self.a if rs else self.b()
        rc = rc * self.a
        if r <= rs:
            return self.pi(r)
        return self.pi(r) * (1 - ((r - rs) / (rc - rs)) ** 2) ** 2 if r < rc else 0.0

    # the same law as a lepton expression of r, and its cutoff
    def lepton(self, tail, rc=None, rs=None):
        s = f"({self.kappa!r}*(r-{self.a!r})+{self.a!r})"
        D, a = repr(self.D), repr(self.a)
        if self.base == "morse":
            al = repr(self.alpha)
            base = f"{D}*(exp(-2*{al}*({s}-{a}))-2*exp(-{al}*({s}-{a})))"
        elif self.base == "harmonic":
            base = f"{self.alpha ** 2 * self.D!r}*({s}-{a})^2-{D}"
        else:
            n, m = (12.0, 6.0) if self.base == "lj" else (self.n, self.m)
            base = f"{self.D / (n - m)!r}*({m!r}*({a}/{s})^{n!r}-{n!r}*({a}/{s})^{m!r})"
        if tail == "cut":
            return base, rc * self.a
        if tail == "wagner":
            b, ac, a2, a3 = self.wagner()
            w = f"({ac * ac!r}-r^2)"
            return f"select(step(r-{b!r}),-{a2!r}*{w}^2+{a3!r}*{w}^3,{base})", ac
        rs = rs * self.a if rs else self.b()
        k = f"(1-((r-{rs!r})/{rc * self.a - rs!r})^2)^2"
        return f"select(step(r-{rs!r}),({base})*{k},{base})", rc * self.a
