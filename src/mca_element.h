/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the geometry of one element of
   movable cellular automata (stateless, as spline_laws.h), the one
   definition that pair_style mca, its checks and compute mca/atom use.
   An element of radius R in a packing of fraction F stands for the volume
       Omega = (4 pi / 3) R^3 / F
   (the seam for a two-dimensional element: its area).  Its stress is
   Love's formula, sigma = (1/Omega) sum_j q_ij sym(n_ij (x) F_ij), summed
   here in the columns xx yy zz xy xz yz.  Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_ELEMENT_H
#define LMP_CLUSTERDYN_MCA_ELEMENT_H

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaElement {
    static double volume(double radius, double fraction)
    {
      return 4.0 * M_PI / 3.0 * radius * radius * radius / fraction;
    }

    // the symmetric product sym(n (x) f): xx yy zz xy xz yz
    static void dyad(const double *n, const double *f, double *sym)
    {
      sym[0] = n[0] * f[0];
      sym[1] = n[1] * f[1];
      sym[2] = n[2] * f[2];
      sym[3] = 0.5 * (n[0] * f[1] + n[1] * f[0]);
      sym[4] = 0.5 * (n[0] * f[2] + n[2] * f[0]);
      sym[5] = 0.5 * (n[1] * f[2] + n[2] * f[1]);
    }

    // one pair's share of Love's sum: q sym(n (x) f) added to a row of six columns
    static void add_love(double *row, double q, const double *sym)
    {
      for (int k = 0; k < 6; k++) row[k] += q * sym[k];
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
