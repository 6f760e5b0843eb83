/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: friction of an unlinked contact of
   movable cellular automata (stateless, as spline_laws.h): the review's
   eq. 16, a viscous part plus dry (Coulomb) friction.  The dry part is an
   elastic tangential stress tau (stiffness a per unit slide, as a linked
   pair's) capped at mu |sigma_n|: where the cap holds the contact slips
   and the work cap x slip is dissipated.  The viscous part is eta v_t,
   v_t the tangential velocity of the partner's contact point relative to
   the element's own.  Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_FRICTION_H
#define LMP_CLUSTERDYN_MCA_FRICTION_H

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaFriction {
    double mu = 0.0;     // dry friction coefficient
    double eta = 0.0;    // viscous: stress per tangential velocity (energy/volume units)
    double weld = 0.0;   // a contact pressed at this stress links (0: never)

    // two surfaces: the geometric means; welding needs both to weld, at the higher pressure
    static McaFriction of_pair(double mu_i, double eta_i, double weld_i, double mu_j,
                               double eta_j, double weld_j)
    {
      return {sqrt(mu_i * mu_j), sqrt(eta_i * eta_j),
              weld_i > 0.0 && weld_j > 0.0 ? (weld_i > weld_j ? weld_i : weld_j) : 0.0};
    }

    // a contact keeps a tangential state (the dry part, or a weld that takes it over)
    bool keeps_state() const { return mu > 0.0 || weld > 0.0; }

    // the dry part: tau (trial, per area) capped at mu |sigma_n|; returns the work per area
    // dissipated by the slip (a: the tangential stiffness per unit slide)
    double cap(double *tau, double sigma_n, double a) const
    {
      const double limit = mu * fabs(sigma_n);
      const double t = sqrt(tau[0] * tau[0] + tau[1] * tau[1] + tau[2] * tau[2]);
      if (t <= limit) return 0.0;
      const double keep = limit / t;
      for (int k = 0; k < 3; k++) tau[k] *= keep;
      return limit * (t - limit) / a;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
