/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the stiffnesses of the elements of
   pair_style mca at this step, per element (owned and ghost):
     a_i = 2 G_i / R_i                  the half stiffness of its links
     b_i = 2 H (K + 4G/3) / R_i + 4 H |p| / R_i
                                        its half of a pair's hourglass
                                        spring (a shock law's element, p
                                        the pair's mean pressure)
   Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_ELEMENT_STIFFNESS_H
#define LMP_CLUSTERDYN_MCA_ELEMENT_STIFFNESS_H

#include "mca_material.h"
#include "mca_pair_halves.h"
#include "pointers.h"

#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaElementStiffness : protected Pointers {
   public:
    explicit McaElementStiffness(LAMMPS *lmp) : Pointers(lmp), a(nullptr), b(nullptr), nmax(0) {}
    ~McaElementStiffness() override;
    void grow(int nmax_atoms);
    double memory_usage() const;

    // this step's a_i of every element, and b_i's parts where springs are wanted (a shock law)
    void compute(const std::vector<McaMaterial> &scaled, bool springs);

    double half(int i) const { return a[i]; }
    // the halves of pair ij, with the reciprocal of their sum
    McaPairHalves pair(int i, int j) const { return McaPairHalves(a[i], a[j]); }
    const double *halves() const { return a; }
    // b_i under the pair's mean pressure |p| = squeeze
    double spring(int i, double squeeze) const { return b[i][0] + b[i][1] * squeeze; }

   private:
    double *a, **b;
    int nmax;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
