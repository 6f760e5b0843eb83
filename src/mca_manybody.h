/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the many-body (volumetric) part of
   pair_style mca, per element i:
     theta_i = (1/Omega_i) sum_j (1 - D_ij) S_ij w_i (r_ij - r_ref - e_p)
   the volume change from the elastic elongations of its linked pairs (its
   share w_i = a_j / (a_i + a_j) of each), summed onto owners and sent to
   ghosts; a linked pair's normal stress gains
     (a_j lambda_i theta_i + a_i lambda_j theta_j) / (a_i + a_j),
   the element's energy is lambda_i Omega_i theta_i^2 / 2; the changes of
   theta made by this step's breaking and welding (column 0), damage (1)
   and plastic flow (2) release the energy between theta before and after
   each, in that order.  The pair stress of this step is the theta before
   the plastic flow: the step's forces lag it by one step, and the plastic
   work takes the trapezoid rule's share of that lag over the step's motion
   (column 3, the elongation of the links over the step), -lambda Omega
   dtheta_p dtheta_motion / 2, so that the budget closes to second order.
   The seam for a volumetric response beyond the linear one (an equation of
   state): pair_stress(), tally_energy() and the release in tally_changes().
   Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_MANYBODY_H
#define LMP_CLUSTERDYN_MCA_MANYBODY_H

#include "mca_exchange.h"
#include "mca_material.h"
#include "mca_pair_changes.h"
#include "atom.h"
#include "pair_state.h"
#include "pointers.h"

#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaManybody final : protected Pointers, public McaVolumeChanges {
   public:

    McaManybody(LAMMPS *lmp, McaExchange &exchange) :
        Pointers(lmp), exchange(exchange), theta(nullptr), dtheta(nullptr), extra(nullptr), nmax(0),
        fraction(1.0), scaled(nullptr)
    {
    }
    ~McaManybody() override;
    // materials in energy/volume; element volume = sphere volume / fraction
    void init(const std::vector<McaMaterial> &materials, double packing_fraction)
    {
      scaled = &materials;
      fraction = packing_fraction;
    }
    void grow(int nmax_atoms);
    double memory_usage() const;

    // the volumetric strain: zero, the pairs' elongations (share by stiffness), then finish
    void begin_strain(int nall);
    void add_elongation(int i, int j, double elong, const McaPairHalves &halves, bool jown)
    {
      McaElementShares{theta}.add(0, i, j, elong, halves, jown);
    }
    void finish_strain();
    // a modulus added to element i's lambda from here to the next begin_strain() (owners and
    // ghosts alike): the bulk modulus of a shock-law element whose links span no volume
    void add_modulus(int i, double k) { extra[i] = k; }

    // the normal stress the many-body term adds to linked pair ij (its elements' halves)
    double pair_stress(int i, int j, const McaPairHalves &halves) const
    {
      const std::vector<McaMaterial> &m = *scaled;
      const int *type = atom->type;
      return (halves.aj * (m[type[i]].lambda + extra[i]) * theta[i][0] +
              halves.ai * (m[type[j]].lambda + extra[j]) * theta[j][0]) *
          halves.inverse;
    }

    // the changes of theta this step makes (volume changes dv of pairs, shared as elongations)
    void begin_changes(int nall);
    McaElementShares volume_changes() const { return {dtheta}; }
    // the energies they release: state changes to the jump, damage and plastic flow to work
    // (and the plastic flow's into the element's heat, where it has a shock law: heat)
    void tally_changes(StateTally &changes, int damage_work, int plastic_work,
                       McaElementShares heat);

    // the elements' energies lambda Omega theta^2 / 2 added to the total and per atom (each
    // null: not wanted)
    void tally_energy(double *total, double *per_atom) const;

   private:
    McaExchange &exchange;
    double **theta, **dtheta;
    double *extra;    // add_modulus()
    int nmax;
    double fraction;
    const std::vector<McaMaterial> *scaled;
    double volume(int i) const;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
