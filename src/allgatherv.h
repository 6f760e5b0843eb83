/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: every processor's entries,
   concatenated in rank order, on every processor (compute dust, fix
   PAIR_STATE).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_ALLGATHERV_H
#define LMP_CLUSTERDYN_ALLGATHERV_H

#include <mpi.h>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  template <class T>
  std::vector<T> allgatherv(const std::vector<T> &mine, MPI_Datatype type, MPI_Comm world)
  {
    int nprocs, n = mine.size();
    MPI_Comm_size(world, &nprocs);
    std::vector<int> counts(nprocs), displs(nprocs);
    MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
    int total = 0;
    for (int p = 0; p < nprocs; p++) {
      displs[p] = total;
      total += counts[p];
    }
    std::vector<T> all(total);
    MPI_Allgatherv(mine.data(), n, type, all.data(), counts.data(), displs.data(), type, world);
    return all;
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
