/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute dust, the fragments of the
   bond graph and the dust (detached fragments) (doc/compute_dust.rst).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_COMPUTE_DUST_H
#define LMP_CLUSTERDYN_COMPUTE_DUST_H

#include "compute.h"
#include "union_find.h"

#include <array>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class ComputeDust : public Compute {
   public:
    ComputeDust(class LAMMPS *, int, char **);
    ~ComputeDust() override;
    void init() override;
    void init_list(int, class NeighList *) override;
    void compute_vector() override;
    void compute_peratom() override;
    void compute_local() override;
    int pack_forward_comm(int, int *, double *, int, int *) override;
    void unpack_forward_comm(int, int, double *) override;
    double memory_usage() override;

    static constexpr int NSUMS = 8;    // per fragment: size, mass, m x (3), m v (3)
    using Sums = std::array<double, NSUMS>;

   private:
    double cutoff_user;        // 0: the pair style's cutoff of each type pair
    bigint maxsize;            // 0: every fragment but the largest is dust
    int links;                 // bonds = the pair style's links (link L), not distances
    int dust_rows;             // local rows of the dust only (rows dust), not every fragment
    class PairState *state;    // the pair style's link state (links)
    std::vector<double> cutsq; // (ntypes+1)^2 bond distance squared
    class NeighList *list;
    int nmax;
    double **fragments;        // per atom: fragment ID, size, dust flag
    int nrows, maxrows;
    double **rows;             // local: the fragments I own, one row each
    UnionFind sets;            // over my atoms and ghosts
    std::vector<double> label; // per atom (and ghost): local fragment label
    bigint evaluated;          // step of the last evaluation

    void bond_distances();
    void evaluate();
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
