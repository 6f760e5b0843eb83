/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the time-step check of the spline
   pair styles.  Warns once when the time step exceeds what compute
   pair/params suggests for the deepest compression present: T_min/20 with
   T_min = pi / sqrt(ftm2v Pi''(r)/m) at the closest pair of each type pair
   (the law's argument r/n in a chain), Pi'' at least C, m the smaller
   mass.  Called on steps that rebuilt the list: at every run's setup and
   then at most every EVERY steps.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_STEP_CHECK_H
#define LMP_CLUSTERDYN_SPLINE_STEP_CHECK_H

#include "law_source.h"
#include "spline_laws.h"

#include <vector>

namespace LAMMPS_NS {
class NeighList;
namespace ClusterDyn {

  class SplineStepCheck {
   public:
    void check(LAMMPS *lmp, const char *style, const NeighList *list, const LawSource &law,
               const SplineCoeff *coeffs, double **stiffness, int chain_n,
               const std::vector<double> &chain_scale);

   private:
    int warned = 0;          // the warning was given (once per pair style)
    bigint next_check = 0;   // no check before this step (except at a run's setup)
    static constexpr int EVERY = 20;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
