/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the one force kernel of the spline
   pair styles, used by the serial styles (pair_spline.cpp: every list
   entry, tally ev_tally) and the /omp styles (pair_spline_omp.cpp: each
   thread's entries and forces, tally ev_tally_thr).  Compiled per law,
   tail, mode and energy/virial/newton flags.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_KERNEL_H
#define LMP_CLUSTERDYN_SPLINE_KERNEL_H

#include "damping_pass.h"
#include "pair_state.h"
#include "spline_block.h"
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
    const DampingPass *damping;       // DAMP: fix viscous/relative's forces into damping->fd
  };

  // the pairs of list entries iifrom..iito-1: forces into f, energy and virial through
  // tally(i, j, nlocal, newton, evdwl, fpair, dx, dy, dz), state changes into changes;
  // singular(i, j, rsq) stops at a pair inside the law's singular distance.
  // DAMP (PLAIN and KAPPA modes): also fix viscous/relative's damping forces of the same pairs
  // into k.damping->fd, in list order as the fix's own loop sums them (damping_pass.h).
  // Blocks of pairs (spline_block.h): the vector stage computes separations and the law with
  // its tail; this loop then applies the link rule and scatters in list order.
  template <class Law, class TailT, int MODE, int EVFLAG, int EFLAG, int NEWTON_PAIR, int DAMP,
            class Tally, class Singular>
  void spline_kernel(const SplineKernelData &k, const NeighList *list, const Atom *atom,
                     const double *special_lj, int iifrom, int iito, xyz3 *f,
                     const StatePass &pass, StateTally &changes, Tally &&tally,
                     Singular &&singular)
  {
    constexpr bool LINKED = SplineMode::link(MODE);
    constexpr bool KAPPA_ON = SplineMode::kappa(MODE);
    constexpr bool CHAIN = MODE == SplineMode::CHAIN;
    // the law in the block's SIMD loop: a transcendental function, or kappa's root and quotient
    constexpr bool BLOCK = Law::vector_stage || KAPPA_ON;
    static_assert(!DAMP || MODE == SplineMode::PLAIN || MODE == SplineMode::KAPPA,
                  "the damping pass covers every pair inside the interaction end");
    const tagint *_noalias const tag = atom->tag;
    const auto *_noalias const x = (xyz3 *) atom->x[0];
    const int *_noalias const type = atom->type;
    const int nlocal = atom->nlocal;
    const int ntp1 = atom->ntypes + 1;
    const bool uniform = atom->ntypes == 1;
    const int *_noalias const ilist = list->ilist;
    const int *_noalias const numneigh = list->numneigh;
    int **firstneigh = list->firstneigh;
    const SplineCoeff *_noalias const coeffs = k.coeffs;
    const LinkCoeff *const link_coeffs = k.link_coeffs;
    const Making making = k.making;
    int *const *const words = pass.words;
    const tagint *const fresh = pass.fresh;
    const int trial = pass.trial;
    const auto *_noalias const v = (const xyz3 *) atom->v[0];
    xyz3 *const fd = DAMP ? k.damping->fd : nullptr;
    SplineBlock b;

    // f[i] is summed over i's pairs first, across blocks, as a scalar loop would
    int icur = -1;
    double fxtmp = 0.0, fytmp = 0.0, fztmp = 0.0;
    double dxtmp = 0.0, dytmp = 0.0, dztmp = 0.0;    // DAMP: the damping force on icur
    auto flush = [&]() {
      if (icur < 0) return;
      f[icur].x += fxtmp;
      f[icur].y += fytmp;
      f[icur].z += fztmp;
      if (DAMP) {
        fd[icur].x += dxtmp;
        fd[icur].y += dytmp;
        fd[icur].z += dztmp;
      }
    };

    // one pair, in list order: the link rule, special factors, forces, tallies; et and ft are
    // the law with its tail at rsq, df the damping force on i
    auto apply = [&](int i, int jraw, int jj, int tp, double delx, double dely, double delz,
                     double rsq, double scale, double et, double ft, const xyz3 &df) {
      const int j = jraw & NEIGHMASK;
      if (i != icur) {
        flush();
        icur = i;
        fxtmp = fytmp = fztmp = 0.0;
        dxtmp = dytmp = dztmp = 0.0;
      }
      if (DAMP) {
        dxtmp += df.x;
        dytmp += df.y;
        dztmp += df.z;
        if (NEWTON_PAIR || j < nlocal) {
          fd[j].x -= df.x;
          fd[j].y -= df.y;
          fd[j].z -= df.z;
        }
      }
      double e = et, fpair = ft;
      if constexpr (LINKED) {
        const SplineCoeff &c = coeffs[tp];
        int &word = words[i][jj];
        const Making now = fresh && (!fresh[i] || !fresh[j]) ? MAKE_INITIAL : making;
        const double w = NEWTON_PAIR || j < nlocal ? 1.0 : 0.5;
        const LinkCoeff &lc = link_coeffs[tp];
        bool on;
        if (!trial) {    // the word is the state
          on = SplineLinks::eval<TailT, KAPPA_ON, Law>(c, lc, rsq, word, now, w, changes, et, ft,
                                                       e, fpair);
        } else {    // a minimizer's trial point: the change is only marked
          int linked = word & 1;
          on = SplineLinks::eval<TailT, KAPPA_ON, Law>(c, lc, rsq, linked, now, w, changes, et,
                                                       ft, e, fpair);
          word = state_word(word, linked, 1);
        }
        if (!on) return;
      }
      if (rsq <= coeffs[tp].hardsq) singular(i, j, rsq / scale);
      const double factor_lj = special_lj[jraw >> SBBITS & 3];
      fpair *= factor_lj * scale;
      fxtmp += delx * fpair;
      fytmp += dely * fpair;
      fztmp += delz * fpair;
      if (NEWTON_PAIR || j < nlocal) {
        f[j].x -= delx * fpair;
        f[j].y -= dely * fpair;
        f[j].z -= delz * fpair;
      }
      if (EVFLAG) tally(i, j, nlocal, NEWTON_PAIR, EFLAG ? factor_lj * e : 0.0, fpair, delx, dely, delz);
    };

    // BLOCK: the pairs go through the block (the law in its SIMD loop), else each is applied
    // as it is read (a polynomial law costs less than storing and reloading it)
    int ii = iifrom, jjnext = 0;
    while (ii < iito) {
      // fill: list entries from (ii, jjnext) on, with their separations; without link state
      // only the pairs inside the interaction end (chain N: only chain neighbours)
      b.n = 0;
      while (ii < iito && b.n < SplineBlock::SIZE) {
        const int i = ilist[ii];
        const double xtmp = x[i].x, ytmp = x[i].y, ztmp = x[i].z;
        const xyz3 vi = DAMP ? v[i] : xyz3{0.0, 0.0, 0.0};
        const int tpi = type[i] * ntp1;
        const int *_noalias const jlist = firstneigh[i];
        const int jnum = numneigh[i];
        int jj = jjnext;
        for (; jj < jnum && b.n < SplineBlock::SIZE; jj++) {
          const int jraw = jlist[jj];
          const int j = jraw & NEIGHMASK;
          const double delx = xtmp - x[j].x;
          const double dely = ytmp - x[j].y;
          const double delz = ztmp - x[j].z;
          double rsq = delx * delx + dely * dely + delz * delz;
          double scale = 1.0;    // chain: the n-th neighbour along the chain feels Pi(r/n)
          if (CHAIN) {
            const tagint nc = chain_distance(tag[i], tag[j]);
            if (nc == 0 || nc > k.chain_n) continue;
            scale = k.chain_scale[nc];
            rsq *= scale;
          }
          const int tp = uniform ? ntp1 + 1 : tpi + type[j];
          if (!LINKED && rsq >= coeffs[tp].cutsq) continue;
          if constexpr (!BLOCK) {
            const SplineCoeff &c = coeffs[tp];
            double ft;
            const double et = TailT::template eval<KAPPA_ON, Law>(c, rsq, ft) - c.offset;
            xyz3 df{0.0, 0.0, 0.0};
            if (DAMP)
              k.damping->force(k.damping->coeff[tp], c.cutsq, rsq, vi.x - v[j].x, vi.y - v[j].y,
                               vi.z - v[j].z, delx, dely, delz, df);
            apply(i, jraw, jj, tp, delx, dely, delz, rsq, scale, et, ft, df);
            continue;
          }
          const int m = b.n++;
          b.i[m] = i;
          b.jraw[m] = jraw;
          if (LINKED) b.jj[m] = jj;
          b.tp[m] = tp;
          b.delx[m] = delx;
          b.dely[m] = dely;
          b.delz[m] = delz;
          b.rsq[m] = rsq;
          if (CHAIN) b.scale[m] = scale;
          if (DAMP) {
            b.dvx[m] = vi.x - v[j].x;
            b.dvy[m] = vi.y - v[j].y;
            b.dvz[m] = vi.z - v[j].z;
          }
        }
        if (jj == jnum) {
          ii++;
          jjnext = 0;
        } else
          jjnext = jj;
      }
      if (b.n == 0) break;
      if (uniform) b.compute<Law, TailT, KAPPA_ON, true>(coeffs, ntp1);
      else b.compute<Law, TailT, KAPPA_ON, false>(coeffs, ntp1);
      if constexpr (DAMP > 0) {
        if (uniform) b.damp<true>(*k.damping, coeffs, ntp1);
        else b.damp<false>(*k.damping, coeffs, ntp1);
      }
      for (int p = 0; p < b.n; p++)
        apply(b.i[p], b.jraw[p], LINKED ? b.jj[p] : 0, b.tp[p], b.delx[p], b.dely[p], b.delz[p],
              b.rsq[p], CHAIN ? b.scale[p] : 1.0, b.e[p], b.fpair[p],
              DAMP ? xyz3{b.dfx[p], b.dfy[p], b.dfz[p]} : xyz3{0.0, 0.0, 0.0});
    }
    flush();
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
