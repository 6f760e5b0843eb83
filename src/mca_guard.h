/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: what pair_style mca checks about its
   elements, and the element sizes its cutoffs are made from (the box: the
   pair state, periodic_images.h).
     check_style():   what the style needs of LAMMPS's settings
     check_shock():   what the shock equation of state needs (3d, the many-body
                      term, dynamics)
     init():          every element has a positive radius; the largest radius
                      per type (elements present, fix pour, fix deposit)
     state_reach():   per type, how far apart two elements can link or touch
     each_step():     no element grown beyond those radii (fix adapt)
     at_setup():      the time step against the time a longitudinal wave takes
                      to cross the smallest element (a warning)
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_GUARD_H
#define LMP_CLUSTERDYN_MCA_GUARD_H

#include "mca_material.h"
#include "mca_settings.h"
#include "pointers.h"

#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaGuard : protected Pointers {
   public:
    McaGuard(LAMMPS *lmp) : Pointers(lmp) {}
    // init_style(): the atom style, dimension, communication and integrator the style needs;
    // pair_modify tail and shift do not apply
    void check_style(int tail_flag, int offset_flag, int plane) const;
    // init_style(), given the materials as given: a shock equation of state is 3d, needs the
    // many-body term (manybody) and cannot be minimized
    void check_shock(const std::vector<McaMaterial> &given, bool manybody) const;
    void init();
    double largest_radius(int type) const { return rmax[type]; }
    // per type, (1 + T) R_max: elements link (at a setup) within (1 + T)(R_i + R_j) and touch
    // within R_i + R_j or where a broken link left them, R no larger than the largest of the
    // type at init; the pairs farther apart keep no state until the next list build
    std::vector<double> state_reach(double tolerance) const;
    void each_step() const;
    // materials in energy/volume; element volume = sphere volume / fraction
    void at_setup(const std::vector<McaMaterial> &scaled, double fraction) const;

   private:
    std::vector<double> rmax;    // per atom type
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
