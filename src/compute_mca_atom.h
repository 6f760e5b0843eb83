/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute mca/atom, the state of each
   element of pair_style mca: its stress tensor by Love's formula (tension
   positive, pressure units), mean stress, equivalent (von Mises) stress,
   linked pairs, volume and damage by spall kinetics.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(mca/atom,ComputeMcaAtom);
// clang-format on
#else

#ifndef LMP_CLUSTERDYN_COMPUTE_MCA_ATOM_H
#define LMP_CLUSTERDYN_COMPUTE_MCA_ATOM_H

#include "compute.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  class PairMCA;

  class ComputeMcaAtom : public Compute {
   public:
    ComputeMcaAtom(class LAMMPS *, int, char **);
    ~ComputeMcaAtom() override;
    void init() override;
    void compute_peratom() override;
    double memory_usage() override;

    enum { SXX, SYY, SZZ, SXY, SXZ, SYZ, MEAN, EQUIVALENT, LINKS, VOLUME, DAMAGE, NCOLUMNS };

   private:
    PairMCA *pair;
    double **values;
    int nmax;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
#endif
