/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: what pair_style mca checks about its
   elements, and the element sizes its cutoffs are made from (the box: the
   pair state, periodic_images.h).
     check_style():   what the style needs of LAMMPS's settings
     init():          every element has a positive radius; the largest radius
                      per type (elements present, fix pour, fix deposit)
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
    void init();
    double largest_radius(int type) const { return rmax[type]; }
    void each_step() const;
    // materials in energy/volume; element volume = sphere volume / fraction
    void at_setup(const std::vector<McaMaterial> &scaled, double fraction) const;

   private:
    std::vector<double> rmax;    // per atom type
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
