/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the model of one pair of element
   types of movable cellular automata (stateless, as spline_laws.h), made
   once per type pair when pair_style mca initializes (init_one), as
   GRANULAR's granular_model is made per type pair from its sub-models:
   the response of a linked pair beyond elasticity (mca_response.h), the
   friction and welding of an unlinked contact (mca_friction.h), and
   whether the two types link.  Both orders of a pair give the same model.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_PAIR_MODEL_H
#define LMP_CLUSTERDYN_MCA_PAIR_MODEL_H

#include "mca_friction.h"
#include "mca_material.h"
#include "mca_response.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaPairModel {
    McaResponse response;    // strength and damage of a linked pair
    McaFriction friction;    // dry and viscous friction, welding, of an unlinked contact
    bool links = true;       // elements of these types link (at a setup, or welded)

    // the materials in energy/volume (McaMaterial::scaled)
    static McaPairModel of_types(const McaMaterial &mi, const McaMaterial &mj, bool links)
    {
      McaPairModel m;
      m.response = McaResponse::of_pair(mi.strength, mi.damage, mj.strength, mj.damage);
      m.friction =
          McaFriction::of_pair(mi.friction, mi.viscous, mi.weld, mj.friction, mj.viscous, mj.weld);
      m.links = links;
      return m;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
