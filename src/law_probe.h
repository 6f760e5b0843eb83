/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the interaction law of one type pair
   as a function of r, seen through a pair style (compute pair/params).

   AnalyticProbe uses this package's pair styles (LawSource): exact to
   round-off.  SingleProbe works with any pair style that has single():
   energy and force from single(), Pi'' and Pi''' by central differences of
   the force with Richardson extrapolation (steps h and h/2 for Pi'', 10 h and
   5 h for Pi''', h = 1e-4 a).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_LAW_PROBE_H
#define LMP_CLUSTERDYN_LAW_PROBE_H

#include "law_source.h"
#include "pair.h"

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class LawProbe {
   public:
    virtual ~LawProbe() = default;
    virtual double energy(double r) = 0;
    virtual double force(double r) = 0;    // f = -Pi' (positive = repulsion)
    virtual double d2(double r) = 0;       // Pi''
    virtual double d3(double r) = 0;       // Pi'''
  };

  class AnalyticProbe : public LawProbe {
   public:
    AnalyticProbe(const LawSource *law, int i, int j, bool tail) :
        law(law), i(i), j(j), tail(tail)
    {
    }
    double energy(double r) override { return at(r)[0]; }
    double force(double r) override { return -at(r)[1]; }
    double d2(double r) override { return at(r)[2]; }
    double d3(double r) override { return at(r)[3]; }

   private:
    const LawSource *law;
    int i, j;
    bool tail;
    double d[4];
    const double *at(double r)
    {
      law->law_derivs(i, j, r, d, tail);
      return d;
    }
  };

  class SingleProbe : public LawProbe {
   public:
    SingleProbe(Pair *pair, int i, int j, double h) : pair(pair), i(i), j(j), h(h) {}
    double energy(double r) override
    {
      double fforce;
      return pair->single(0, 0, i, j, r * r, 1.0, 1.0, fforce);
    }
    double force(double r) override
    {
      double fforce;
      pair->single(0, 0, i, j, r * r, 1.0, 1.0, fforce);
      return fforce * r;
    }
    double d2(double r) override
    {
      auto diff = [&](double s) { return -(force(r + s) - force(r - s)) / (2.0 * s); };
      return (4.0 * diff(0.5 * h) - diff(h)) / 3.0;
    }
    double d3(double r) override
    {
      const double f0 = force(r);
      auto diff = [&](double s) { return -(force(r + s) - 2.0 * f0 + force(r - s)) / (s * s); };
      return (4.0 * diff(5.0 * h) - diff(10.0 * h)) / 3.0;
    }

   private:
    Pair *pair;
    int i, j;
    double h;    // step of the differences: 1e-4 a
  };

  // a root of f in [lo, hi] where f(lo) and f(hi) have opposite signs, by bisection
  // to round-off
  template <class F> double bisect(F f, double lo, double hi)
  {
    const bool rising = f(lo) < 0.0;
    for (int iter = 0; iter < 200 && hi - lo > 4e-16 * hi; iter++) {
      const double mid = 0.5 * (lo + hi);
      if ((f(mid) < 0.0) == rising) lo = mid;
      else hi = mid;
    }
    return 0.5 * (lo + hi);
  }

  // the minimum of f in [lo, hi] (unimodal there), by golden-section search
  template <class F> double golden_min(F f, double lo, double hi)
  {
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = f(x1), f2 = f(x2);
    for (int iter = 0; iter < 200 && hi - lo > 1e-12 * hi; iter++) {
      if (f1 < f2) {
        hi = x2;
        x2 = x1;
        f2 = f1;
        x1 = hi - g * (hi - lo);
        f1 = f(x1);
      } else {
        lo = x1;
        x1 = x2;
        f1 = f2;
        x2 = lo + g * (hi - lo);
        f2 = f(x2);
      }
    }
    return 0.5 * (lo + hi);
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
