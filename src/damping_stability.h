/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the stability check of fix
   viscous/relative at each run's setup.  The explicit update of the
   relative velocities is stable while G x (bonds per atom) x dt stays
   below 1 (its eigenvalues reach 2 G x bonds): above, a run stops with
   the time step that would do; run 0 is only warned.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_DAMPING_STABILITY_H
#define LMP_CLUSTERDYN_DAMPING_STABILITY_H

#include "damping_forces.h"
#include "damping_pairs.h"

namespace LAMMPS_NS {
class Fix;
namespace ClusterDyn {

  // the fix's bonds, counted per atom in its fd (counts.data()[i].x, ghosts' counts summed to
  // their owners by the fix's reverse communication)
  void check_damping_stability(LAMMPS *lmp, Fix *fix, const DampingBonds &bonds,
                               const DampingTypes &types, const ViscousSettings &opt,
                               DampingForces &counts);

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
