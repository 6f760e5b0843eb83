/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the tails of the spline pair styles,
   stateless policies beside the laws of spline_laws.h.

   Each tail is a struct used as a template argument:
     derive<Law>()  the tail's kernel constants (SplineCoeff rc, and bsq, acsq,
                    wa2, wa3 or rs, rssq, inv_l2) from the kappa-modified base;
                    errors name the type pair
     eval<KAPPA, Law, SIMD>()  energy (unshifted) and fpair of a pair inside
                    the interaction end (rsq < c.cutsq); SIMD (the block's
                    simd loop, spline_block.h): without a branch, each choice
                    a blend of both sides (vector_math.h), so that AVX2
                    vectorizes it as AVX-512 does; else (one pair at a time)
                    a branch may skip what the pair does not need
     derivs<Law>()  Pi, Pi', Pi'', Pi''' of the law with the tail at r < rc
   cut: the law up to Rc a.  wagner: Wagner, Holian & Voter's cubic spline
   from the inflection point b to its end ac.  lagunov: Lagunov & Sinani's
   smoothing (1 - (r - Rs)^2/(Rc - Rs)^2)^2 from Rs to Rc.
   Formulas: doc/pair_spline.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_TAILS_H
#define LMP_CLUSTERDYN_SPLINE_TAILS_H

#include "spline_laws.h"
#include "vector_math.h"

#include <cmath>
#include <utility>

namespace LAMMPS_NS {
namespace ClusterDyn {

  enum Tail { CUT = 0, WAGNER = 1, LAGUNOV = 2 };

  // what a tail needs of the kappa-modified base and of the input (units of a)
  struct TailShape {
    double b, pib, fstar;    // inflection point, Pi(b), bond strength f* (0 without)
    double rc_rel, rs_rel;   // Rc and Rs in units of a (0: not given)
    int i, j;                // the type pair, for messages
  };

  // Pi .. Pi''' of the kappa-modified base at r
  template <class Law> inline void kappa_derivs(const SplineCoeff &c, double r, double *d)
  {
    double base[4];
    Law::derivs(c, c.kappa * (r - c.a) + c.a, base);
    const double k = c.kappa;
    d[0] = base[0];
    d[1] = k * base[1];
    d[2] = k * k * base[2];
    d[3] = k * k * k * base[3];
  }

  struct CutTail {
    static constexpr int id = CUT;
    template <class Law> static void derive(SplineCoeff &c, const TailShape &s, LAMMPS *)
    {
      c.rc = s.rc_rel * c.a;
    }
    template <bool KAPPA, class Law, bool SIMD = false>
    static inline double eval(const SplineCoeff &c, double rsq, double &fpair)
    {
      return Law::template eval<KAPPA>(c, rsq, fpair);
    }
    template <class Law> static void derivs(const SplineCoeff &c, double r, double *d)
    {
      kappa_derivs<Law>(c, r, d);
    }
  };

  struct WagnerTail {
    static constexpr int id = WAGNER;
    template <class Law> static void derive(SplineCoeff &c, const TailShape &s, LAMMPS *lmp)
    {
      const double b = s.b, fstar = s.fstar;
      const double disc = 16.0 + 24.0 * s.pib / (b * fstar);
      if (disc < 0.0)
        lmp->error->all(FLERR, "Pair {}: tail wagner has no cutoff for types {} {} ({}): the "
                        "well is too wide, 16 + 24 Pi(b)/(b f*) = {:.6g} < 0", Law::style, s.i,
                        s.j, Law::wide_well_hint, disc);
      const double b2 = b * b;
      c.bsq = b2;
      c.acsq = b2 * (5.0 - sqrt(disc));
      c.wa2 = (5.0 * b2 - c.acsq) * fstar / (8.0 * b2 * b * (c.acsq - b2));
      c.wa3 = (3.0 * b2 - c.acsq) * fstar / (12.0 * b2 * b * (c.acsq - b2) * (c.acsq - b2));
      c.rc = sqrt(c.acsq);
    }
    template <bool KAPPA, class Law, bool SIMD = false>
    static inline double eval(const SplineCoeff &c, double rsq, double &fpair)
    {
      // both sides for every pair, also one at a time: pairs on both sides of b alternate
      // in a list, and a branch between them mispredicts (doc/benchmarks/bench_pair_spline.md)
      double flaw;
      const double elaw = Law::template eval<KAPPA>(c, rsq, flaw);
      const double w = c.acsq - rsq;
      const bool spline = rsq >= c.bsq;
      fpair = blend(spline, 2.0 * w * (3.0 * c.wa3 * w - 2.0 * c.wa2), flaw);
      return blend(spline, w * w * (c.wa3 * w - c.wa2), elaw);
    }
    template <class Law> static void derivs(const SplineCoeff &c, double r, double *d)
    {
      if (r * r < c.bsq) return kappa_derivs<Law>(c, r, d);
      const double w = c.acsq - r * r;
      const double g = w * (3.0 * c.wa3 * w - 2.0 * c.wa2);    // dPi/dw
      const double g1 = 6.0 * c.wa3 * w - 2.0 * c.wa2;           // d2Pi/dw2
      d[0] = w * w * (c.wa3 * w - c.wa2);
      d[1] = -2.0 * r * g;
      d[2] = -2.0 * g + 4.0 * r * r * g1;
      d[3] = 12.0 * r * g1 - 48.0 * c.wa3 * r * r * r;
    }
  };

  struct LagunovTail {
    static constexpr int id = LAGUNOV;
    template <class Law> static void derive(SplineCoeff &c, const TailShape &s, LAMMPS *lmp)
    {
      c.rs = s.rs_rel > 0.0 ? s.rs_rel * c.a : s.b;
      if (!(c.rs > 0.0))
        lmp->error->all(FLERR, "Pair {}: tail lagunov needs a start Rs for types {} {} "
                        "(pair_style ... start Rs or pair_coeff ... rs Rs): the law has no "
                        "inflection point", Law::style, s.i, s.j);
      c.rc = s.rc_rel * c.a;
      if (!(c.rc > c.rs))
        lmp->error->all(FLERR, "Pair {}: lagunov Rc = {} a must be > its start Rs = {:.6g} a "
                        "for types {} {}", Law::style, s.rc_rel, c.rs / c.a, s.i, s.j);
      c.rssq = c.rs * c.rs;
      c.inv_l2 = 1.0 / ((c.rc - c.rs) * (c.rc - c.rs));
    }
    template <bool KAPPA, class Law, bool SIMD = false>
    static inline double eval(const SplineCoeff &c, double rsq, double &fpair)
    {
      double fbase;
      const double e = Law::template eval<KAPPA>(c, rsq, fbase);
      // one pair at a time: most pairs lie before Rs, where a branch (well predicted) saves
      // the root and the division
      if (!SIMD && rsq < c.rssq) {
        fpair = fbase;
        return e;
      }
      const double r = sqrt(rsq);
      const double x = blend(rsq >= c.rssq, r - c.rs, 0.0);    // 0 before Rs: m = 1
      const double m = 1.0 - x * x * c.inv_l2;
      fpair = m * (fbase * m + 4.0 * x * c.inv_l2 * e / r);
      return e * m * m;
    }
    template <class Law> static void derivs(const SplineCoeff &c, double r, double *d)
    {
      kappa_derivs<Law>(c, r, d);
      if (r < c.rs) return;
      const double l = c.inv_l2;
      const double x = r - c.rs;
      const double m = 1.0 - x * x * l;
      const double k0 = m * m, k1 = -4.0 * x * m * l, k2 = -4.0 * l * (m - 2.0 * x * x * l);
      const double k3 = 24.0 * x * l * l;
      d[3] = d[3] * k0 + 3.0 * d[2] * k1 + 3.0 * d[1] * k2 + d[0] * k3;
      d[2] = d[2] * k0 + 2.0 * d[1] * k1 + d[0] * k2;
      d[1] = d[1] * k0 + d[0] * k1;
      d[0] *= k0;
    }
    // the inflection point of the smoothed law: the base's b unless the smoothing starts
    // before it, then the first zero of Pi'' in (Rs, Rc) (0 if there is none)
    template <class Law> static double inflection(const SplineCoeff &c, double b)
    {
      if (b > 0.0 && c.rs >= b) return b;
      double lo = c.a > c.rs ? c.a : c.rs, hi = c.rc, d[4];
      derivs<Law>(c, lo, d);
      if (d[2] <= 0.0) return lo;
      derivs<Law>(c, hi * (1.0 - 1e-12), d);
      if (d[2] > 0.0) return 0.0;
      while (hi - lo > 1e-15 * hi) {
        const double mid = 0.5 * (lo + hi);
        derivs<Law>(c, mid, d);
        if (d[2] > 0.0) lo = mid;
        else hi = mid;
      }
      return 0.5 * (lo + hi);
    }
  };

  // calls run(Tail()) with the tail policy of a runtime tail id
  template <class Run> inline decltype(auto) with_tail(int tail, Run &&run)
  {
    if (tail == CUT) return run(CutTail());
    if (tail == WAGNER) return run(WagnerTail());
    return run(LagunovTail());
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
