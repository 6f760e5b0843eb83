/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the variable-size collectives of
   compute dust and fix PAIR_STATE.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MPI_COLLECTIVES_H
#define LMP_CLUSTERDYN_MPI_COLLECTIVES_H

#include <mpi.h>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  // every processor's entries, concatenated in rank order, on every processor
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

  // each processor's boxes[p] delivered to processor p; returns what I received, concatenated in
  // rank order, and sets recvcounts (how much came from each processor)
  inline std::vector<double> alltoallv(const std::vector<std::vector<double>> &boxes,
                                       std::vector<int> &recvcounts, MPI_Comm world)
  {
    const int nprocs = boxes.size();
    recvcounts.assign(nprocs, 0);
    std::vector<int> sendcounts(nprocs), sdispls(nprocs), rdispls(nprocs);
    std::vector<double> sendbuf;
    for (int p = 0; p < nprocs; p++) {
      sdispls[p] = sendbuf.size();
      sendcounts[p] = boxes[p].size();
      sendbuf.insert(sendbuf.end(), boxes[p].begin(), boxes[p].end());
    }
    MPI_Alltoall(sendcounts.data(), 1, MPI_INT, recvcounts.data(), 1, MPI_INT, world);
    int total = 0;
    for (int p = 0; p < nprocs; p++) {
      rdispls[p] = total;
      total += recvcounts[p];
    }
    std::vector<double> recvbuf(total);
    MPI_Alltoallv(sendbuf.data(), sendcounts.data(), sdispls.data(), MPI_DOUBLE, recvbuf.data(),
                  recvcounts.data(), rdispls.data(), MPI_DOUBLE, world);
    return recvbuf;
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
