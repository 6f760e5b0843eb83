/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative's own loop over
   the pairs it damps, on the steps the pair style's force pass does not
   (damping_pass.h): the pairs of a half neighbour list within the damping
   range, or only the pair style's linked pairs; the forces summed into fd
   (damping_forces.h), the virial tallied through the fix.  Compiled per
   mode, weight, masses and links, so a scene pays only for what it uses.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_DAMPING_PAIRS_H
#define LMP_CLUSTERDYN_DAMPING_PAIRS_H

#include "damping_pass.h"
#include "damping_types.h"
#include "pair_state.h"
#include "viscous_settings.h"
#include "xyz3.h"

#include "atom.h"
#include "neigh_list.h"

#include <type_traits>

namespace LAMMPS_NS {
namespace ClusterDyn {

  // the pairs damped: those of list within the damping range, or (words) its linked pairs
  struct DampingBonds {
    const NeighList *list;
    int *const *words;    // link L: the pair states of list's pairs; else null
    const int *counts;    // with words: per atom, its first pairs that have a state word
  };

  struct DampingPairs {
    const Atom *atom;
    const DampingTypes &types;
    DampingBonds bonds;
    int groupbit;
    int newton_pair;
    int virial;    // tally(n, pair, vir) each pair's virial, shared by n of its atoms

    // the forces of every pair into fd
    template <class Tally> void run(const ViscousSettings &opt, xyz3 *fd, Tally &&tally) const
    {
      const int general = atom->rmass != nullptr || groupbit != 1;    // group all: no mask lookups
      auto with = [&](auto normal, auto dpd) {
        constexpr int N = decltype(normal)::value, D = decltype(dpd)::value;
        if (general) bonds.words ? damp<N, D, 1, 1>(fd, tally) : damp<N, D, 1, 0>(fd, tally);
        else bonds.words ? damp<N, D, 0, 1>(fd, tally) : damp<N, D, 0, 0>(fd, tally);
      };
      using I0 = std::integral_constant<int, 0>;
      using I1 = std::integral_constant<int, 1>;
      if (opt.normal) opt.dpd ? with(I1(), I1()) : with(I1(), I0());
      else opt.dpd ? with(I0(), I1()) : with(I0(), I0());
    }

    // GENERAL: per-atom masses or a group other than all (else: per-type masses, group all);
    // LINKED: only the pair style's linked pairs
    template <int NORMAL, int DPD, int GENERAL, int LINKED, class Tally>
    void damp(xyz3 *_noalias const fdamp, Tally &tally) const
    {
      const auto *_noalias const x = (xyz3 *) atom->x[0];
      const auto *_noalias const v = (xyz3 *) atom->v[0];
      const int *_noalias const type = atom->type;
      const int *_noalias const mask = atom->mask;
      const double *_noalias const rmass = atom->rmass;
      const int nlocal = atom->nlocal;
      const NeighList *const list = bonds.list;
      const int inum = list->inum;

      for (int ii = 0; ii < inum; ii++) {
        const int i = list->ilist[ii];
        if (GENERAL && !(mask[i] & groupbit)) continue;
        const DampingTypes::TypePair *tpi = types.row(type[i]);
        const DampingCoeff *ci = types.coeff_row(type[i]);
        const double xtmp = x[i].x, ytmp = x[i].y, ztmp = x[i].z;
        const double vxtmp = v[i].x, vytmp = v[i].y, vztmp = v[i].z;
        double fxtmp = 0.0, fytmp = 0.0, fztmp = 0.0;
        const int *jlist = list->firstneigh[i];
        const int jnum = LINKED ? bonds.counts[i] : list->numneigh[i];    // the rest: unlinked
        for (int jj = 0; jj < jnum; jj++) {
          const int j = jlist[jj] & NEIGHMASK;
          const double delx = xtmp - x[j].x;
          const double dely = ytmp - x[j].y;
          const double delz = ztmp - x[j].z;
          const double rsq = delx * delx + dely * dely + delz * delz;
          const DampingTypes::TypePair &tp = tpi[type[j]];
          if (rsq >= tp.cutsq || (GENERAL && !(mask[j] & groupbit))) continue;
          if (LINKED && !state_now(bonds.words[i][jj])) continue;

          const DampingCoeff &c = ci[type[j]];
          const double coef = GENERAL && rmass ? types.friction(tp, rmass[i], rmass[j]) : c.coef;
          double fx, fy, fz;
          damping_force<NORMAL, DPD>(coef, c.inv_cut, rsq, tp.cutsq, vxtmp - v[j].x,
                                     vytmp - v[j].y, vztmp - v[j].z, delx, dely, delz, fx, fy, fz);
          fxtmp += fx;
          fytmp += fy;
          fztmp += fz;
          if (newton_pair || j < nlocal) {
            fdamp[j].x -= fx;
            fdamp[j].y -= fy;
            fdamp[j].z -= fz;
          }
          if (virial) {
            int pair[2] = {i, j};
            double vir[6] = {delx * fx, dely * fy, delz * fz, delx * fy, delx * fz, dely * fz};
            tally((newton_pair || j < nlocal) ? 2 : 1, pair, vir);
          }
        }
        fdamp[i].x += fxtmp;
        fdamp[i].y += fytmp;
        fdamp[i].z += fztmp;
      }
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
