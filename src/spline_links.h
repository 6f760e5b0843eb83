/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the link model of the spline pair
   styles (pair_style ... link L [relink yes]), a stateless rule beside the
   laws and tails; the state itself is kept by PairState (pair_state.h).

   A linked pair feels the full law and tail up to Rc a, where the link
   breaks for good; an unlinked pair feels only the repulsive branch r < a,
   shifted to zero at a.  Pairs closer than L a are linked when their atoms
   are fresh (the first setup, atoms created since) and, with relink yes,
   on every step.  Formulas and the energy balance: doc/pair_spline.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_LINKS_H
#define LMP_CLUSTERDYN_SPLINE_LINKS_H

#include "pair_state.h"
#include "spline_tails.h"

#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct LinkCoeff {
    double linksq;    // (L a)^2
    double asq;       // a^2
    double ea;        // the law's energy at a (the unlinked branch is shifted by it)
    double ebreak;    // the energy a link holds as it breaks at Rc a (cut tail; 0 else)
  };

  class SplineLinks {
   public:
    double l = 0.0;               // L in units of a; 0 = off
    int relink = 0;               // unlinked pairs closer than L a link again
    std::vector<LinkCoeff> coeff;    // per type pair, as the pair style's coefficients

    bool on() const { return l > 0.0; }
    Making making() const { return relink ? MAKE_AGAIN : MAKE_NONE; }

    // the link constants of type pair i,j of law coefficients c (tail and shift derived)
    template <class Law>
    void derive(const SplineCoeff &c, int tail, int i, int j, int np1, LAMMPS *lmp)
    {
      if (coeff.size() != (size_t) np1 * np1) coeff.assign(np1 * np1, LinkCoeff());
      if (l * c.a > c.rc)
        lmp->error->all(FLERR, "Pair {}: link L = {} is beyond the tail end of types {} {} "
                        "({:.6g} a): a pair linked there would break at once", Law::style, l,
                        i, j, c.rc / c.a);
      LinkCoeff &k = coeff[i * np1 + j];
      k.linksq = l * l * c.a * c.a;
      k.asq = c.a * c.a;
      double f;
      k.ea = Law::template eval<true>(c, k.asq, f);
      k.ebreak = tail == CUT ? Law::template eval<true>(c, c.cutsq, f) - c.offset : 0.0;
      coeff[j * np1 + i] = k;
    }

    // energy (shifted) and fpair of a pair, updating its state linked; false when the pair
    // does not interact.  et, ft: the law with the tail at rsq, shifted (the kernel's vector
    // stage; valid for rsq < c.cutsq).  w: the pair's weight in the tally t.
    template <class Tail, bool KAPPA, class Law>
    static inline bool eval(const SplineCoeff &c, const LinkCoeff &k, double rsq, int &linked,
                            int making, double w, StateTally &t, double et, double ft,
                            double &e, double &fpair)
    {
      if (linked) {
        if (rsq >= c.cutsq) {
          linked = 0;
          t.broken += w;
          t.ejump -= w * k.ebreak;
          return false;
        }
      } else if (making != MAKE_NONE && rsq < k.linksq) {
        linked = 1;
        if (making == MAKE_AGAIN) {
          double f;
          const double eu = rsq < k.asq ? Law::template eval<KAPPA>(c, rsq, f) - k.ea : 0.0;
          t.formed += w;
          t.ejump += w * (et - eu);
        }
      }
      if (linked) {
        e = et;
        fpair = ft;
        return true;
      }
      if (rsq >= k.asq) return false;
      e = Law::template eval<KAPPA>(c, rsq, fpair) - k.ea;
      return true;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
