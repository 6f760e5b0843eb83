/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the material of a movable cellular
   automaton (element) type and its reading from pair_coeff.  Isotropic
   linear elasticity: bulk modulus K and shear modulus G, given as
   "bulk K shear G" or "young E poisson nu"; the response beyond it (the
   review's Fig. 3): strength sigma_c at which a linked pair unlinks (a),
   damage from sigma_d up to sigma_c (b), von Mises yield sigma_y with
   linear hardening H (c; with strength: d); and the surface of its
   unlinked contacts: dry friction mu, viscous friction eta, welding
   pressure; or, for shocks, a Mie-Grueneisen equation of state on the
   Hugoniot us = c0 + s up in place of the bulk modulus ("shock rho0 c0 s
   Gamma0", K = rho0 c0^2; mca_shock_eos.h) with its bulk viscosity and, in
   place of the links' strength, the spall kinetics of its elements ("spall
   S rate m": the spall strength S at the strain rate rate and the exponent
   m of the rate law; mca_spall_kinetics.h).
   Stresses in pressure units, eta in pressure / velocity, rho0 in the
   mass/volume units that "set density" takes.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_MATERIAL_H
#define LMP_CLUSTERDYN_MCA_MATERIAL_H

#include "arg_values.h"
#include "keyword_set.h"

#include "comm.h"
#include "force.h"
#include "utils.h"

#include <cstdio>
#include <mpi.h>
#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaMaterial {
    double bulk = 0.0;       // K
    double shear = 0.0;      // G
    double lambda = 0.0;     // Lame's first parameter K - 2G/3: the many-body (volumetric) term
    double strength = 0.0;   // sigma_c; 0: the links never break
    double damage = 0.0;     // sigma_d < sigma_c: damage between them; 0: none (type a)
    double yield = 0.0;      // sigma_y of the element (von Mises); 0: elastic
    double hardening = 0.0;  // H: sigma_y + H eps_p
    double friction = 0.0;   // mu of its unlinked contacts (dry, Coulomb)
    double viscous = 0.0;    // eta: tangential stress eta v_t of its unlinked contacts
    double weld = 0.0;       // an unlinked contact pressed at this stress links; 0: never
    double rho0 = 0.0;       // shock: the reference density; 0: the linear law (bulk K)
    double c0 = 0.0;         // shock: the bulk sound speed, K = rho0 c0^2
    double slope = 0.0;      // shock: s of us = c0 + s up
    double gruneisen = 0.0;  // shock: Gamma0
    double b1 = 0.06;        // shock: linear bulk viscosity coefficient
    double b2 = 1.2;         // shock: quadratic bulk viscosity coefficient
    double hourglass = 1.0;  // shock: the hourglass spring, in units of 2 (K + 4G/3 + 2|p|) / R
    double spall = 0.0;      // shock: the spall strength S at the strain rate spall_rate; 0: none
    double spall_rate = 0.0; // shock: its reference strain rate (1/time)
    double spall_m = 0.0;    // shock: the exponent of sigma_sp = S (rate / spall_rate)^m

    enum { NRESTART = 19 };

    bool kinetic() const { return spall > 0.0; }

    bool shock() const { return c0 > 0.0; }

    double young() const { return 9.0 * bulk * shear / (3.0 * bulk + shear); }
    double poisson() const { return (3.0 * bulk - 2.0 * shear) / (2.0 * (3.0 * bulk + shear)); }

    // the words of pair_coeff that give this material back (data files)
    std::string words() const
    {
      std::string w = shock()
          ? fmt::format("shock {:.17g} {:.17g} {:.17g} {:.17g} bulk_viscosity {:.17g} {:.17g} "
                        "hourglass {:.17g} shear {:.17g}", rho0, c0, slope, gruneisen, b1, b2,
                        hourglass, shear)
          : fmt::format("bulk {:.17g} shear {:.17g}", bulk, shear);
      const std::pair<const char *, double> more[] = {
          {"strength", strength}, {"damage", damage},     {"yield", yield},
          {"hardening", hardening}, {"friction", friction}, {"viscous", viscous},
          {"weld", weld}};
      for (const auto &kv : more)
        if (kv.second > 0.0) w += fmt::format(" {} {:.17g}", kv.first, kv.second);
      if (kinetic()) w += fmt::format(" spall {:.17g} {:.17g} {:.17g}", spall, spall_rate, spall_m);
      return w;
    }

    void write_restart(FILE *fp) const
    {
      const double v[NRESTART] = {bulk,     shear, strength, damage, yield,     hardening,
                                  friction, viscous, weld,   rho0,   c0,        slope,
                                  gruneisen, b1,     b2,     hourglass, spall,     spall_rate,
                                  spall_m};
      fwrite(v, sizeof(double), NRESTART, fp);
    }

    void read_restart(FILE *fp, LAMMPS *lmp)    // processor 0 reads, all take it
    {
      double v[NRESTART];
      if (lmp->comm->me == 0)
        utils::sfread(FLERR, v, sizeof(double), NRESTART, fp, nullptr, lmp->error);
      MPI_Bcast(v, NRESTART, MPI_DOUBLE, 0, lmp->world);
      bulk = v[0];
      shear = v[1];
      strength = v[2];
      damage = v[3];
      yield = v[4];
      hardening = v[5];
      friction = v[6];
      viscous = v[7];
      weld = v[8];
      rho0 = v[9];
      c0 = v[10];
      slope = v[11];
      gruneisen = v[12];
      b1 = v[13];
      b2 = v[14];
      hourglass = v[15];
      spall = v[16];
      spall_rate = v[17];
      spall_m = v[18];
      lambda = volumetric_lambda();
    }

    // the many-body term's modulus: K - 2G/3 (Lame's lambda); with a shock equation of state
    // the pressure acts apart (mca_element_eos.h) and the term only takes the volumetric part
    // of the pairs' 2G eps out, -2G/3
    double volumetric_lambda() const { return (shock() ? 0.0 : bulk) - 2.0 * shear / 3.0; }

    // in plane stress (sigma_zz = 0) the in-plane volumetric modulus is 2 G lambda / (lambda + 2G)
    McaMaterial in_plane_stress() const
    {
      McaMaterial m = *this;
      m.lambda = 2.0 * shear * lambda / (lambda + 2.0 * shear);
      return m;
    }
    // the stresses in energy/volume: pressure / nktv2p (eta likewise)
    McaMaterial scaled(double p2e) const
    {
      McaMaterial m = *this;
      for (double *v : {&m.bulk, &m.shear, &m.lambda, &m.strength, &m.damage, &m.yield,
                        &m.hardening, &m.viscous, &m.weld, &m.spall})
        *v *= p2e;
      return m;
    }

    // pair_coeff I I bulk K shear G | young E poisson nu | shock rho0 c0 s Gamma0 shear G
    //   [bulk_viscosity b1 b2] [strength S [damage Sd] | spall S rate m] [yield Y [hardening H]]
    //   [friction mu] [viscous eta] [weld P]   (words after I I)
    static McaMaterial read(const std::string &who, int narg, char **arg, LAMMPS *lmp)
    {
      KeywordSet seen(lmp, who, Keywords::MCA_MATERIAL);
      double k = -1.0, g = -1.0, e = -1.0, nu = 2.0;
      bool viscosity_given = false, hourglass_given = false;
      McaMaterial m;
      for (int i = 0; i < narg;) {
        const std::string key = arg[i];
        const int count = seen.add(key).values;
        if (i + count >= narg)
          lmp->error->all(FLERR, "{}: {} needs {}", who, key,
                          count > 1 ? fmt::format("{} values", count) : std::string("a value"));
        const char *val = arg[i + 1 < narg ? i + 1 : i];
        if (key == "bulk") k = positive_arg(who, "bulk modulus K", val, lmp);
        else if (key == "shear") g = positive_arg(who, "shear modulus G", val, lmp);
        else if (key == "young") e = positive_arg(who, "Young's modulus E", val, lmp);
        else if (key == "strength") m.strength = positive_arg(who, "strength", val, lmp);
        else if (key == "damage") m.damage = positive_arg(who, "damage (threshold)", val, lmp);
        else if (key == "yield") m.yield = positive_arg(who, "yield (stress)", val, lmp);
        else if (key == "hardening") m.hardening = nonnegative(who, "hardening", val, lmp);
        else if (key == "friction") m.friction = nonnegative(who, "friction (mu)", val, lmp);
        else if (key == "viscous") m.viscous = nonnegative(who, "viscous (eta)", val, lmp);
        else if (key == "weld") m.weld = positive_arg(who, "weld (pressure)", val, lmp);
        else if (key == "shock") {
          m.rho0 = positive_arg(who, "shock rho0 (density)", arg[i + 1], lmp);
          m.c0 = positive_arg(who, "shock c0 (bulk sound speed)", arg[i + 2], lmp);
          m.slope = nonnegative(who, "shock s (slope of us = c0 + s up)", arg[i + 3], lmp);
          m.gruneisen = nonnegative(who, "shock Gamma0 (Grueneisen parameter)", arg[i + 4], lmp);
          if (m.slope > 10.0)
            lmp->error->all(FLERR, "{}: shock s of {} is not the slope of a metal's Hugoniot "
                            "us = c0 + s up (0 to 10)", who, arg[i + 3]);
          if (m.gruneisen > 10.0)
            lmp->error->all(FLERR, "{}: shock Gamma0 of {} is not a Grueneisen parameter (0 to "
                            "10)", who, arg[i + 4]);
        } else if (key == "spall") {
          m.spall = positive_arg(who, "spall S (spall strength)", arg[i + 1], lmp);
          m.spall_rate = positive_arg(who, "spall rate (reference strain rate)", arg[i + 2], lmp);
          m.spall_m = number_arg(who, "spall m (rate exponent)", arg[i + 3], lmp);
          if (!(m.spall_m >= 0.01 && m.spall_m < 1.0))
            lmp->error->all(FLERR, "{}: spall m of {} must lie in [0.01, 1): the exponent of "
                            "sigma_sp = S (rate / rate_ref)^m, 0.1-0.3 for metals", who,
                            arg[i + 3]);
          if (!(m.spall_rate >= 1.0e-100 && m.spall_rate <= 1.0e100))
            lmp->error->all(FLERR, "{}: spall rate of {} is outside 1e-100 to 1e100 (1/time "
                            "units of the unit style)", who, arg[i + 2]);
        } else if (key == "bulk_viscosity") {
          m.b1 = bounded(who, "bulk_viscosity b1 (linear)", arg[i + 1], 2.0, lmp);
          m.b2 = bounded(who, "bulk_viscosity b2 (quadratic)", arg[i + 2], 4.0, lmp);
          viscosity_given = true;
        } else if (key == "hourglass") {
          m.hourglass = bounded(who, "hourglass (coefficient)", val, 5.0, lmp);
          hourglass_given = true;
        } else if (key == "poisson") {
          nu = number_arg(who, "Poisson's ratio nu", val, lmp);
          if (!(nu > -1.0 && nu < 0.5))
            lmp->error->all(FLERR, "{}: Poisson's ratio nu must lie in (-1, 0.5) (got {})", who,
                            val);
        }
        i += 1 + count;
      }
      if (m.shock()) {
        if (k > 0.0 || e > 0.0 || nu < 2.0)
          lmp->error->all(FLERR, "{}: shock gives the bulk modulus K = rho0 c0^2: give shear G "
                          "with it, not bulk, young or poisson", who);
        if (g < 0.0) lmp->error->all(FLERR, "{}: shock needs shear G", who);
        if (m.hourglass == 0.0)
          lmp->error->all(FLERR, "{}: hourglass must be > 0 with shock (got 0): without the "
                          "hourglass spring alternate planes of elements run through each other "
                          "(the pressure forces do not resist that mode); give H in (0, 5], "
                          "default 1", who);
        k = m.rho0 * m.c0 * m.c0 * lmp->force->mvv2e * lmp->force->nktv2p;
      } else if (viscosity_given || hourglass_given)
        lmp->error->all(FLERR, "{}: {} needs shock (the equation of state it stabilises)", who,
                        viscosity_given ? "bulk_viscosity" : "hourglass");
      else if (m.kinetic())
        lmp->error->all(FLERR, "{}: spall needs shock (the kinetics reads the mean stress of "
                        "the shock equation of state): give strength S to the linear law", who);
      if (m.kinetic() && m.strength > 0.0)
        lmp->error->all(FLERR, "{}: give strength S (the links break at a stress) or spall S "
                        "rate m (the elements' spall kinetics), not both", who);
      if (m.kinetic() && m.damage > 0.0)
        lmp->error->all(FLERR, "{}: damage Sd is the links' damage below their strength: it does "
                        "not go with spall (the elements' own damage)", who);
      if (m.kinetic() && m.weld > 0.0)
        lmp->error->all(FLERR, "{}: weld does not go with spall: a spalled element carries no "
                        "tension, so a weld to it would break at once, every step", who);
      const bool kg = k > 0.0 || g > 0.0, enu = e > 0.0 || nu < 2.0;
      if (kg == enu || (kg && (k < 0.0 || g < 0.0)) || (enu && (e < 0.0 || nu > 1.0)))
        lmp->error->all(FLERR, "{}: give bulk K shear G, or young E poisson nu", who);
      for (const double v : {k, g, e, m.strength, m.damage, m.yield, m.hardening, m.viscous,
                             m.weld, m.spall})
        if (v > 0.0 && !(v >= 1.0e-100 && v <= 1.0e100))
          lmp->error->all(FLERR, "{}: a value of {} is outside the range 1e-100 to 1e100 that "
                          "the force kernel takes (pressure units of the unit style)", who, v);
      if (m.damage > 0.0 && !(m.damage < m.strength))
        lmp->error->all(FLERR, "{}: damage (the stress where damage starts, {}) needs strength "
                        "S above it (got strength {})", who, m.damage, m.strength);
      if (m.hardening > 0.0 && m.yield == 0.0)
        lmp->error->all(FLERR, "{}: hardening needs yield (the initial yield stress)", who);
      if (m.friction > 1.0e6)
        lmp->error->all(FLERR, "{}: friction (mu) of {} is not a friction coefficient", who,
                        m.friction);
      m.bulk = kg ? k : e / (3.0 * (1.0 - 2.0 * nu));
      m.shear = kg ? g : e / (2.0 * (1.0 + nu));
      m.lambda = m.volumetric_lambda();
      return m;
    }

   private:
    // a coefficient of a numerical term: 0 to most (beyond it the explicit step is unstable)
    static double bounded(const std::string &who, const char *name, const char *val, double most,
                          LAMMPS *lmp)
    {
      const double v = nonnegative(who, name, val, lmp);
      if (v > most)
        lmp->error->all(FLERR, "{}: {} must lie in 0 to {:g} (got {}): the explicit time step "
                        "does not follow a larger one", who, name, most, val);
      return v;
    }
    static double nonnegative(const std::string &who, const char *name, const char *val,
                              LAMMPS *lmp)
    {
      const double v = number_arg(who, name, val, lmp);
      if (v < 0.0) lmp->error->all(FLERR, "{}: {} must be >= 0 (got {})", who, name, val);
      return v;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
