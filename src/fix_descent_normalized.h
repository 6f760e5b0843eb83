/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix descent/normalized, Chernyshev's
   quasi-static iteration (doc/fix_descent_normalized.rst).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_FIX_DESCENT_NORMALIZED_H
#define LMP_CLUSTERDYN_FIX_DESCENT_NORMALIZED_H

#include "fix.h"

#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class FixDescentNormalized : public Fix {
   public:
    FixDescentNormalized(class LAMMPS *, int, char **);
    ~FixDescentNormalized() override;
    int setmask() override;
    void init() override;
    void setup(int) override;
    void initial_integrate(int) override;
    double compute_scalar() override;
    double compute_vector(int) override;
    void write_restart(FILE *) override;
    void restart(char *) override;

    // per-atom displacement history (inertia M K only)
    void grow_arrays(int) override;
    void copy_arrays(int, int, int) override;
    int pack_exchange(int, double *) override;
    int unpack_exchange(int, double *) override;
    int pack_restart(int, double *) override;
    void unpack_restart(int, int) override;
    int size_restart(int) override;
    int maxsize_restart() override;
    double memory_usage() override;

   private:
    int pack_history(int, double *);
    int unpack_history(int, const double *, int);
    void clear_history(int);

    double step;          // h of the next iteration (distance units)
    double decay;         // F: h <- max(F h, hmin) after each iteration
    double hmin;          // Hmin
    int nmemory;          // M (0: no inertia)
    double kinertia;      // K
    int nfilled;          // displacements held per atom so far (<= M)
    int slot;             // ring position of the oldest displacement (the next overwritten)
    int nper;             // values per atom: 3 M ring + 3 running sum
    static constexpr int MAX_MEMORY = 1000;    // inertia M
    std::vector<double **> rings;   // rings[m][i]: atom i's displacement in ring slot m
    double **sum;         // per atom: the sum of its ring (each array contiguous over atoms)
    double dmax_local;    // largest displacement of my atoms in the last iteration
    bigint stats_step;    // timestep of the cached force statistics (-1: stale)
    double stats[3];      // max |F_i|, mean |F_i|, largest displacement

    void check_integrators();
    void compute_stats();
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
