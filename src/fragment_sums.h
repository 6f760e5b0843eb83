/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute dust's sums per fragment
   (size, mass, mass-weighted unwrapped position and velocity).  My atoms'
   sums go to each fragment's owner (its ID modulo the number of
   processors) in one MPI_Alltoallv; the body, the largest fragment (the
   smallest ID among equals), from two MPI_Allreduce; one MPI_Alltoallv
   back gives each processor the size and dust flag of the fragments it
   sent.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_FRAGMENT_SUMS_H
#define LMP_CLUSTERDYN_FRAGMENT_SUMS_H

#include "lmptype.h"

#include <mpi.h>

#include <array>
#include <map>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class FragmentSums {
   public:
    static constexpr int NSUMS = 8;    // size, mass, m x (3), m v (3)
    enum { SIZE = 0, MASS = 1, MX = 2, MV = 5 };
    using Sums = std::array<double, NSUMS>;
    struct Answer {
      double size, dust;    // the fragment's size, dust flag 1 or 0
    };

    // maxsize 0: every fragment but the body is dust; else those of at most maxsize atoms
    FragmentSums(MPI_Comm world, bigint maxsize) : world(world), maxsize(maxsize) {}

    void add(tagint id, double m, const double *xu, const double *v);    // one of my atoms
    void combine();    // each fragment's sums on its owner; the body
    const std::map<tagint, Sums> &owned() const { return owned_; }    // mine, by ID
    double body_size() const { return body_size_; }
    bool is_dust(tagint id, double size) const
    {
      return maxsize > 0 ? size <= (double) maxsize : id != body_id;
    }
    // the owners' answers for the fragments of my atoms, by ID (a collective)
    std::unordered_map<tagint, Answer> answers() const;

   private:
    MPI_Comm world;
    bigint maxsize;
    std::unordered_map<tagint, Sums> mine;      // fragment ID -> sums over my atoms
    std::vector<std::vector<double>> outbox;    // (ID, sums) per owner
    std::vector<int> incounts;                  // the sizes of inbox's parts, per sender
    std::vector<double> inbox;                  // (ID, sums) of the fragments I own, by sender
    std::map<tagint, Sums> owned_;
    tagint body_id = 0;
    double body_size_ = 0.0;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
