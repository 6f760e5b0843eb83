/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the settings of pair_style mca,
     pair_style mca fraction F [tolerance T] [manybody yes|no]
                    [plane strain|stress]   (dimension 2: required)
   parsed whole, with their restart (which names the layout of a pair's
   state, so that a restart of another layout is refused).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_SETTINGS_H
#define LMP_CLUSTERDYN_MCA_SETTINGS_H

#include "arg_values.h"
#include "keyword_set.h"
#include "mca_contact.h"

#include "comm.h"
#include "utils.h"

#include <cstdio>
#include <mpi.h>
#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaSettings {
    double fraction = 0.0;     // packing fraction: element volume = sphere volume / fraction
    double tolerance = 0.05;   // pairs closer than (1 + tolerance)(R_i + R_j) are linked
    int manybody = 1;          // the volumetric (many-body) term
    // dimension 2: the elements are discs of unit thickness in plane strain (eps_zz = 0) or
    // plane stress (sigma_zz = 0); NONE: not given (dimension 3)
    enum Plane { NONE = 0, STRAIN = 1, STRESS = 2 };
    int plane = NONE;

    static constexpr double REACH = 1.25;    // neighbour cutoff / linking distance
    // the layout of a restart: these settings' (1000: with plane and contact segments) and a
    // pair's state
    static constexpr int LAYOUT = 1000 + McaContact::NVALUES;

    static McaSettings parse(LAMMPS *lmp, int narg, char **arg)
    {
      const std::string who = "Pair mca";
      McaSettings s;
      KeywordSet seen(lmp, who, Keywords::MCA_STYLE);
      for (int i = 0; i < narg; i += 2) {
        const std::string key = arg[i];
        seen.add(key);
        if (i + 1 >= narg) lmp->error->all(FLERR, "{}: {} needs a value", who, key);
        const char *val = arg[i + 1];
        if (key == "fraction") {
          s.fraction = positive_arg(who, "fraction", val, lmp);
          // below 0.05 no packing of spheres stands (random loose 0.55, diamond 0.34), and an
          // element's volume of 1e100 spheres' overflows its many-body terms
          if (s.fraction > 1.0 || s.fraction < 0.05)
            lmp->error->all(FLERR, "{}: fraction (the packing fraction) must be in [0.05, 1] "
                            "(got {})", who, val);
        } else if (key == "tolerance") {
          s.tolerance = number_arg(who, "tolerance", val, lmp);
          if (!(s.tolerance >= 0.0 && s.tolerance < 1.0))
            lmp->error->all(FLERR, "{}: tolerance must be in [0, 1) (got {})", who, val);
        } else if (key == "plane") {
          const std::string v = val;
          if (v != "strain" && v != "stress")
            lmp->error->all(FLERR, "{}: plane must be strain or stress (got '{}')", who, v);
          s.plane = v == "strain" ? STRAIN : STRESS;
        } else {
          const std::string v = val;
          if (v != "yes" && v != "no")
            lmp->error->all(FLERR, "{}: manybody must be yes or no (got '{}')", who, v);
          s.manybody = v == "yes";
        }
      }
      if (s.fraction == 0.0)
        lmp->error->all(FLERR, "{}: fraction F is required (the packing fraction of the elements: "
                        "0.74048 for fcc and hcp; see the doc page)", who);
      return s;
    }

    // first the layout (LAYOUT): restarts of another are refused
    void write_restart(FILE *fp) const
    {
      const int layout = LAYOUT;
      fwrite(&layout, sizeof(int), 1, fp);
      fwrite(&fraction, sizeof(double), 1, fp);
      fwrite(&tolerance, sizeof(double), 1, fp);
      fwrite(&manybody, sizeof(int), 1, fp);
      fwrite(&plane, sizeof(int), 1, fp);
    }

    void read_restart(FILE *fp, LAMMPS *lmp)
    {
      int layout = 0;
      if (lmp->comm->me == 0) utils::sfread(FLERR, &layout, sizeof(int), 1, fp, nullptr, lmp->error);
      MPI_Bcast(&layout, 1, MPI_INT, 0, lmp->world);
      if (layout != LAYOUT)
        lmp->error->all(FLERR, "Pair mca: the restart file was written by another version of the "
                        "plugin (its pairs keep another state): start from a data file, the links "
                        "are made anew");
      if (lmp->comm->me == 0) {
        utils::sfread(FLERR, &fraction, sizeof(double), 1, fp, nullptr, lmp->error);
        utils::sfread(FLERR, &tolerance, sizeof(double), 1, fp, nullptr, lmp->error);
        utils::sfread(FLERR, &manybody, sizeof(int), 1, fp, nullptr, lmp->error);
        utils::sfread(FLERR, &plane, sizeof(int), 1, fp, nullptr, lmp->error);
      }
      MPI_Bcast(&fraction, 1, MPI_DOUBLE, 0, lmp->world);
      MPI_Bcast(&tolerance, 1, MPI_DOUBLE, 0, lmp->world);
      MPI_Bcast(&manybody, 1, MPI_INT, 0, lmp->world);
      MPI_Bcast(&plane, 1, MPI_INT, 0, lmp->world);
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
