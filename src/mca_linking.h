/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the links pair_style mca makes at a
   setup.  The pairs of fresh elements closer than (1 + tolerance)(R_i + R_j)
   are linked (unless their types never link), stress free at their present
   distance; their contact area is S_ij = (S_i + S_j)/2 with
   S_i = 3 Omega_i / (Z_i R_i), Z_i the linked pairs of element i, so that
   sum_j q_ij S_ij n n = Omega_i I on a regular packing (Love's formula gives
   the element's stress).  Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_LINKING_H
#define LMP_CLUSTERDYN_MCA_LINKING_H

#include "mca_exchange.h"
#include "mca_type_table.h"
#include "pair_state.h"
#include "pointers.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaLinking : protected Pointers {
   public:
    McaLinking(LAMMPS *lmp, McaExchange &exchange) :
        Pointers(lmp), exchange(exchange), zcount(nullptr), nmax(0)
    {
    }
    ~McaLinking() override;
    // the pairs of the fresh elements of this pass (pass.fresh), with their areas
    void make(const NeighList *list, const StatePass &pass, const McaTypeTable &types,
              double tolerance, double fraction);

   private:
    McaExchange &exchange;
    double **zcount;    // per element, its linked pairs
    int nmax;
    void areas(const NeighList *list, const StatePass &pass, double fraction);
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
