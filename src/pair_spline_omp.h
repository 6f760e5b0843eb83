/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the /omp variants of the spline pair
   styles (OPENMP package threading; same per-pair kernel as PairSpline).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_SPLINE_OMP_H
#define LMP_CLUSTERDYN_PAIR_SPLINE_OMP_H

#include "damping_threads.h"
#include "pair_spline.h"
#include "thr_omp.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  template <class Law> class PairSplineOMP : public PairSpline<Law>, public ThrOMP {
   public:
    PairSplineOMP(class LAMMPS *);

    void compute(int, int) override;
    double memory_usage() override;

   private:
    DampingThreads damping_threads;    // fix viscous/relative's damping, per thread
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
