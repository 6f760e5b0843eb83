/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the spline pair styles on the GPU
   package (pair_spline_gpu.h).
------------------------------------------------------------------------- */

#include "pair_spline_gpu.h"

#include "spline_gpu_ext.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "gpu_extra.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "suffix.h"

#include <cmath>
#include <cstring>
#include <type_traits>
#include <vector>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

template <class Law>
PairSplineGPU<Law>::PairSplineGPU(LAMMPS *lmp) :
    PairSpline<Law>(lmp), device(spline_gpu_create()), gpu_mode(GPU_FORCE), cpu_time(0.0)
{
  this->reinitflag = 0;    // the device holds the coefficients: fix adapt cannot change them
  this->suffix_flag |= Suffix::GPU;
  GPU_EXTRA::gpu_ready(lmp->modify, lmp->error);
}

template <class Law> PairSplineGPU<Law>::~PairSplineGPU()
{
  spline_gpu_destroy(device);
}

/* ---------------------------------------------------------------------- */

template <class Law> void PairSplineGPU<Law>::compute(int eflag, int vflag)
{
  this->ev_init(eflag, vflag);
  Atom *atom = this->atom;
  const int nall = atom->nlocal + atom->nghost;
  int inum, host_start;
  bool success = true;
  int *ilist, *numneigh, **firstneigh;
  if (gpu_mode != GPU_FORCE) {
    Domain *domain = this->domain;
    double sublo[3], subhi[3];
    if (domain->triclinic == 0) {
      for (int d = 0; d < 3; d++) {
        sublo[d] = domain->sublo[d];
        subhi[d] = domain->subhi[d];
      }
    } else
      domain->bbox(domain->sublo_lamda, domain->subhi_lamda, sublo, subhi);
    inum = atom->nlocal;
    firstneigh = spline_gpu_compute_n(device, this->neighbor->ago, inum, nall, atom->x,
                                      atom->type, sublo, subhi, atom->tag, atom->nspecial,
                                      atom->special, eflag, vflag, this->eflag_atom,
                                      this->vflag_atom, host_start, &ilist, &numneigh, cpu_time,
                                      success);
  } else {
    inum = this->list->inum;
    ilist = this->list->ilist;
    numneigh = this->list->numneigh;
    firstneigh = this->list->firstneigh;
    spline_gpu_compute(device, this->neighbor->ago, inum, nall, atom->x, atom->type, ilist,
                       numneigh, firstneigh, eflag, vflag, this->eflag_atom, this->vflag_atom,
                       host_start, cpu_time, success);
  }
  if (!success) this->error->one(FLERR, "Insufficient memory on accelerator");

  if (host_start < inum) {
    cpu_time = platform::walltime();
    cpu_compute(host_start, inum, eflag, ilist, numneigh, firstneigh);
    cpu_time = platform::walltime() - cpu_time;
  }
  // the time-step check reads the host's list (device-built lists stay on the device)
  if (gpu_mode == GPU_FORCE && this->neighbor->ago == 0)
    this->step_check.check(this->lmp, Law::style, this->list, *this, this->table.coeffs,
                           this->table.stiffness, 0, this->chain_scale);
}

/* ---------------------------------------------------------------------- */

template <class Law> void PairSplineGPU<Law>::init_style()
{
  const char *style = this->force->pair_style;
  if (this->links.on())
    this->error->all(FLERR, "Pair {}: link L is not supported on the GPU (the link state lives "
                     "with the CPU kernel's neighbour lists): use {} without the gpu suffix",
                     style, Law::style);
  if (this->setting.chain_n)
    this->error->all(FLERR, "Pair {}: chain N is not supported on the GPU (the chain needs atom "
                     "IDs in the kernel): use {} without the gpu suffix", style, Law::style);
  this->check_run();
  this->derive_table();
  // the CPU kernel stops at a pair inside a singular law's distance a (1 - 1/kappa); the
  // device kernel cannot stop, and would return infinite forces
  if (Law::singular)
    for (int i = 1; i <= this->atom->ntypes; i++)
      for (int j = i; j <= this->atom->ntypes; j++)
        if (this->setflag[i][j] && this->table.at(i, j).kappa > 1.0)
          this->error->all(FLERR, "Pair {}: kappa {} > 1 for types {} {} makes the law singular "
                           "at a (1 - 1/kappa), where the CPU style stops with an error and the "
                           "device kernel cannot: use {} without the gpu suffix (kappa <= 1 runs "
                           "on the GPU)", style, this->table.at(i, j).kappa, i, j, Law::style);

  // the kernel constants of every type pair (0: none), 16 per pair as spline_gpu.cu reads them
  Atom *atom = this->atom;
  const int np1 = atom->ntypes + 1;
  std::vector<double> coeffs(16 * np1 * np1, 0.0);
  double cutmax = 0.0;
  for (int i = 1; i < np1; i++)
    for (int j = i; j < np1; j++) cutmax = MAX(cutmax, this->init_one(i, j));
  for (int i = 1; i < np1; i++)
    for (int j = 1; j < np1; j++) {
      const SplineCoeff &c = this->table.at(i, j);
      const bool lagunov = this->setting.tail == LAGUNOV;
      const double w = Law::kappa_kernel ? c.c3 : c.a;    // lj, mie: a^2; morse, harmonic: a
      const double row[16] = {c.cutsq, c.c1, c.c2, w, c.a, c.d, c.kappa, c.offset, c.p, c.q,
                              0.0, 0.0,
                              lagunov ? c.rssq : c.bsq, lagunov ? c.rs : c.acsq,
                              lagunov ? c.inv_l2 : c.wa2, lagunov ? 0.0 : c.wa3};
      std::memcpy(&coeffs[16 * (i * np1 + j)], row, sizeof(row));
    }
  const double cell_size = cutmax + this->neighbor->skin;
  const int maxspecial = atom->molecular != Atom::ATOMIC ? atom->maxspecial : 0;
  const int mnf = 5e-2 * this->neighbor->oneatom;
  // the GPU library compiles a device object's kernel once: a new variant (pair_coeff moved
  // some kappa of lj or mie away from 1 or back) needs a new object
  const std::string now = variant();
  if (!compiled.empty() && now != compiled) {
    spline_gpu_destroy(device);
    device = spline_gpu_create();
  }
  compiled = now;
  const int success = spline_gpu_init(device, Law::style, now, np1, coeffs.data(),
                                      this->force->special_lj, atom->nlocal,
                                      atom->nlocal + atom->nghost, mnf, maxspecial, cell_size,
                                      gpu_mode, this->screen);
  GPU_EXTRA::check_flag(success, this->error, this->world);
  if (gpu_mode == GPU_FORCE) this->neighbor->add_request(this, NeighConst::REQ_FULL);
}

// the kernel's variant: the law, the tail, and kappa's path for the laws that have one
template <class Law> std::string PairSplineGPU<Law>::variant() const
{
  int law = 0;
  if (std::is_same_v<Law, HarmonicLaw>) law = 1;
  if (std::is_same_v<Law, LJLaw>) law = 2;
  if (std::is_same_v<Law, MieLaw>) law = 3;
  const int kappa = Law::kappa_kernel && this->kappa_any;
  return fmt::format("#define SPLINE_LAW {}\n#define SPLINE_TAIL {}\n#define SPLINE_KAPPA {}\n",
                     law, this->setting.tail, kappa);
}

// fix viscous/relative damps in a host pass of its own: the device kernel has no damping stage
template <class Law> void *PairSplineGPU<Law>::extract(const char *str, int &dim)
{
  if (strcmp(str, "damping_pass") == 0) {
    dim = -1;
    return nullptr;
  }
  return PairSpline<Law>::extract(str, dim);
}

template <class Law> double PairSplineGPU<Law>::memory_usage()
{
  return PairSpline<Law>::memory_usage() + spline_gpu_bytes(device);
}

/* ----------------------------------------------------------------------
   the host's share (package gpu split < 1): full lists, as the device's
   (the CPU kernel, spline_kernel.h, walks half lists and adds both ends
   of each pair), each pair's law and tail as the CPU kernel evaluates it
------------------------------------------------------------------------- */

template <class Law>
void PairSplineGPU<Law>::cpu_compute(int start, int inum, int eflag, int *ilist, int *numneigh,
                                     int **firstneigh)
{
  const bool kappa = Law::kappa_kernel && this->kappa_any;
  with_tail(this->setting.tail, [&](auto tail) {
    using TailT = decltype(tail);
    if (kappa) this->template cpu_pairs<TailT, true>(start, inum, eflag, ilist, numneigh, firstneigh);
    else this->template cpu_pairs<TailT, false>(start, inum, eflag, ilist, numneigh, firstneigh);
  });
}

template <class Law>
template <class TailT, bool KAPPA>
void PairSplineGPU<Law>::cpu_pairs(int start, int inum, int eflag, int *ilist, int *numneigh,
                                   int **firstneigh)
{
  double **x = this->atom->x;
  double **f = this->atom->f;
  const int *type = this->atom->type;
  const double *special_lj = this->force->special_lj;
  for (int ii = start; ii < inum; ii++) {
    const int i = ilist[ii];
    const int *jlist = firstneigh[i];
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const double factor_lj = special_lj[jlist[jj] >> SBBITS & 3];
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const SplineCoeff &c = this->table.at(type[i], type[j]);
      if (rsq >= c.cutsq) continue;
      if (rsq <= c.hardsq) this->singular_error(i, j, rsq);
      double fpair;
      const double e = TailT::template eval<KAPPA, Law>(c, rsq, fpair) - c.offset;
      fpair *= factor_lj;
      f[i][0] += delx * fpair;
      f[i][1] += dely * fpair;
      f[i][2] += delz * fpair;
      if (this->evflag)
        this->ev_tally_full(i, eflag ? factor_lj * e : 0.0, 0.0, fpair, delx, dely, delz);
    }
  }
}

namespace LAMMPS_NS {
namespace ClusterDyn {
  template class PairSplineGPU<MorseLaw>;
  template class PairSplineGPU<LJLaw>;
  template class PairSplineGPU<MieLaw>;
  template class PairSplineGPU<HarmonicLaw>;
}    // namespace ClusterDyn
}    // namespace LAMMPS_NS
