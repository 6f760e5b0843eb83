/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: what the pairs of pair_style mca
   report their changes to, beyond the pair state (McaPairTally): rows of
   per-element quantities (owned and ghost) into which a pair's quantity x
   goes as its elongation is shared, x a_j / (a_i + a_j) to i and
   x a_i / (a_i + a_j) to j, a_i and a_j the half stiffnesses of its
   elements (McaPairHalves).  The many-body term's volumetric strain, the
   volume changes it follows (McaManybody; those in the columns of
   McaVolumeChanges) and the plastic work the elements take as heat
   (McaElementEos) are such rows; the pair laws see the rows only.  Not an
   interface of virtual calls: the force pass inlines the additions (as
   calls they cost 6 % of a plate's Pair time, doc/benchmarks/bench_mca.md
   "The tally inlined").
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_PAIR_CHANGES_H
#define LMP_CLUSTERDYN_MCA_PAIR_CHANGES_H

#include "mca_pair_halves.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  // the columns of the elements' volume changes: by breaking and welding, damage, plastic flow,
  // and the links' elongation over the step (for the plastic work's share of the many-body lag)
  struct McaVolumeChanges {
    enum { CHANGE_STATE = 0, CHANGE_DAMAGE = 1, CHANGE_PLASTIC = 2, MOTION = 3, NCHANGES = 4 };
  };

  struct McaElementShares {
    double **rows = nullptr;    // null: nothing takes the shares

    explicit operator bool() const { return rows != nullptr; }
    // pair ij's x into a column, shared by its elements' halves (j's share where jown)
    void add(int column, int i, int j, double x, const McaPairHalves &halves, bool jown) const
    {
      rows[i][column] += x * halves.share_i();
      if (jown) rows[j][column] += x * halves.share_j();
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
