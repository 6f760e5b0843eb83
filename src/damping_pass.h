/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative's damping
   forces computed in the spline pair style's force pass.

   The pair's kernel has the pairs, their separations and the partners'
   positions in hand; adding the damping there saves the fix a second walk
   over the neighbour list.  The handshake, each run:
     - pair init_style: the pair style clears its slot (extract
       "damping_pass": the slot's address, only where its kernel can fuse);
     - fix init: the first fix viscous/relative whose pairs are exactly the
       pair style's (no cutoff keyword, group all, per-type masses, no link
       L, no chain N, not a hybrid) puts its pass in the slot;
     - fix pre_force: fd zeroed and offered, unless the fix tallies its
       virial on this step;
     - pair compute: on steps without energy or virial, the kernel adds the
       damping forces into fd in list order, as the fix's own loop does (the
       /omp styles: per thread, damping_threads.h), and marks the pass filled;
     - fix post_force: its own loop only if the pass was not filled, then
       the ghost parts to their owners and fd into f as before.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_DAMPING_PASS_H
#define LMP_CLUSTERDYN_DAMPING_PASS_H

#include "xyz3.h"

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  // one pair (i,j), dv = v_i - v_j, del = x_i - x_j, coef = m_ij G_ij / ftm2v: the damping
  // force on i (on j: minus it).  Coincident atoms (rsq < 1e-20 cutsq) have no normal: mode
  // normal gives them none, by factors instead of a branch (the kernel's vector loop calls it).
  template <bool NORMAL, bool DPD>
  inline void damping_force(double coef, double inv_cut, double rsq, double cutsq, double dvx,
                            double dvy, double dvz, double delx, double dely, double delz,
                            double &fx, double &fy, double &fz)
  {
    if (DPD) {
      const double w = 1.0 - std::sqrt(rsq) * inv_cut;
      coef *= w * w;
    }
    if (NORMAL) {
      const double apart = rsq >= 1e-20 * cutsq ? 1.0 : 0.0;
      const double proj = apart * (dvx * delx + dvy * dely + dvz * delz) / (rsq + (1.0 - apart));
      dvx = proj * delx;
      dvy = proj * dely;
      dvz = proj * delz;
    }
    fx = -coef * dvx;
    fy = -coef * dvy;
    fz = -coef * dvz;
  }

  struct DampingCoeff {
    double coef;       // m_ij G_ij / ftm2v (per-type masses)
    double inv_cut;    // 1 / damping range (weight dpd)
  };

  struct DampingPass {
    int normal = 0;                          // mode normal: (dv . e) e
    int dpd = 0;                             // weight dpd: (1 - r/rc)^2
    const DampingCoeff *coeff = nullptr;     // per type pair, (ntypes+1)^2
    xyz3 *fd = nullptr;                      // offered this step: zeroed, own and ghost atoms
    int filled = 0;                          // the pair style added the damping into fd

    // damping_force() with this pass's mode and weight, one pair at a time
    void force(const DampingCoeff &c, double cutsq, double rsq, double dvx, double dvy,
               double dvz, double delx, double dely, double delz, xyz3 &df) const
    {
      if (normal) {
        if (dpd) damping_force<true, true>(c.coef, c.inv_cut, rsq, cutsq, dvx, dvy, dvz, delx, dely, delz, df.x, df.y, df.z);
        else damping_force<true, false>(c.coef, c.inv_cut, rsq, cutsq, dvx, dvy, dvz, delx, dely, delz, df.x, df.y, df.z);
      } else {
        if (dpd) damping_force<false, true>(c.coef, c.inv_cut, rsq, cutsq, dvx, dvy, dvz, delx, dely, delz, df.x, df.y, df.z);
        else damping_force<false, false>(c.coef, c.inv_cut, rsq, cutsq, dvx, dvy, dvz, delx, dely, delz, df.x, df.y, df.z);
      }
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
