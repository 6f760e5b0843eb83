/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: what the law of one pair of
   pair_style mca gives its force pass: the force on element i (all of it,
   and the tangential part that makes the torques), a link's moment and the
   pair's energy (McaPairForce), given the load of its elements' pressure
   (McaPressureLoad); and where it tallies what it changes
   (McaPairTally): the state counts and energies of the pair state (a pair
   with a ghost counts w = 1/2 with newton off, as both processors see it),
   the dissipated works, the changes of volume that the many-body term
   follows, and the plastic work that heats elements with a shock equation
   of state, into the elements' rows (mca_pair_changes.h).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_PAIR_TALLY_H
#define LMP_CLUSTERDYN_MCA_PAIR_TALLY_H

#include "mca_pair_changes.h"
#include "pair_state.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  // the energies dissipated, in StateTally::work (and after the state's tally in pvector)
  enum McaWork { WORK_DAMAGE = 0, WORK_PLASTIC = 1, WORK_FRICTION = 2, NWORK = 3 };

  struct McaPairForce {
    double fi[3], ft[3], mom[3] = {0.0, 0.0, 0.0}, evdwl = 0.0;
  };

  // what the elements' pressure does to a linked pair (mca_element_eos.h): its effective force
  // on i, and the mean stress -p of its elements that its response reads as normal stress;
  // whether an element of it has spall kinetics (kinetic) and is fully damaged (spalled)
  struct McaPressureLoad {
    double f[3], stress;
    bool kinetic = false, spalled = false;
  };

  struct McaPairTally {
    StateTally &changes;
    double w;                 // 1, or 1/2 for a pair with a ghost and newton off
    McaElementShares volume;  // the elements' volume changes (McaVolumeChanges' columns); none:
                              // the many-body term does not follow them
    int i, j;
    McaPairHalves halves;     // the elements' half stiffnesses
    bool jown;                // j's side is tallied here
    McaElementShares heat;    // none: no element takes the plastic work as heat

    void work(McaWork kind, double energy) const
    {
      changes.work[kind] += w * energy;
      if (kind == WORK_PLASTIC && heat) heat.add(0, i, j, energy, halves, jown);
    }
    void volume_change(int column, double dv) const
    {
      if (volume) volume.add(column, i, j, dv, halves, jown);
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
