/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the material of a movable cellular
   automaton (element) type and its reading from pair_coeff.  Isotropic
   linear elasticity: bulk modulus K and shear modulus G, given as
   "bulk K shear G" or "young E poisson nu"; the response beyond it (the
   review's Fig. 3): strength sigma_c at which a linked pair unlinks (a),
   damage from sigma_d up to sigma_c (b), von Mises yield sigma_y with
   linear hardening H (c; with strength: d); and the surface of its
   unlinked contacts: dry friction mu, viscous friction eta, welding
   pressure.  Stresses in pressure units, eta in pressure / velocity.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_MATERIAL_H
#define LMP_CLUSTERDYN_MCA_MATERIAL_H

#include "arg_values.h"
#include "keyword_set.h"

#include "comm.h"
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

    enum { NRESTART = 9 };

    double young() const { return 9.0 * bulk * shear / (3.0 * bulk + shear); }
    double poisson() const { return (3.0 * bulk - 2.0 * shear) / (2.0 * (3.0 * bulk + shear)); }

    // the words of pair_coeff that give this material back (data files)
    std::string words() const
    {
      std::string w = fmt::format("bulk {:.17g} shear {:.17g}", bulk, shear);
      const std::pair<const char *, double> more[] = {
          {"strength", strength}, {"damage", damage},     {"yield", yield},
          {"hardening", hardening}, {"friction", friction}, {"viscous", viscous},
          {"weld", weld}};
      for (const auto &kv : more)
        if (kv.second > 0.0) w += fmt::format(" {} {:.17g}", kv.first, kv.second);
      return w;
    }

    void write_restart(FILE *fp) const
    {
      const double v[NRESTART] = {bulk,      shear,    strength, damage, yield,
                                  hardening, friction, viscous,  weld};
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
      lambda = bulk - 2.0 * shear / 3.0;
    }

    // the stresses in energy/volume: pressure / nktv2p (eta likewise)
    McaMaterial scaled(double p2e) const
    {
      McaMaterial m = *this;
      for (double *v : {&m.bulk, &m.shear, &m.lambda, &m.strength, &m.damage, &m.yield,
                        &m.hardening, &m.viscous, &m.weld})
        *v *= p2e;
      return m;
    }

    // pair_coeff I I bulk K shear G | young E poisson nu [strength S [damage Sd]]
    //   [yield Y [hardening H]] [friction mu] [viscous eta] [weld P]   (words after I I)
    static McaMaterial read(const std::string &who, int narg, char **arg, LAMMPS *lmp)
    {
      KeywordSet seen(lmp, who);
      double k = -1.0, g = -1.0, e = -1.0, nu = 2.0;
      McaMaterial m;
      for (int i = 0; i < narg; i += 2) {
        const std::string key = arg[i];
        if (i + 1 >= narg && is_keyword(key))
          lmp->error->all(FLERR, "{}: {} needs a value", who, key);
        seen.add(key);
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
        else if (key == "poisson") {
          nu = number_arg(who, "Poisson's ratio nu", val, lmp);
          if (!(nu > -1.0 && nu < 0.5))
            lmp->error->all(FLERR, "{}: Poisson's ratio nu must lie in (-1, 0.5) (got {})", who,
                            val);
        } else
          lmp->error->all(FLERR, "{}: unknown keyword '{}' (expected bulk K shear G or young E "
                          "poisson nu; strength, damage, yield, hardening, friction, viscous, "
                          "weld)", who, key);
      }
      const bool kg = k > 0.0 || g > 0.0, enu = e > 0.0 || nu < 2.0;
      if (kg == enu || (kg && (k < 0.0 || g < 0.0)) || (enu && (e < 0.0 || nu > 1.0)))
        lmp->error->all(FLERR, "{}: give bulk K shear G, or young E poisson nu", who);
      for (const double v : {k, g, e, m.strength, m.damage, m.yield, m.hardening, m.viscous,
                             m.weld})
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
      m.lambda = m.bulk - 2.0 * m.shear / 3.0;
      return m;
    }

   private:
    static bool is_keyword(const std::string &key)
    {
      for (const char *k : {"bulk", "shear", "young", "poisson", "strength", "damage", "yield",
                            "hardening", "friction", "viscous", "weld"})
        if (key == k) return true;
      return false;
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
