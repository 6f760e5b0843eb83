/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the device side of the spline pair
   styles on the GPU package (pair_style morse/spline/gpu and its kin), a
   LAMMPS Accelerator Library (lib/gpu) class as lal_morse is for stock
   morse/gpu: the per type pair coefficients on the device and the force
   kernel (spline_gpu.cu) compiled for one law, tail and kappa mode.
   Compiled with the GPU library's own definitions (CMakeLists.txt).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_GPU_DEVICE_H
#define LMP_CLUSTERDYN_SPLINE_GPU_DEVICE_H

#include "lal_base_atomic.h"

#include <string>

namespace LAMMPS_AL {

template <class numtyp, class acctyp> class SplineGPUDevice : public BaseAtomic<numtyp, acctyp> {
 public:
  SplineGPUDevice();
  ~SplineGPUDevice() override;

  /// the variant (defines the kernel is compiled with: SPLINE_LAW, SPLINE_TAIL, SPLINE_KAPPA),
  /// ntypes rows and columns of 16 coefficients per type pair (coef1, coef2, coef3 and tailc of
  /// spline_gpu.cu), the rest as BaseAtomic::init_atomic; returns its codes (0: success)
  int init(const std::string &variant, int ntypes, const double *coeffs, const double *special_lj,
           int nlocal, int nall, int max_nbors, int maxspecial, double cell_size,
           double gpu_split, FILE *screen);
  void clear();
  double host_memory_usage() const;

 private:
  UCL_D_Vec<numtyp4> coef1, coef2, coef3, tailc;
  UCL_D_Vec<numtyp> sp_lj;
  bool shared_types;    // the type table fits in local memory: k_spline_fast
  int types;            // rows of the device tables
  bool allocated;
  std::string program;    // the variant's defines and the kernel source

  int loop(const int eflag, const int vflag) override;
};

}    // namespace LAMMPS_AL

#endif
