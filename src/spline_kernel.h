/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the one force kernel of the spline
   pair styles, used by the serial styles (pair_spline.cpp: every list
   entry, tally ev_tally) and the /omp styles (pair_spline_omp.cpp: each
   thread's entries and forces, tally ev_tally_thr).  Compiled per law,
   tail, mode and energy/virial/newton flags.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_KERNEL_H
#define LMP_CLUSTERDYN_SPLINE_KERNEL_H

#include "pair_state.h"
#include "spline_links.h"
#include "xyz3.h"

#include "atom.h"
#include "neigh_list.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  // kernel variants: PLAIN (every kappa 1), KAPPA (some kappa != 1), CHAIN (chain N),
  // LINK and LINK_KAPPA (link L)
  struct SplineMode {
    enum { PLAIN = 0, KAPPA = 1, CHAIN = 2, LINK = 3, LINK_KAPPA = 4 };
    static constexpr bool kappa(int mode) { return mode != PLAIN && mode != LINK; }
    static constexpr bool link(int mode) { return mode == LINK || mode == LINK_KAPPA; }
  };

  // chain N: how far apart along the chain two atoms are (0: a periodic image of one atom)
  inline tagint chain_distance(tagint a, tagint b)
  {
    return a > b ? a - b : b - a;
  }

  // what the kernel reads of the pair style
  struct SplineKernelData {
    const SplineCoeff *coeffs;        // (ntypes+1)^2
    const LinkCoeff *link_coeffs;     // link modes: (ntypes+1)^2
    Making making;                    // link modes: how unlinked pairs link during a run
    int chain_n;
    const double *chain_scale;        // 1/n^2
  };

  // the pairs of list entries iifrom..iito-1: forces into f, energy and virial through
  // tally(i, j, nlocal, newton, evdwl, fpair, dx, dy, dz), state changes into changes;
  // singular(i, j, rsq) stops at a pair inside the law's singular distance
  template <class Law, class TailT, int MODE, int EVFLAG, int EFLAG, int NEWTON_PAIR, class Tally,
            class Singular>
  void spline_kernel(const SplineKernelData &k, const NeighList *list, const Atom *atom,
                     const double *special_lj, int iifrom, int iito, xyz3 *f,
                     const StatePass &pass, StateTally &changes, Tally &&tally,
                     Singular &&singular)
  {
    constexpr bool LINKED = SplineMode::link(MODE);
    constexpr bool KAPPA_ON = SplineMode::kappa(MODE);
    const tagint *_noalias const tag = atom->tag;
    const auto *_noalias const x = (xyz3 *) atom->x[0];
    const int *_noalias const type = atom->type;
    const int nlocal = atom->nlocal;
    const int ntp1 = atom->ntypes + 1;
    const int *_noalias const ilist = list->ilist;
    const int *_noalias const numneigh = list->numneigh;
    int **firstneigh = list->firstneigh;
    const SplineCoeff *_noalias const coeffs = k.coeffs;
    const LinkCoeff *const link_coeffs = k.link_coeffs;
    const Making making = k.making;
    const int chain_n = k.chain_n;
    const double *const chain_scale = k.chain_scale;
    int *const *const words = pass.words;
    const tagint *const fresh = pass.fresh;
    const int trial = pass.trial;
    double evdwl = 0.0;

    for (int ii = iifrom; ii < iito; ii++) {
      const int i = ilist[ii];
      const double xtmp = x[i].x, ytmp = x[i].y, ztmp = x[i].z;
      const SplineCoeff *_noalias const ci = coeffs + type[i] * ntp1;
      const LinkCoeff *const lci = LINKED ? link_coeffs + type[i] * ntp1 : nullptr;
      const int *_noalias const jlist = firstneigh[i];
      const int jnum = numneigh[i];
      double fxtmp = 0.0, fytmp = 0.0, fztmp = 0.0;

      for (int jj = 0; jj < jnum; jj++) {
        int j = jlist[jj];
        const double factor_lj = special_lj[j >> SBBITS & 3];
        j &= NEIGHMASK;
        const double delx = xtmp - x[j].x;
        const double dely = ytmp - x[j].y;
        const double delz = ztmp - x[j].z;
        const double rsq = delx * delx + dely * dely + delz * delz;
        const SplineCoeff &c = ci[type[j]];
        double scale = 1.0;    // chain: the n-th neighbour along the chain feels Pi(r/n)
        if (MODE == SplineMode::CHAIN) {
          const tagint n = chain_distance(tag[i], tag[j]);
          if (n == 0 || n > chain_n) continue;
          scale = chain_scale[n];
        }
        const double rsq_law = MODE == SplineMode::CHAIN ? rsq * scale : rsq;
        double e, fpair;
        if constexpr (LINKED) {
          int &word = words[i][jj];
          const Making now = fresh && (!fresh[i] || !fresh[j]) ? MAKE_INITIAL : making;
          const double w = NEWTON_PAIR || j < nlocal ? 1.0 : 0.5;
          const LinkCoeff &lc = lci[type[j]];
          bool on;
          if (!trial) {    // the word is the state
            on = SplineLinks::eval<TailT, KAPPA_ON, Law>(c, lc, rsq_law, word, now, w, changes, e,
                                                         fpair);
          } else {    // a minimizer's trial point: the change is only marked
            int linked = word & 1;
            on = SplineLinks::eval<TailT, KAPPA_ON, Law>(c, lc, rsq_law, linked, now, w, changes,
                                                         e, fpair);
            word = state_word(word, linked, 1);
          }
          if (!on) continue;
        } else {
          if (rsq_law >= c.cutsq) continue;
          e = TailT::template eval<KAPPA_ON, Law>(c, rsq_law, fpair) - c.offset;
        }
        if (rsq_law <= c.hardsq) singular(i, j, rsq);
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
