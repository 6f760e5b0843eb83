/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: whether the ghost atoms that fix
   viscous/relative damps carry their owners' per-atom masses.  An atom
   style's rmass travels with the ghost atoms; fix property/atom rmass's
   only with ghost yes (its default, ghost no, leaves the ghosts' masses
   0 or stale: LAMMPS warns, and pair amoeba stops for its properties).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_DAMPING_MASSES_H
#define LMP_CLUSTERDYN_DAMPING_MASSES_H

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
namespace ClusterDyn {

  // the ID of the fix property/atom that defines rmass without ghost yes; "" where there is
  // none (per-type masses, an atom style's rmass, or fix property/atom rmass ghost yes).
  // The same on every processor (the fixes' settings, no atom data).
  std::string ghostless_rmass_fix(LAMMPS *lmp);

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
