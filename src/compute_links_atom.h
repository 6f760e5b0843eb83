/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute links/atom, the number of
   intact links of each atom under a pair style with link L
   (doc/compute_links_atom.rst).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_COMPUTE_LINKS_ATOM_H
#define LMP_CLUSTERDYN_COMPUTE_LINKS_ATOM_H

#include "compute.h"

namespace LAMMPS_NS {
namespace ClusterDyn {
  class PairState;

  class ComputeLinksAtom : public Compute {
   public:
    ComputeLinksAtom(class LAMMPS *, int, char **);
    ~ComputeLinksAtom() override;
    void init() override;
    void compute_peratom() override;
    int pack_reverse_comm(int, int, double *) override;
    void unpack_reverse_comm(int, int *, double *) override;
    double memory_usage() override;

   private:
    PairState *state;          // of the pair style (link L)
    int nmax;
    double *count;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
