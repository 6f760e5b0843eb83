/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: what pair_style mca prints of each
   material at the start of a run, the way LAMMPS prints its own derived
   quantities: the moduli K, G, E, nu, the wave speeds c_L, c_S and the bulk
   speed c0 = sqrt(K/rho), the Hugoniot elastic limit of a yield stress, and
   the density in the unit style's units and in the unit a person reads
   (g/cm^3, kg/m^3), so that a value typed in the wrong unit shows itself.
   The density is rho0 for a shock law, else the elements' mass over their
   volume.  Printed again only when it changes.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_MATERIAL_REPORT_H
#define LMP_CLUSTERDYN_MCA_MATERIAL_REPORT_H

#include "mca_type_table.h"
#include "pointers.h"

#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaMaterialReport : protected Pointers {
   public:
    McaMaterialReport(LAMMPS *lmp) : Pointers(lmp) {}
    // the materials as given (pressure units), element volume = sphere volume / fraction
    void print(const McaTypeTable &types, double fraction);

   private:
    std::vector<double> densities(const McaTypeTable &types, double fraction) const;
    std::string last;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
