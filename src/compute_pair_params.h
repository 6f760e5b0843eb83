/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute pair/params, the
   characteristic parameters of a pair law (doc/compute_pair_params.rst).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_COMPUTE_PAIR_PARAMS_H
#define LMP_CLUSTERDYN_COMPUTE_PAIR_PARAMS_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class ComputePairParams : public Compute {
   public:
    ComputePairParams(class LAMMPS *, int, char **);
    ~ComputePairParams() override;
    void init() override;
    void compute_vector() override;
    void compute_array() override;

    static constexpr int NVALUES = 21;

   private:
    int itype, jtype;
    double mass_user;            // 0: the mass of type I
    double rc_user;              // 0: the pair cutoff / a
    double lambda;               // v_l / v0 of the lattice, 0 without
    std::vector<double> speeds;  // loading speeds of the shock table
    int fresh;                   // values are up to date for this run

    void evaluate();
    void shock_table(class LawProbe &probe, double a, double c);
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
