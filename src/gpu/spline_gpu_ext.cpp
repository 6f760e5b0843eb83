/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the device side's entry points
   (spline_gpu_ext.h), the sequence of lib/gpu's lal_morse_ext.cpp: the
   first rank compiles the kernel, then the ranks sharing a device in turn.
------------------------------------------------------------------------- */

#include "spline_gpu_ext.h"

#include "spline_gpu_device.h"

using namespace LAMMPS_AL;

namespace {
using SplineDevice = SplineGPUDevice<PRECISION, ACC_PRECISION>;
SplineDevice &of(void *handle)
{
  return *static_cast<SplineDevice *>(handle);
}
}    // namespace

namespace LAMMPS_NS {
namespace ClusterDyn {

  void *spline_gpu_create()
  {
    return new SplineDevice();
  }

  void spline_gpu_destroy(void *handle)
  {
    delete static_cast<SplineDevice *>(handle);
  }

  int spline_gpu_init(void *handle, const char *style, const std::string &variant, int ntypes,
                      const double *coeffs, const double *special_lj, int nlocal, int nall,
                      int max_nbors, int maxspecial, double cell_size, int &gpu_mode,
                      FILE *screen)
  {
    SplineDevice &dev = of(handle);
    dev.clear();
    gpu_mode = dev.device->gpu_mode();
    const double gpu_split = dev.device->particle_split();
    const int first_gpu = dev.device->first_device();
    const int last_gpu = dev.device->last_device();
    const int world_me = dev.device->world_me();
    const int gpu_rank = dev.device->gpu_rank();
    const int procs_per_gpu = dev.device->procs_per_gpu();

    dev.device->init_message(screen, style, first_gpu, last_gpu);
    const bool message = dev.device->replica_me() == 0 && screen;
    if (message) {
      fprintf(screen, "Initializing Device and compiling on process 0...");
      fflush(screen);
    }
    auto init = [&]() {
      return dev.init(variant, ntypes, coeffs, special_lj, nlocal, nall, max_nbors, maxspecial,
                      cell_size, gpu_split, screen);
    };
    int init_ok = 0;
    if (world_me == 0) init_ok = init();
    dev.device->world_barrier();
    if (message) fprintf(screen, "Done.\n");

    for (int i = 0; i < procs_per_gpu; i++) {
      if (message) {
        if (last_gpu - first_gpu == 0)
          fprintf(screen, "Initializing Device %d on core %d...", first_gpu, i);
        else
          fprintf(screen, "Initializing Devices %d-%d on core %d...", first_gpu, last_gpu, i);
        fflush(screen);
      }
      if (gpu_rank == i && world_me != 0) init_ok = init();
      dev.device->serialize_init();
      if (message) fprintf(screen, "Done.\n");
    }
    if (message) fprintf(screen, "\n");
    if (init_ok == 0) dev.estimate_gpu_overhead();
    return init_ok;
  }

  int **spline_gpu_compute_n(void *handle, int ago, int inum, int nall, double **host_x,
                             int *host_type, double *sublo, double *subhi, tagint *tag,
                             int **nspecial, tagint **special, bool eflag, bool vflag, bool eatom,
                             bool vatom, int &host_start, int **ilist, int **jnum,
                             double cpu_time, bool &success)
  {
    return of(handle).compute(ago, inum, nall, host_x, host_type, sublo, subhi, tag, nspecial,
                              special, eflag, vflag, eatom, vatom, host_start, ilist, jnum,
                              cpu_time, success);
  }

  void spline_gpu_compute(void *handle, int ago, int inum, int nall, double **host_x,
                          int *host_type, int *ilist, int *numj, int **firstneigh, bool eflag,
                          bool vflag, bool eatom, bool vatom, int &host_start, double cpu_time,
                          bool &success)
  {
    of(handle).compute(ago, inum, nall, host_x, host_type, ilist, numj, firstneigh, eflag, vflag,
                       eatom, vatom, host_start, cpu_time, success);
  }

  double spline_gpu_bytes(void *handle)
  {
    return of(handle).host_memory_usage();
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS
