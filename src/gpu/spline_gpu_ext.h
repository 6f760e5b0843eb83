/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: what the spline pair styles' GPU
   variants (pair_spline_gpu.h) call of their device side
   (spline_gpu_device.h), without the GPU library's headers, as the GPU
   package's styles call lib/gpu (src/GPU/pair_morse_gpu.cpp): one device
   object per pair style, named by an opaque handle.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_GPU_EXT_H
#define LMP_CLUSTERDYN_SPLINE_GPU_EXT_H

#include "lmptype.h"

#include <cstdio>
#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  void *spline_gpu_create();
  void spline_gpu_destroy(void *handle);
  // compiles the kernel for variant (its defines), copies the coefficients (ntypes x ntypes x 16)
  // to the device; returns the GPU library's code (GPU_EXTRA::check_flag reads it)
  int spline_gpu_init(void *handle, const char *style, const std::string &variant, int ntypes,
                      const double *coeffs, const double *special_lj, int nlocal, int nall,
                      int max_nbors, int maxspecial, double cell_size, int &gpu_mode,
                      FILE *screen);
  // device-built neighbour lists
  int **spline_gpu_compute_n(void *handle, int ago, int inum, int nall, double **host_x,
                             int *host_type, double *sublo, double *subhi, tagint *tag,
                             int **nspecial, tagint **special, bool eflag, bool vflag, bool eatom,
                             bool vatom, int &host_start, int **ilist, int **jnum,
                             double cpu_time, bool &success);
  // host-built neighbour lists
  void spline_gpu_compute(void *handle, int ago, int inum, int nall, double **host_x,
                          int *host_type, int *ilist, int *numj, int **firstneigh, bool eflag,
                          bool vflag, bool eatom, bool vatom, int &host_start, double cpu_time,
                          bool &success);
  double spline_gpu_bytes(void *handle);

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
