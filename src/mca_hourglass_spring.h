/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the hourglass spring of a linked
   pair of two shock-law elements (stateless, as spline_laws.h; its state
   is the pair's doubles HG, EHG, FHG and the step's DR, mca_contact.h):
     pull F = S b e_hg, b the series of b_i and b_j, b = 2 H (K + 4G/3 +
       2 |p|) / R (p the elements' mean pressure)
     energy: the work the pull has done on the pair, by the trapezoid rule
       over each step, W += (F_before + F_now) dr / 2, since e_hg grows with
       the pair's motion less its elements' affine part and b stiffens with
       p, so that S b e_hg^2 / 2 is not conserved by the spring's own force
   Formulas: doc/pair_mca.rst "The hourglass spring".
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_HOURGLASS_SPRING_H
#define LMP_CLUSTERDYN_MCA_HOURGLASS_SPRING_H

#include "mca_contact.h"
#include "mca_pair_halves.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaHourglassSpring {
    using C = McaContact;

    // the pull of pair v (> 0 draws its elements together) with the halves' stiffnesses bi,
    // bj; moving: a step of dynamics, whose motion DR the pull has worked through (FHG: the
    // pull at the step's start); returns the pull and sets the spring's energy
    static double pull(double *v, double bi, double bj, bool moving, double &energy)
    {
      const double f =
          bi + bj > 0.0 ? v[C::AREA] * McaPairHalves(bi, bj).series() * v[C::HG] : 0.0;
      if (moving) v[C::EHG] += 0.5 * (v[C::FHG] + f) * v[C::DR];
      v[C::FHG] = f;
      energy = v[C::EHG];
      return f;
    }

    // no spring on this pair (an element of the linear law, or without a volume)
    static void clear(double *v) { v[C::HG] = v[C::EHG] = v[C::FHG] = 0.0; }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
