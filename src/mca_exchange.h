/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: how the components of pair_style mca
   exchange per-element columns between processors (the pair style's
   forward and reverse communication, which LAMMPS calls on the pair:
   pair_column_exchange.h).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_EXCHANGE_H
#define LMP_CLUSTERDYN_MCA_EXCHANGE_H

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaExchange {
   public:
    // the ghosts' rows summed onto their owners (with newton_pair on; off, owners have theirs)
    virtual void to_owners(double **rows, int columns) = 0;
    // the owners' rows copied to their ghosts
    virtual void to_ghosts(double **rows, int columns) = 0;

   protected:
    ~McaExchange() = default;    // not deleted through this interface
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
