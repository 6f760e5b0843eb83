/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative's damping
   forces per atom, own and ghost (fd).  Zeroed before each pass; the
   ghosts' parts go to their owners by the fix's reverse communication
   (its pack_reverse_comm and unpack_reverse_comm call pack() and
   unpack()); then fd is added into the forces, with the power sum fd . v
   of my atoms that the fix's energy tally needs.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_DAMPING_FORCES_H
#define LMP_CLUSTERDYN_DAMPING_FORCES_H

#include "xyz3.h"

#include "pointers.h"

namespace LAMMPS_NS {
class Fix;
namespace ClusterDyn {

  class DampingForces : protected Pointers {
   public:
    explicit DampingForces(LAMMPS *lmp) : Pointers(lmp) {}
    ~DampingForces();
    DampingForces(const DampingForces &) = delete;
    DampingForces &operator=(const DampingForces &) = delete;

    void clear();    // room for my atoms and ghosts, zeroed
    xyz3 *data() const { return (xyz3 *) fd[0]; }
    void sum_to_owners(Fix *fix);      // the ghosts' parts, under newton_pair
    double add_to_forces(Fix *fix);    // sum_to_owners, fd into f; the power sum
    double power() const;                    // sum over my atoms of fd . v
    int pack(int n, int first, double *buf) const;
    void unpack(int n, const int *list, const double *buf);
    double memory_usage() const;

   private:
    double **fd = nullptr;
    int maxfd = 0;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
