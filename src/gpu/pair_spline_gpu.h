/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair styles morse/spline/gpu,
   lj/spline/gpu, mie/spline/gpu and harmonic/spline/gpu, the spline pair
   styles on LAMMPS's GPU package (doc/pair_spline.rst, "GPU variants"), as
   src/GPU/pair_morse_gpu.cpp is morse on it: the forces of the device's
   share of the atoms on the device (spline_gpu_ext.h), the rest on the host
   with the same law and tail.  Every tail and kappa; link and chain need
   the per-pair state and the chain's atom IDs of the CPU kernel and are
   refused.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_SPLINE_GPU_H
#define LMP_CLUSTERDYN_PAIR_SPLINE_GPU_H

#include "pair_spline.h"

#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  template <class Law> class PairSplineGPU : public PairSpline<Law> {
   public:
    PairSplineGPU(class LAMMPS *);
    ~PairSplineGPU() override;

    void compute(int, int) override;
    void init_style() override;
    void *extract(const char *, int &) override;
    double memory_usage() override;

    enum { GPU_FORCE, GPU_NEIGH, GPU_HYB_NEIGH };    // FixGPU's modes (pair_morse_gpu.h)

   private:
    void *device;      // the device side (spline_gpu_ext.h)
    std::string compiled;    // the variant its kernel was compiled for
    int gpu_mode;
    double cpu_time;

    std::string variant() const;
    void cpu_compute(int start, int inum, int eflag, int *ilist, int *numneigh, int **firstneigh);
    template <class TailT, bool KAPPA>
    void cpu_pairs(int start, int inum, int eflag, int *ilist, int *numneigh, int **firstneigh);
  };

  using PairMorseSplineGPU = PairSplineGPU<MorseLaw>;
  using PairLJSplineGPU = PairSplineGPU<LJLaw>;
  using PairMieSplineGPU = PairSplineGPU<MieLaw>;
  using PairHarmonicSplineGPU = PairSplineGPU<HarmonicLaw>;

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
