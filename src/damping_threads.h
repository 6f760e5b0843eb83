/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative's damping in
   the /omp spline pair styles' force pass (damping_pass.h).  Thread 0 adds
   into the fix's fd; threads 1..n-1 add into blocks of their own, zeroed
   before their pairs and summed into fd after a barrier, each thread
   summing a slice of the atoms (as OPENMP's data_reduce_thr sums forces).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_DAMPING_THREADS_H
#define LMP_CLUSTERDYN_DAMPING_THREADS_H

#include "damping_pass.h"
#include "xyz3.h"

#include <cstring>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class DampingThreads {
   public:
    // before the parallel region: room for nthreads - 1 blocks of nall atoms
    void reserve(int nthreads, int nall)
    {
      nall_ = nall;
      const size_t need = (size_t) (nthreads > 1 ? nthreads - 1 : 0) * nall;
      if (blocks_.size() < need) blocks_.resize(need);
    }

    // thread tid's pass: the fix's fd for thread 0, else its own block, zeroed
    DampingPass pass_of(const DampingPass &pass, int tid)
    {
      DampingPass mine = pass;
      if (tid > 0) {
        mine.fd = blocks_.data() + (size_t) (tid - 1) * nall_;
        memset((void *) mine.fd, 0, sizeof(xyz3) * nall_);
      }
      return mine;
    }

    // after every thread's pairs (a barrier): thread tid sums its slice of the atoms into fd
    void reduce(xyz3 *fd, int tid, int nthreads) const
    {
      const int from = (int) ((long) nall_ * tid / nthreads);
      const int to = (int) ((long) nall_ * (tid + 1) / nthreads);
      for (int t = 1; t < nthreads; t++) {
        const xyz3 *block = blocks_.data() + (size_t) (t - 1) * nall_;
        for (int i = from; i < to; i++) {
          fd[i].x += block[i].x;
          fd[i].y += block[i].y;
          fd[i].z += block[i].z;
        }
      }
    }

    double memory_usage() const { return (double) blocks_.capacity() * sizeof(xyz3); }

   private:
    std::vector<xyz3> blocks_;
    int nall_ = 0;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
