/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the device side of the spline pair
   styles on the GPU package (spline_gpu_device.h).
------------------------------------------------------------------------- */

#include "spline_gpu_cl.h"    // const char *spline_gpu: spline_gpu.cu as text (CMakeLists.txt)

#include "spline_gpu_device.h"

namespace LAMMPS_AL {

template <class numtyp, class acctyp>
SplineGPUDevice<numtyp, acctyp>::SplineGPUDevice() :
    BaseAtomic<numtyp, acctyp>(), shared_types(false), types(0), allocated(false)
{
}

template <class numtyp, class acctyp> SplineGPUDevice<numtyp, acctyp>::~SplineGPUDevice()
{
  clear();
}

template <class numtyp, class acctyp>
int SplineGPUDevice<numtyp, acctyp>::init(const std::string &variant, int ntypes,
                                          const double *coeffs, const double *special_lj,
                                          int nlocal, int nall, int max_nbors, int maxspecial,
                                          double cell_size, double gpu_split, FILE *screen)
{
  program = variant + spline_gpu;
  const int success = this->init_atomic(nlocal, nall, max_nbors, maxspecial, cell_size,
                                        gpu_split, screen, program.c_str(), "k_spline");
  if (success != 0) return success;

  // the type table in local memory when it fits (the block's threads load it in strides)
  const int max_shared = this->device->max_shared_types();
  shared_types = ntypes <= max_shared;
  types = shared_types ? max_shared : ntypes;

  UCL_D_Vec<numtyp4> *tables[4] = {&coef1, &coef2, &coef3, &tailc};
  UCL_H_Vec<numtyp> host(types * types * 4, *(this->ucl_device), UCL_WRITE_ONLY);
  for (int t = 0; t < 4; t++) {
    for (int k = 0; k < types * types * 4; k++) host[k] = 0.0;
    for (int i = 0; i < ntypes; i++)
      for (int j = 0; j < ntypes; j++)
        for (int m = 0; m < 4; m++)
          host[(i * types + j) * 4 + m] =
              static_cast<numtyp>(coeffs[(i * ntypes + j) * 16 + 4 * t + m]);
    tables[t]->alloc(types * types, *(this->ucl_device), UCL_READ_ONLY);
    UCL_H_Vec<numtyp4> view;
    view.view_offset(0, host, types * types);
    ucl_copy(*tables[t], view, false);
  }

  for (int k = 0; k < 4; k++) host[k] = static_cast<numtyp>(special_lj[k]);
  sp_lj.alloc(4, *(this->ucl_device), UCL_READ_ONLY);
  ucl_copy(sp_lj, host, 4, false);

  allocated = true;
  this->_max_bytes = 4 * coef1.row_bytes() + sp_lj.row_bytes();
  return 0;
}

template <class numtyp, class acctyp> void SplineGPUDevice<numtyp, acctyp>::clear()
{
  if (!allocated) return;
  allocated = false;
  coef1.clear();
  coef2.clear();
  coef3.clear();
  tailc.clear();
  sp_lj.clear();
  this->clear_atomic();
}

template <class numtyp, class acctyp>
double SplineGPUDevice<numtyp, acctyp>::host_memory_usage() const
{
  return this->host_memory_usage_atomic() + sizeof(SplineGPUDevice<numtyp, acctyp>);
}

// the forces of this step: k_spline_fast (with or without energies, LAL_OCL_EV_JIT) when the
// type table fits in local memory, else k_spline
template <class numtyp, class acctyp>
int SplineGPUDevice<numtyp, acctyp>::loop(const int eflag, const int vflag)
{
  const int BX = this->block_size();
  const int GX = static_cast<int>(
      ceil(static_cast<double>(this->ans->inum()) / (BX / this->_threads_per_atom)));
  int ainum = this->ans->inum();
  int nbor_pitch = this->nbor->nbor_pitch();
  this->time_pair.start();
  if (shared_types) {
    this->k_pair_sel->set_size(GX, BX);
    this->k_pair_sel->run(&this->atom->x, &coef1, &coef2, &coef3, &tailc, &sp_lj,
                          &this->nbor->dev_nbor, &this->_nbor_data->begin(), &this->ans->force,
                          &this->ans->engv, &eflag, &vflag, &ainum, &nbor_pitch,
                          &this->_threads_per_atom);
  } else {
    this->k_pair.set_size(GX, BX);
    this->k_pair.run(&this->atom->x, &coef1, &coef2, &coef3, &tailc, &types, &sp_lj,
                     &this->nbor->dev_nbor, &this->_nbor_data->begin(), &this->ans->force,
                     &this->ans->engv, &eflag, &vflag, &ainum, &nbor_pitch,
                     &this->_threads_per_atom);
  }
  this->time_pair.stop();
  return GX;
}

template class SplineGPUDevice<PRECISION, ACC_PRECISION>;

}    // namespace LAMMPS_AL
