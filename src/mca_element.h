/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the geometry of one element of
   movable cellular automata (stateless, as spline_laws.h), the one
   definition that pair_style mca, its checks and compute mca/atom use.
   An element of radius R in a packing of fraction F stands for the volume
       Omega = (4 pi / 3) R^3 / F          (dimension 3)
       Omega = pi R^2 / F  (times a unit thickness, as LAMMPS's 2d pressure)
   and a linked pair's contact area is its elements' mean of
       S_i = D Omega_i / (Z_i R_i)   (D the dimension, Z_i the links of i)
   so that Love's identity sum_j S_ij R_i n n = Omega_i I holds on a
   regular packing.  Its stress is Love's formula,
   sigma = (1/Omega) sum_j q_ij sym(n_ij (x) F_ij), summed here in the
   columns xx yy zz xy xz yz.  Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_ELEMENT_H
#define LMP_CLUSTERDYN_MCA_ELEMENT_H

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaElement {
    static double volume(double radius, double fraction, int dimension)
    {
      if (dimension == 2) return M_PI * radius * radius / fraction;
      return 4.0 * M_PI / 3.0 * radius * radius * radius / fraction;
    }

    // element i's share of a linked pair's contact area: D Omega_i / (Z_i R_i)
    static double area_share(double volume, double links, double radius, int dimension)
    {
      return dimension * volume / (links * radius);
    }

    // the contact area an unlinked pair pushes through: a close-packed element's face for the
    // harmonic mean radius R_h, sqrt(2) R_h^2 (fcc) or, in 2d, 2 R_h / sqrt(3) (the side of
    // the triangular packing's hexagonal cell, times the unit thickness)
    static double unlinked_area(double ri, double rj, int dimension)
    {
      const double rh = 2.0 * ri * rj / (ri + rj);
      return dimension == 2 ? 2.0 * rh / sqrt(3.0) : M_SQRT2 * rh * rh;
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
