/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the neighbor skin against the
   interaction range.  LAMMPS's default skin is a fixed length of each unit
   style (units si: 1 mm, cgs: 0.1 cm); at cluster scale (a ~ 10 um) that is
   100 particle sizes, the ghost shell spans many box lengths and LAMMPS
   fails in binning.  The styles stop first, naming the fix.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SKIN_CHECK_H
#define LMP_CLUSTERDYN_SKIN_CHECK_H

#include "error.h"
#include "lammps.h"
#include "neighbor.h"
#include "update.h"

#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  // the largest skin accepted, in units of the interaction range
  constexpr double MAX_SKIN_RATIO = 10.0;

  inline void check_neighbor_skin(LAMMPS *lmp, double range, const std::string &who)
  {
    const double skin = lmp->neighbor->skin;
    if (range > 0.0 && skin > MAX_SKIN_RATIO * range)
      lmp->error->all(FLERR, "{}: neighbor skin {:.6g} is {:.3g} x the interaction range "
                      "{:.6g}: set it, e.g. neighbor {:.3g} bin (the default skin of units {} "
                      "suits atoms, not clusters)", who, skin, skin / range, range,
                      0.25 * range, lmp->update->unit_style);
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
