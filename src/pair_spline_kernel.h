/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the one force kernel of the spline
   pair styles, used by the serial styles (pair_spline.cpp, tally ev_tally)
   and the /omp styles (pair_spline_omp.cpp, each thread's entries and
   forces, tally ev_tally_thr).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_SPLINE_KERNEL_H
#define LMP_CLUSTERDYN_PAIR_SPLINE_KERNEL_H

#include "pair_spline.h"

#include "neigh_list.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  // chain N: how far apart along the chain two atoms are (0: a periodic image of one atom)
  inline tagint chain_distance(tagint a, tagint b)
  {
    return a > b ? a - b : b - a;
  }

  template <class Law>
  template <class TailT, int MODE, int EVFLAG, int EFLAG, int NEWTON_PAIR, class Tally>
  void PairSpline<Law>::eval(int iifrom, int iito, xyz3 *f, const StatePass &pass,
                             StateTally &changes, Tally &&tally) const
  {
    constexpr bool LINKED = mode_link(MODE);
    constexpr bool KAPPA_ON = mode_kappa(MODE);
    const Making making = links.making();
    const tagint *_noalias const tag = atom->tag;
    const auto *_noalias const x = (xyz3 *) atom->x[0];
    const int *_noalias const type = atom->type;
    const int nlocal = atom->nlocal;
    const double *_noalias const special_lj = force->special_lj;
    const int ntp1 = atom->ntypes + 1;
    const int *_noalias const ilist = list->ilist;
    const int *_noalias const numneigh = list->numneigh;
    int **firstneigh = list->firstneigh;
    double evdwl = 0.0;

    for (int ii = iifrom; ii < iito; ii++) {
      const int i = ilist[ii];
      const double xtmp = x[i].x, ytmp = x[i].y, ztmp = x[i].z;
      const SplineCoeff *_noalias const ci = coeffs + type[i] * ntp1;
      const LinkCoeff *const lci = LINKED ? links.coeff.data() + type[i] * ntp1 : nullptr;
      const int *_noalias const jlist = firstneigh[i];
      const int jnum = numneigh[i];
      double fxtmp = 0.0, fytmp = 0.0, fztmp = 0.0;

      for (int jj = 0; jj < jnum; jj++) {
        int j = jlist[jj];
        const double factor_lj = special_lj[sbmask(j)];
        j &= NEIGHMASK;
        const double delx = xtmp - x[j].x;
        const double dely = ytmp - x[j].y;
        const double delz = ztmp - x[j].z;
        const double rsq = delx * delx + dely * dely + delz * delz;
        const SplineCoeff &c = ci[type[j]];
        double scale = 1.0;    // chain: the n-th neighbour along the chain feels Pi(r/n)
        if (MODE == CHAIN) {
          const tagint n = chain_distance(tag[i], tag[j]);
          if (n == 0 || n > chain_n) continue;
          scale = chain_scale[n];
        }
        const double rsq_law = MODE == CHAIN ? rsq * scale : rsq;
        double e, fpair;
        if constexpr (LINKED) {
          int &word = pass.words[i][jj];
          int linked = pass.trial ? word & 1 : word;
          const Making now = pass.fresh && (!pass.fresh[i] || !pass.fresh[j]) ? MAKE_INITIAL
                                                                              : making;
          const double w = NEWTON_PAIR || j < nlocal ? 1.0 : 0.5;
          const bool on = SplineLinks::eval<TailT, KAPPA_ON, Law>(c, lci[type[j]], rsq_law, linked,
                                                                  now, w, changes, e, fpair);
          word = state_word(word, linked, pass.trial);
          if (!on) continue;
        } else {
          if (rsq_law >= c.cutsq) continue;
          e = TailT::template eval<KAPPA_ON, Law>(c, rsq_law, fpair) - c.offset;
        }
        if (rsq_law <= c.hardsq) singular_error(i, j, rsq);
        fpair *= factor_lj * scale;
        fxtmp += delx * fpair;
        fytmp += dely * fpair;
        fztmp += delz * fpair;
        if (NEWTON_PAIR || j < nlocal) {
          f[j].x -= delx * fpair;
          f[j].y -= dely * fpair;
          f[j].z -= delz * fpair;
        }
        if (EFLAG) evdwl = factor_lj * e;
        if (EVFLAG) tally(i, j, nlocal, NEWTON_PAIR, evdwl, fpair, delx, dely, delz);
      }
      f[i].x += fxtmp;
      f[i].y += fytmp;
      f[i].z += fztmp;
    }
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
