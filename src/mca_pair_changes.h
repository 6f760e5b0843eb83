/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: what the pairs of pair_style mca
   report their changes to, beyond the pair state (McaPairTally): the
   elements' volume changes, which the many-body term follows
   (McaManybody), and the plastic work the elements take as heat
   (McaElementEos).  The pair laws see these interfaces only.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_PAIR_CHANGES_H
#define LMP_CLUSTERDYN_MCA_PAIR_CHANGES_H

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaVolumeChanges {
   public:
    // the changes of a pair's volume: by breaking and welding, damage, plastic flow, and the
    // links' elongation over the step (for the plastic work's share of the many-body lag)
    enum { CHANGE_STATE = 0, CHANGE_DAMAGE = 1, CHANGE_PLASTIC = 2, MOTION = 3, NCHANGES = 4 };
    // pair ij's volume change dv in a column, shared by the half stiffnesses ai, aj (j's
    // share where jown)
    virtual void add_change(int column, int i, int j, double dv, double ai, double aj,
                            bool jown) = 0;

   protected:
    ~McaVolumeChanges() = default;
  };

  class McaPlasticHeat {
   public:
    // pair ij's plastic work, shared as its elongation (ai, aj: the half stiffnesses)
    virtual void add_heat(int i, int j, double work, double ai, double aj, bool jown) = 0;

   protected:
    ~McaPlasticHeat() = default;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
