/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the load of a linked pair of
   pair_style mca from its elements' pressure (mca_element_eos.h): their
   force on i, f_i = -(P_i + P_j) d S / r_ref, and their mean stress, which
   the pair's response reads as normal stress; whether an element has
   spall kinetics and is fully damaged; and, where both elements have the
   shock law (spring), the hourglass spring (mca_hourglass_spring.h) on the
   elongation beyond the elements' displacement gradients (a dynamics step
   adds the pair's own motion in the pass of the volumes and takes the
   affine part off here), with the halves' stiffnesses b_i of
   mca_element_stiffness.h under the pair's |p|.  Composes the element
   components; holds no state.  Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_PRESSURE_PAIR_H
#define LMP_CLUSTERDYN_MCA_PRESSURE_PAIR_H

#include "mca_element_eos.h"
#include "mca_element_stiffness.h"
#include "mca_hourglass_spring.h"
#include "mca_pair_tally.h"
#include "mca_pair_walk.h"

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaPressurePair {
    using C = McaContact;

    const McaElementEos &eos;
    const McaElementStiffness &stiffness;
    const int *type;
    bool turning;    // a step of dynamics: the spring takes its elements' affine elongation off

    // the load on pair v (spring: both elements have the shock law); returns the spring's
    // effective energy
    double load(int i, int j, double *v, const McaPairFrame &p, bool spring,
                McaPressureLoad &out) const
    {
      double *force = out.f;
      eos.pair_force(i, j, p.d, v[C::AREA] / v[C::REF], force);
      out.stress = eos.pair_stress(i, j);
      out.kinetic = eos.kinetic(type[i]) || eos.kinetic(type[j]);
      out.spalled = out.kinetic && eos.spalled(i, j);
      double affine;
      if (!spring || !eos.affine_elongation(i, j, p.n, p.r, affine)) {
        McaHourglassSpring::clear(v);    // a linear-law element, or neither has a volume
        return 0.0;
      }
      if (turning) v[C::HG] -= affine;
      const double squeeze = fabs(out.stress);
      double energy;
      const double pull = McaHourglassSpring::pull(v, stiffness.spring(i, squeeze),
                                                   stiffness.spring(j, squeeze), turning, energy);
      for (int k = 0; k < 3; k++) force[k] += pull * p.n[k];
      return energy;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
