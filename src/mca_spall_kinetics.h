/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the spall kinetics of an element of
   pair_style mca with a shock equation of state (stateless, as
   spline_laws.h): a cumulative damage after Tuler and Butcher (1968),
     dD/dt = A (sigma~ / S)^lambda   (sigma~ > 0),   D <= 1,
   sigma~ = -p the effective (undamaged) mean stress in tension; the
   element transmits (1 - D) of its tension, and at D = 1 its links break.
   From the handbook's rate law sigma_sp = S (rate / rate_ref)^m:
     lambda = 1/m - 1,  A = (lambda + 1) c^(lambda + 1) (K / S) rate_ref,
     c = (lambda + 1) / (lambda + 2)^((lambda + 2) / (lambda + 1)),
   so that under a mean stress rising as K rate t (uniaxial strain at the
   strain rate rate, K the bulk modulus) the transmitted tension (1 - D)
   sigma~ peaks at exactly S (rate / rate_ref)^m.  Formulas: doc/pair_mca.rst
   "Spall kinetics".
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_SPALL_KINETICS_H
#define LMP_CLUSTERDYN_MCA_SPALL_KINETICS_H

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaSpallKinetics {
    double strength = 0.0;    // S, the spall strength at the reference rate (0: no kinetics)
    double lambda = 0.0;      // the exponent of the stress
    double rate = 0.0;        // A, the damage rate at sigma~ = S (1/time)

    // from the spall strength S at the strain rate rate_ref, the rate exponent m (0 < m < 1)
    // and the bulk modulus K (S and K in one unit)
    static McaSpallKinetics of_rate_law(double s, double rate_ref, double m, double bulk)
    {
      const double lam = 1.0 / m - 1.0;
      return {s, lam, (lam + 1.0) * pow(peak_share(lam), lam + 1.0) * (bulk / s) * rate_ref};
    }

    // c: the peak of (1 - D) sigma~ under a linear ramp of sigma~, as a share of sigma~ at
    // D = 1 on the same ramp
    static double peak_share(double lam)
    {
      return (lam + 1.0) / pow(lam + 2.0, (lam + 2.0) / (lam + 1.0));
    }

    bool active() const { return strength > 0.0; }

    // the damage rate at the effective tension sigma~ (none in compression)
    double growth(double tension) const
    {
      return tension > 0.0 ? rate * pow(tension / strength, lambda) : 0.0;
    }

    // D after a step of dt from the effective tension before to after (the trapezoid rule:
    // second order in dt)
    double advance(double damage, double before, double after, double dt) const
    {
      if (damage >= 1.0) return damage;
      const double grown = damage + 0.5 * dt * (growth(before) + growth(after));
      return grown < 1.0 ? grown : 1.0;
    }

    // the mean pressure the element transmits: all of it in compression, (1 - D) in tension
    static double transmitted(double pressure, double damage)
    {
      return pressure < 0.0 ? (1.0 - damage) * pressure : pressure;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
