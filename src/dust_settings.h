/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the arguments of compute dust,
   parsed whole:
     compute ID group dust [cutoff d] [maxsize N] [links] [rows all|dust]
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_DUST_SETTINGS_H
#define LMP_CLUSTERDYN_DUST_SETTINGS_H

#include "pointers.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct DustSettings {
    double cutoff = 0.0;    // 0: the pair style's cutoff of each type pair
    bigint maxsize = 0;     // 0: every fragment but the largest is dust
    int links = 0;          // bonds = the pair style's links (link L), not distances
    int dust_rows = 0;      // local rows of the dust only (rows dust), not every fragment

    static DustSettings parse(LAMMPS *lmp, int narg, char **arg);
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
