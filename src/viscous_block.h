/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: a packed block of damped pairs, the
   vector stage of fix viscous/relative (fix_viscous_relative.cpp), beside
   the spline kernel's SplineBlock (spline_block.h).

   The fix copies up to SIZE pairs with their separations, relative
   velocities and friction coefficients into the block (a scalar loop over
   its list: the partners' positions and velocities are read as the list
   orders them); one `#pragma omp simd` loop computes the damping force of
   every pair (the DPD weight, the projection on the bond); the fix then
   scatters in list order.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_VISCOUS_BLOCK_H
#define LMP_CLUSTERDYN_VISCOUS_BLOCK_H

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct ViscousBlock {
    static constexpr int SIZE = 128;

    // filled by the fix
    alignas(64) int i[SIZE], j[SIZE];
    alignas(64) double delx[SIZE], dely[SIZE], delz[SIZE];
    alignas(64) double dvx[SIZE], dvy[SIZE], dvz[SIZE];
    alignas(64) double rsq[SIZE];
    alignas(64) double coef[SIZE];       // m_ij G_ij / ftm2v
    alignas(64) double inv_cut[SIZE];    // weight dpd: 1 / damping range
    int n = 0;
    // written by compute(): the damping force on i (on j: minus it)
    alignas(64) double fx[SIZE], fy[SIZE], fz[SIZE];

    // NORMAL: only the relative velocity along the bond; DPD: weight (1 - r/rc)^2.  The
    // whole block is computed (entries past n padded with the first): no remainder loop.
    template <int NORMAL, int DPD> void compute()
    {
      for (int k = n; k < SIZE; k++) {
        delx[k] = delx[0], dely[k] = dely[0], delz[k] = delz[0];
        dvx[k] = dvx[0], dvy[k] = dvy[0], dvz[k] = dvz[0];
        rsq[k] = rsq[0], coef[k] = coef[0], inv_cut[k] = inv_cut[0];
      }
#pragma omp simd
      for (int k = 0; k < SIZE; k++) {
        double c = coef[k];
        if (DPD) {
          const double w = 1.0 - sqrt(rsq[k]) * inv_cut[k];
          c *= w * w;
        }
        double ux = dvx[k], uy = dvy[k], uz = dvz[k];
        if (NORMAL) {
          const double proj = (ux * delx[k] + uy * dely[k] + uz * delz[k]) / rsq[k];
          ux = proj * delx[k];
          uy = proj * dely[k];
          uz = proj * delz[k];
        }
        fx[k] = -c * ux;
        fy[k] = -c * uy;
        fz[k] = -c * uz;
      }
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
