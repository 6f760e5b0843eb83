/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: what the pairs of pair_style mca
   report their changes to, beyond the pair state (McaPairTally): rows of
   per-element quantities (owned and ghost) that take a pair's share as
   its elongation does, i x a_j / (a_i + a_j) and j x a_i / (a_i + a_j) of
   the pair's x, a_i and a_j the half stiffnesses of its elements
   (mca_element_stiffness.h).  The many-body term's volumetric strain and
   the volume changes it follows (McaManybody, in the columns of
   McaVolumeChanges) and the plastic work the elements take as heat
   (McaElementEos) are such rows; the pair laws see the rows only.  Not an
   interface of virtual calls: the force pass inlines the additions (as
   calls they cost 6 % of a plate's Pair time, doc/benchmarks/bench_mca.md).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_PAIR_CHANGES_H
#define LMP_CLUSTERDYN_MCA_PAIR_CHANGES_H

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
    // pair ij's x into a column, shared by the half stiffnesses ai, aj (j's share where jown)
    void add(int column, int i, int j, double x, double ai, double aj, bool jown) const
    {
      rows[i][column] += x * aj / (ai + aj);
      if (jown) rows[j][column] += x * ai / (ai + aj);
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
