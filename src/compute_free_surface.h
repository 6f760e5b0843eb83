/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute free/surface, the velocity
   of a body's free face (what a VISAR records): the mean velocity along an
   axis of the group's atoms within a depth of its outermost atom that a
   compute dust does not flag as dust, and a count of the face's jumps
   (doc/compute_free_surface.rst).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_COMPUTE_FREE_SURFACE_H
#define LMP_CLUSTERDYN_COMPUTE_FREE_SURFACE_H

#include "compute.h"
#include "lmptype.h"

#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class ComputeFreeSurface : public Compute {
   public:
    ComputeFreeSurface(class LAMMPS *, int, char **);
    ~ComputeFreeSurface() override;
    void init() override;
    void compute_vector() override;

   private:
    void count_jump(bool found, double face, double velocity);

    std::string dust_id;
    Compute *dust = nullptr;
    double depth;
    int axis = 0;       // x, y, z
    int sign = 1;       // +1: the face at the largest coordinate (rear), -1: the smallest
    double minsize = 0;    // > 0: the pieces of at least minsize atoms are the body
    double jumps = 0.0;    // evaluations at which the face jumped (count_jump)
    struct Evaluation {
      bigint step = -1;
      bool found = false;
      double face = 0.0, velocity = 0.0, time = 0.0;    // face: sign x of the outermost atom
    } last;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
