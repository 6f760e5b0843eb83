/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the material of a movable cellular
   automaton (element) type and its reading from pair_coeff.  Isotropic
   linear elasticity: bulk modulus K and shear modulus G, given as
   "bulk K shear G" or "young E poisson nu", and optionally the strength
   sigma_c at which a linked pair in tension unlinks (pressure units).
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
    double bulk = 0.0;      // K
    double shear = 0.0;     // G
    double lambda = 0.0;    // Lame's first parameter K - 2G/3: the many-body (volumetric) term
    double strength = 0.0;  // sigma_c; 0: the links never break

    // the words of pair_coeff that give this material back (data files)
    std::string words() const
    {
      std::string w = fmt::format("bulk {:.17g} shear {:.17g}", bulk, shear);
      if (strength > 0.0) w += fmt::format(" strength {:.17g}", strength);
      return w;
    }

    void write_restart(FILE *fp) const
    {
      const double v[3] = {bulk, shear, strength};
      fwrite(v, sizeof(double), 3, fp);
    }

    void read_restart(FILE *fp, LAMMPS *lmp)    // processor 0 reads, all take it
    {
      double v[3];
      if (lmp->comm->me == 0) utils::sfread(FLERR, v, sizeof(double), 3, fp, nullptr, lmp->error);
      MPI_Bcast(v, 3, MPI_DOUBLE, 0, lmp->world);
      bulk = v[0];
      shear = v[1];
      strength = v[2];
      lambda = bulk - 2.0 * shear / 3.0;
    }

    double young() const { return 9.0 * bulk * shear / (3.0 * bulk + shear); }
    double poisson() const { return (3.0 * bulk - 2.0 * shear) / (2.0 * (3.0 * bulk + shear)); }

    // pair_coeff I I bulk K shear G | young E poisson nu [strength S] (words after I I)
    static McaMaterial read(const std::string &who, int narg, char **arg, LAMMPS *lmp)
    {
      KeywordSet seen(lmp, who);
      double k = -1.0, g = -1.0, e = -1.0, nu = 2.0, strength = 0.0;
      for (int i = 0; i < narg; i += 2) {
        const std::string key = arg[i];
        if (key != "bulk" && key != "shear" && key != "young" && key != "poisson" &&
            key != "strength")
          lmp->error->all(FLERR, "{}: unknown keyword '{}' (expected bulk K shear G or young E "
                          "poisson nu, and strength S)", who, key);
        if (i + 1 >= narg) lmp->error->all(FLERR, "{}: {} needs a value", who, key);
        seen.add(key);
        const char *val = arg[i + 1];
        if (key == "bulk") k = positive_arg(who, "bulk modulus K", val, lmp);
        else if (key == "shear") g = positive_arg(who, "shear modulus G", val, lmp);
        else if (key == "young") e = positive_arg(who, "Young's modulus E", val, lmp);
        else if (key == "strength") strength = positive_arg(who, "strength", val, lmp);
        else {
          nu = number_arg(who, "Poisson's ratio nu", val, lmp);
          if (!(nu > -1.0 && nu < 0.5))
            lmp->error->all(FLERR, "{}: Poisson's ratio nu must lie in (-1, 0.5) (got {})", who,
                            val);
        }
      }
      const bool kg = k > 0.0 || g > 0.0, enu = e > 0.0 || nu < 2.0;
      if (kg == enu || (kg && (k < 0.0 || g < 0.0)) || (enu && (e < 0.0 || nu > 1.0)))
        lmp->error->all(FLERR, "{}: give bulk K shear G, or young E poisson nu", who);
      for (const double v : {k, g, e, strength})
        if (v > 0.0 && !(v >= 1.0e-100 && v <= 1.0e100))
          lmp->error->all(FLERR, "{}: a modulus of {} is outside the range 1e-100 to 1e100 that "
                          "the force kernel takes (pressure units of the unit style)", who, v);
      McaMaterial m;
      m.bulk = kg ? k : e / (3.0 * (1.0 - 2.0 * nu));
      m.shear = kg ? g : e / (2.0 * (1.0 + nu));
      m.lambda = m.bulk - 2.0 * m.shear / 3.0;
      m.strength = strength;
      return m;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
