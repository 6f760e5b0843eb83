/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: /omp variants of the spline pair
   styles, following OPENMP/pair_morse_omp.cpp.
------------------------------------------------------------------------- */

#include "pair_spline_omp.h"

#include "atom.h"
#include "comm.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "suffix.h"

#include <cmath>
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
  std::exception_ptr failure;    // an error of a thread, raised after the parallel region
  LinkTally pass;

#if defined(_OPENMP)
#pragma omp parallel LMP_DEFAULT_NONE LMP_SHARED(eflag, vflag, failure, pass)
#endif
  {
    int ifrom, ito, tid;
    loop_setup_thr(ifrom, ito, tid, inum, nthreads);
    ThrData *thr = fix->get_thr(tid);
    thr->timer(Timer::START);
    ev_setup_thr(eflag, vflag, nall, this->eatom, this->vatom, nullptr, thr);
    LinkTally mine;
    try {
      this->dispatch(eflag, [&](auto t, auto mode, auto ev, auto e, auto n) {
        eval<decltype(t)::value, decltype(mode)::value, decltype(ev)::value, decltype(e)::value,
             decltype(n)::value>(ifrom, ito, thr, mine);
      });
    } catch (...) {    // an exception must not leave an OpenMP region (std::terminate)
#if defined(_OPENMP)
#pragma omp critical(clusterdyn_pair_spline_failure)
#endif
      if (!failure) failure = std::current_exception();
    }
#if defined(_OPENMP)
#pragma omp critical(clusterdyn_pair_spline_links)
#endif
    {
      pass.broken += mine.broken;
      pass.formed += mine.formed;
      pass.ejump += mine.ejump;
    }
    thr->timer(Timer::PAIR);
    reduce_thr(this, eflag, vflag, thr);
  }
  if (failure) std::rethrow_exception(failure);
  if (this->link_l > 0.0) this->link_done(pass);
  if (this->neighbor->ago == 0) this->check_time_step();
}

template <class Law>
template <int TAIL, int MODE, int EVFLAG, int EFLAG, int NEWTON_PAIR>
void PairSplineOMP<Law>::eval(int iifrom, int iito, ThrData *const thr, LinkTally &links)
{
  constexpr bool CHAIN = MODE == PairSpline<Law>::CHAIN;
  constexpr bool LINKED = PairSpline<Law>::mode_link(MODE);
  int *const *const touch = LINKED ? this->fix_history->firstflag : nullptr;
  const int linking = LINKED ? this->linking_now() : LINK_KEEP;
  const tagint *_noalias const tag = this->atom->tag;
  const auto *_noalias const x = (xyz3 *) this->atom->x[0];
  auto *_noalias const f = (xyz3 *) thr->get_f()[0];
  const int *_noalias const type = this->atom->type;
  const int nlocal = this->atom->nlocal;
  const double *_noalias const special_lj = this->force->special_lj;
  const int ntp1 = this->atom->ntypes + 1;
  const int *_noalias const ilist = this->list->ilist;
  const int *_noalias const numneigh = this->list->numneigh;
  int **firstneigh = this->list->firstneigh;
  double evdwl = 0.0;

  for (int ii = iifrom; ii < iito; ++ii) {
    const int i = ilist[ii];
    const double xtmp = x[i].x, ytmp = x[i].y, ztmp = x[i].z;
    const SplineCoeff *_noalias const ci = this->coeffs + type[i] * ntp1;
    const int *_noalias const jlist = firstneigh[i];
    const int jnum = numneigh[i];
    double fxtmp = 0.0, fytmp = 0.0, fztmp = 0.0;

    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj];
      const double factor_lj = special_lj[this->sbmask(j)];
      j &= NEIGHMASK;
      const double delx = xtmp - x[j].x;
      const double dely = ytmp - x[j].y;
      const double delz = ztmp - x[j].z;
      const double rsq = delx * delx + dely * dely + delz * delz;
      const SplineCoeff &c = ci[type[j]];
      double scale = 1.0;    // chain: the n-th neighbour along the chain feels Pi(r/n)
      if (CHAIN) {
        const tagint n = tag[i] > tag[j] ? tag[i] - tag[j] : tag[j] - tag[i];
        if (n == 0 || n > this->chain_n) continue;    // n = 0: a periodic image of atom i
        scale = this->chain_scale[n];
      }
      const double rsq_law = CHAIN ? rsq * scale : rsq;
      double e, fpair;
      const double w = !LINKED || NEWTON_PAIR || j < nlocal ? 1.0 : 0.5;
      if (!PairSpline<Law>::template pair_eval<TAIL, MODE>(c, rsq_law, LINKED ? &touch[i][jj] : nullptr, linking, w,
                                      links, e, fpair))
        continue;
      if (rsq_law <= c.hardsq) this->singular_error(i, j, rsq);
      fpair *= factor_lj * scale;
      fxtmp += delx * fpair;
      fytmp += dely * fpair;
      fztmp += delz * fpair;
      if (NEWTON_PAIR || j < nlocal) {
        f[j].x -= delx * fpair;
        f[j].y -= dely * fpair;
        f[j].z -= delz * fpair;
      }
      if (EFLAG) evdwl = factor_lj * e;
      if (EVFLAG)
        ev_tally_thr(this, i, j, nlocal, NEWTON_PAIR, evdwl, 0.0, fpair, delx, dely, delz, thr);
    }
    f[i].x += fxtmp;
    f[i].y += fytmp;
    f[i].z += fztmp;
  }
}

template <class Law> double PairSplineOMP<Law>::memory_usage()
{
  return memory_usage_thr() + PairSpline<Law>::memory_usage();
}

namespace LAMMPS_NS {
namespace ClusterDyn {
  template class PairSplineOMP<MorseLaw>;
  template class PairSplineOMP<LJLaw>;
  template class PairSplineOMP<MieLaw>;
  template class PairSplineOMP<HarmonicLaw>;
}    // namespace ClusterDyn
}    // namespace LAMMPS_NS
