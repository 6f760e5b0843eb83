/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: /omp variants of the spline pair
   styles, following OPENMP/pair_morse_omp.cpp.
------------------------------------------------------------------------- */

#include "pair_spline_omp.h"

#include "atom.h"
#include "comm.h"
#include "force.h"
#include "neigh_list.h"
#include "suffix.h"

#include <exception>

#include "omp_compat.h"

using namespace LAMMPS_NS;
using namespace ClusterDyn;

template <class Law>
PairSplineOMP<Law>::PairSplineOMP(LAMMPS *lmp) : PairSpline<Law>(lmp), ThrOMP(lmp, THR_PAIR)
{
  this->suffix_flag |= Suffix::OMP;
  this->respa_enable = 0;
}

template <class Law> void PairSplineOMP<Law>::compute(int eflag, int vflag)
{
  this->ev_init(eflag, vflag);
  const int nall = this->atom->nlocal + this->atom->nghost;
  const int nthreads = this->comm->nthreads;
  const int inum = this->list->inum;
  const StatePass pass = this->start_compute();
  std::exception_ptr failure;    // an error of a thread, raised after the parallel region
  StateTally changes;
  DampingPass *const fused = this->damping_this_step();    // fix viscous/relative's
  if (fused) damping_threads.reserve(nthreads, nall);

#if defined(_OPENMP)
#pragma omp parallel LMP_DEFAULT_NONE LMP_SHARED(eflag, vflag, failure, changes, pass, fused)
#endif
  {
    int ifrom, ito, tid;
    loop_setup_thr(ifrom, ito, tid, inum, nthreads);
    ThrData *thr = fix->get_thr(tid);
    thr->timer(Timer::START);
    ev_setup_thr(eflag, vflag, nall, this->eatom, this->vatom, nullptr, thr);
    StateTally mine;
    const DampingPass damping_mine = fused ? damping_threads.pass_of(*fused, tid) : DampingPass();
    try {
      run_spline_kernel<Law>(
          this->variant(eflag, fused), this->kernel_data(fused ? &damping_mine : nullptr),
          this->list, this->atom, this->force->special_lj, ifrom, ito, (xyz3 *) thr->get_f()[0],
          pass, mine,
          [&](int i, int j, int nlocal, int newton, double evdwl, double fpair, double dx,
              double dy, double dz) {
            ev_tally_thr(this, i, j, nlocal, newton, evdwl, 0.0, fpair, dx, dy, dz, thr);
          },
          [this](int i, int j, double rsq) { this->singular_error(i, j, rsq); });
    } catch (...) {    // an exception must not leave an OpenMP region (std::terminate)
#if defined(_OPENMP)
#pragma omp critical(clusterdyn_pair_spline_failure)
#endif
      if (!failure) failure = std::current_exception();
    }
#if defined(_OPENMP)
#pragma omp critical(clusterdyn_pair_spline_links)
#endif
    changes.add(mine);
    if (fused && nthreads > 1) {
      sync_threads();
      damping_threads.reduce(fused->fd, tid, nthreads);
    }
    thr->timer(Timer::PAIR);
    reduce_thr(this, eflag, vflag, thr);
  }
  if (failure) std::rethrow_exception(failure);
  if (fused) fused->filled = 1;
  this->finish_compute(changes);
}

template <class Law> double PairSplineOMP<Law>::memory_usage()
{
  return memory_usage_thr() + PairSpline<Law>::memory_usage() + damping_threads.memory_usage();
}

namespace LAMMPS_NS {
namespace ClusterDyn {
  template class PairSplineOMP<MorseLaw>;
  template class PairSplineOMP<LJLaw>;
  template class PairSplineOMP<MieLaw>;
  template class PairSplineOMP<HarmonicLaw>;
}    // namespace ClusterDyn
}    // namespace LAMMPS_NS
