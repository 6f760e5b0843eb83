/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the walk of pair_style mca's passes
   over its neighbour list, and the geometry of one pair at this step: the
   separation d = x_j - x_i, its length r and direction n, the arms
   q_ij = r R_i/(R_i + R_j) and q_ji = r - q_ij from the centres to the
   contact point, and the turn of the pair's frame by the spin of the
   contact, w dt = dt (q_ij omega_i + q_ji omega_j) / r (mca_contact.h).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_PAIR_WALK_H
#define LMP_CLUSTERDYN_MCA_PAIR_WALK_H

#include "mca_contact.h"
#include "pair_state.h"

#include "atom.h"
#include "error.h"
#include "lammps.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <cmath>
#include <cstdlib>

namespace LAMMPS_NS {
namespace ClusterDyn {

  // visit(i, j, jj) for every pair of the list that keeps a state (PairState: the first
  // pass.counts[i] of i's list; the rest are too far apart to link or touch before the next
  // list build), jj the pair's place in i's list (its state)
  template <class Visit> void walk_pairs(const NeighList *list, const StatePass &pass, Visit &&visit)
  {
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      const int *jlist = list->firstneigh[i];
      for (int jj = 0; jj < pass.counts[i]; jj++) visit(i, jlist[jj] & NEIGHMASK, jj);
    }
  }

  // two elements at the same place have no direction between them
  [[noreturn]] inline void coincident_elements(LAMMPS *lmp, int i, int j)
  {
    lmp->error->one(FLERR, "Pair mca: elements {} and {} are at the same place (coincident "
                    "elements): remove one", lmp->atom->tag[i], lmp->atom->tag[j]);
    std::abort();    // not reached: error->one() throws
  }

  struct McaPairFrame {
    double d[3] = {0.0, 0.0, 0.0}, rsq = 0.0, r = 0.0, n[3] = {0.0, 0.0, 0.0}, qi = 0.0, qj = 0.0;
    double inverse = 0.0;    // 1 / r (orient()): one division for the direction and the turn

    McaPairFrame() = default;
    McaPairFrame(double *const *x, int i, int j) :
        d{x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]}, rsq(McaContact::dot(d, d))
    {
    }

    // length, direction and arms (r > 0)
    void orient(double ri, double rj)
    {
      r = sqrt(rsq);
      inverse = 1.0 / r;
      for (int k = 0; k < 3; k++) n[k] = d[k] * inverse;
      qi = r * ri / (ri + rj);
      qj = r - qi;
    }

    McaContact::Turn turn(const double *omega_i, const double *omega_j, double dt) const
    {
      double spin[3];
      rotation(omega_i, omega_j, dt, spin);
      return McaContact::Turn(spin);
    }
    // the turn's rotation vector w dt (with the reciprocal orient() took: every pass that
    // inlines this takes the same roundings, whatever -freciprocal-math makes of a division)
    void rotation(const double *omega_i, const double *omega_j, double dt, double *spin) const
    {
      for (int k = 0; k < 3; k++) spin[k] = dt * (qi * omega_i[k] + qj * omega_j[k]) * inverse;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
