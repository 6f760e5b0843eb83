/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the law of one type pair as the
   spline pair styles apply it (the kappa-modified base, its tail and the
   shift), one distance at a time outside the force loop: single(),
   born_matrix() and the LawSource that compute pair/params and the
   time-step check read.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_PAIR_LAW_H
#define LMP_CLUSTERDYN_SPLINE_PAIR_LAW_H

#include "spline_tails.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  // Pi, Pi', Pi'', Pi''' at r: with the tail and shift (tailed), or the kappa-modified base
  template <class Law>
  inline void pair_law_derivs(const SplineCoeff &c, int tail, double r, double *d, bool tailed)
  {
    if (!tailed) return kappa_derivs<Law>(c, r, d);
    if (r >= c.rc) {
      d[0] = d[1] = d[2] = d[3] = 0.0;
      return;
    }
    with_tail(tail, [&](auto t) { decltype(t)::template derivs<Law>(c, r, d); });
    d[0] -= c.offset;
  }

  // the inflection point b > a: the base's unless a lagunov tail starts before it, 0 if none
  template <class Law> inline double pair_law_inflection(const SplineCoeff &c, int tail)
  {
    const bool lagunov = tail == LAGUNOV;
    if (!Law::has_inflection && !lagunov) return 0.0;
    const double b = Law::has_inflection ? c.a + (Law::inflection(c) - c.a) / c.kappa : 0.0;
    return lagunov ? LagunovTail::inflection<Law>(c, b) : b;
  }

  // the energy at rsq (shifted), fpair the force / r; both 0 at and beyond the interaction end
  template <class Law>
  inline double pair_law_energy(const SplineCoeff &c, int tail, double rsq, double &fpair)
  {
    fpair = 0.0;
    if (rsq >= c.cutsq) return 0.0;
    const double e = with_tail(tail, [&](auto t) {
      return decltype(t)::template eval<true, Law>(c, rsq, fpair);
    });
    return e - c.offset;
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
