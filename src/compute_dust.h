/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute dust, the fragments of the
   bond graph and the dust (detached fragments) (doc/compute_dust.rst).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_COMPUTE_DUST_H
#define LMP_CLUSTERDYN_COMPUTE_DUST_H

#include "compute.h"
#include "dust_settings.h"
#include "fragment_sums.h"
#include "union_find.h"

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

   private:
    DustSettings opt;          // the compute's arguments
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
    // the stages of one evaluation (compute_dust.cpp)
    void join_bonded_atoms();
    std::vector<tagint> label_local_sets();
    LabelUnion join_across_processors(const std::vector<tagint> &setmin);
    void sum_fragments(const LabelUnion &fragment, FragmentSums &sums);
    void write_vector(const FragmentSums &sums);
    void write_rows(const FragmentSums &sums);
    void write_atoms(const FragmentSums &sums);
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
