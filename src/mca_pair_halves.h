/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the half stiffnesses a_i and a_j of
   a pair of pair_style mca's elements (mca_element_stiffness.h) with the
   reciprocal of their sum, taken once per pair in a pass (twice in the
   plastic pass): the pair's stiffness in series, a = a_i a_j / (a_i + a_j),
   and the shares of i and j in what the pair shares as its elongation,
   a_j / (a_i + a_j) and a_i / (a_i + a_j) (the many-body term's strain and
   volume changes, the plastic heat, a link's many-body stress).  One
   division per pair, where each of these took its own (doc/benchmarks/bench_mca.md, "One division
   per pair's halves").  Stateless, as spline_laws.h.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_PAIR_HALVES_H
#define LMP_CLUSTERDYN_MCA_PAIR_HALVES_H

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaPairHalves {
    double ai, aj;      // the half stiffnesses of i and j
    double inverse;     // 1 / (a_i + a_j)

    McaPairHalves(double ai, double aj) : ai(ai), aj(aj), inverse(1.0 / (ai + aj)) {}

    double series() const { return ai * aj * inverse; }
    double share_i() const { return aj * inverse; }
    double share_j() const { return ai * inverse; }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
