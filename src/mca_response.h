/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the response of a linked pair of
   movable cellular automata beyond elasticity (stateless, as
   spline_laws.h): the review's Fig. 3 read at the pair.

   A linked pair carries its effective (undamaged) stresses sigma~ (normal)
   and tau~ (tangential); it transmits (1 - D) of them.  Its equivalent
   stress in tension is s~ = sqrt(sigma~^2 + 3 tau~^2) (sigma~ > 0; a pair
   in compression neither damages nor breaks), kappa the largest s~ it has
   had.  Type (a): D = 0 and the pair unlinks at s~ = sigma_c.  Type (b):
   from sigma_d the transmitted stress follows the parabola
       g(s~) = sigma_c - (sigma_c - sigma_d) (1 - (s~ - sigma_d) / (2 (sigma_c - sigma_d)))^2
   which leaves the elastic line with its slope at sigma_d and peaks at
   sigma_c when s~ = 2 sigma_c - sigma_d, where the pair unlinks; a pair
   unloads towards zero along the secant, 1 - D = g(kappa) / kappa.
   Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_RESPONSE_H
#define LMP_CLUSTERDYN_MCA_RESPONSE_H

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaResponse {
    double strength = 0.0;    // sigma_c (0: the pair never unlinks)
    double damage = 0.0;      // sigma_d (0: type a)

    // a pair of two materials takes the weaker element's strength and damage threshold: the
    // lower strength, at equal strengths the one that unlinks first (the lower peak); the same
    // whichever element is i
    static McaResponse of_pair(double sc_i, double sd_i, double sc_j, double sd_j)
    {
      const McaResponse i{sc_i, sd_i}, j{sc_j, sd_j};
      if (!i.active()) return j;
      if (!j.active()) return i;
      if (sc_i != sc_j) return sc_i < sc_j ? i : j;
      return i.peak() <= j.peak() ? i : j;
    }

    bool active() const { return strength > 0.0; }

    // the effective equivalent stress at which the pair unlinks
    double peak() const { return damage > 0.0 ? 2.0 * strength - damage : strength; }

    // 1 - D after the largest effective equivalent stress kappa
    double intact(double kappa) const
    {
      if (damage == 0.0 || kappa <= damage) return 1.0;
      const double u = 1.0 - (kappa - damage) / (2.0 * (strength - damage));
      return (strength - (strength - damage) * u * u) / kappa;
    }

    // the equivalent stress that damages and breaks (tension only)
    static double equivalent(double sigma, double tau2)
    {
      return sigma > 0.0 ? sqrt(sigma * sigma + 3.0 * tau2) : 0.0;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
