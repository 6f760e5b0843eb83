/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the shock equation of state of a
   movable cellular automaton (stateless, as spline_laws.h).  Mie-Grueneisen
   on the linear Hugoniot us = c0 + s up as reference curve, with
   Gamma rho = Gamma0 rho0, in the element's volume ratio J = V/V0
   (eta = 1 - J) and its internal energy u per reference volume
   (u = rho0 e):
     p_H = K eta / (1 - s eta)^2 (eta > 0), K eta (tension),  K = rho0 c0^2
     u_H = p_H eta / 2,    p = p_H + Gamma0 (u - u_H)
   the energy over a step, u1 = u0 - w0 - (p1 + q1) s1 with w0 the work of
   the old pressure and viscosity and s1 the new one's share of the volume
   change (the trapezoid w0 = P0 dJ / 2, s1 = dJ / 2 is exact for the
   Rankine-Hugoniot jump), solved for u1 in closed form; the bulk
   (artificial) viscosity of an element, a linear term both ways and von
   Neumann-Richtmyer's quadratic one in compression (Wilkins 1980; the bulk
   viscosity of Abaqus/Explicit, whose defaults b1 = 0.06, b2 = 1.2 these
   are):
     q = rho L D (b1 c0 + b2^2 L max(D, 0)),   D = -(dJ/dt)/J,  rho = rho0 / J.
   All in energy/volume (the caller scales).  Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_SHOCK_EOS_H
#define LMP_CLUSTERDYN_MCA_SHOCK_EOS_H

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaShockEos {
    double bulk = 0.0;     // K = rho0 c0^2
    double slope = 0.0;    // s
    double gamma = 0.0;    // Gamma0
    double b1 = 0.0;       // linear viscosity coefficient
    double b2 = 0.0;       // quadratic viscosity coefficient

    // the volume ratio below which the reference Hugoniot has no pressure: 1 - 1/s
    double limit() const { return slope > 0.0 ? 1.0 - 1.0 / slope : 0.0; }

    double hugoniot_pressure(double eta) const
    {
      if (eta <= 0.0) return bulk * eta;
      const double c = 1.0 - slope * eta;
      return bulk * eta / (c * c);
    }
    double hugoniot_energy(double eta) const { return 0.5 * hugoniot_pressure(eta) * eta; }

    double pressure(double volume_ratio, double u) const
    {
      const double eta = 1.0 - volume_ratio;
      return hugoniot_pressure(eta) + gamma * (u - hugoniot_energy(eta));
    }

    // the internal energy at J1 from u0: w0 the work done by the old pressure, s1 the volume
    // change (per reference volume) the new pressure f p(J1, u1) + q1 works on (f: the share
    // a damaged element transmits, mca_spall_kinetics.h)
    double energy_after(double u0, double w0, double j1, double q1, double s1,
                        double f = 1.0) const
    {
      const double eta = 1.0 - j1;
      const double ph = hugoniot_pressure(eta), uh = hugoniot_energy(eta);
      return (u0 - w0 - s1 * (f * (ph - gamma * uh) + q1)) / (1.0 + f * gamma * s1);
    }

    // the viscosity at the compression rate D = -(dJ/dt)/J (the linear term only in
    // expansion, where it is negative); rho the density, c0 the bulk sound speed, length the
    // element's size; mass x velocity^2 / volume
    double viscosity(double rate, double rho, double c0, double length) const
    {
      return rho * length * rate * (b1 * c0 + (rate > 0.0 ? b2 * b2 * length * rate : 0.0));
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
