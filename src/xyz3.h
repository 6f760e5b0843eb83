/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: a view of LAMMPS's x, v and f
   arrays as packed triplets (as the OPT and OPENMP packages read them).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_XYZ3_H
#define LMP_CLUSTERDYN_XYZ3_H

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct xyz3 {
    double x, y, z;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
