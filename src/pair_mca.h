/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair_style mca, movable cellular
   automata (Psakhie et al.): elements with the bulk and shear moduli of
   their material, linked pairs (tension, compression, shear, torques) and
   unlinked pairs (compression only), and the many-body volumetric term
   that makes an element respond as a piece of isotropic continuum.
   Formulas, units and limits: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(mca,PairMCA);
// clang-format on
#else

#ifndef LMP_CLUSTERDYN_PAIR_MCA_H
#define LMP_CLUSTERDYN_PAIR_MCA_H

#include "atom.h"
#include "atoms_fingerprint.h"
#include "mca_contact.h"
#include "mca_guard.h"
#include "mca_material.h"
#include "mca_plasticity.h"
#include "mca_settings.h"
#include "pair.h"
#include "pair_state.h"
#include "update.h"

#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class PairMCA : public Pair {
   public:
    PairMCA(LAMMPS *);
    ~PairMCA() override;
    void compute(int, int) override;
    void settings(int, char **) override;
    void coeff(int, char **) override;
    void init_style() override;
    double init_one(int, int) override;
    void write_restart(FILE *) override;
    void read_restart(FILE *) override;
    void write_restart_settings(FILE *) override;
    void read_restart_settings(FILE *) override;
    void write_data(FILE *) override;
    void write_data_all(FILE *) override;
    void transfer_history(double *, double *, int, int) override;
    void *extract(const char *, int &) override;
    int pack_forward_comm(int, int *, double *, int, int *) override;
    void unpack_forward_comm(int, int, double *) override;
    int pack_reverse_comm(int, int, double *) override;
    void unpack_reverse_comm(int, int *, double *) override;
    double memory_usage() override;

    // per element, for compute mca/atom: the stress tensor (Love's formula, tension positive:
    // xx yy zz xy xz yz) and the count of linked pairs, from the last force evaluation
    enum { STRESS_COLUMNS = 7 };
    void request_element_stress() { stress_wanted = 1; }
    // the element stresses of my atoms, or null unless they belong to the current atoms (this
    // step, and the same atoms in the same slots)
    double **element_stress() const
    {
      return stress_step == update->ntimestep && stress_atoms == atoms_fingerprint(atom) ? stress
                                                                                      : nullptr;
    }
    double element_volume(int i) const;
    // the equivalent plastic strain of my elements, or null (no material yields)
    const double *plastic_strain() const { return plasticity.plastic_strain(); }

    // pvector: broken links, links formed, the energy of those changes, then the energy
    // dissipated by damage, by plastic flow and by friction (all since the links were made)
    enum { TALLY_DAMAGE = 0, TALLY_PLASTIC = 1, TALLY_FRICTION = 2, NWORK = 3 };

   private:
    McaSettings setting;
    std::vector<McaMaterial> material;    // per atom type, as given (pressure units)
    std::vector<McaMaterial> scaled;      // the same in energy/volume
    std::vector<int> material_set;
    std::vector<int> unlinkable;          // per type pair (i * (ntypes + 1) + j): never link
    McaGuard guard;                       // checks; the largest radius per type
    McaPlasticity plasticity;
    PairState state;
    int responds;                         // a material breaks, damages, yields or welds
    // per atom, the sum of one pass over the pairs: at a setup the linked pairs (make_links),
    // then the volumetric strain theta (volumetric_strain, used by the forces)
    double *sums;
    double **stress;
    // per atom: the plastic factor phi and mean stress (plasticity); the changes of the
    // volumetric strain made by this step's changes of state, damage and plastic flow
    double **returned, **dtheta;
    int nmax, stress_wanted;
    bigint stress_step;
    std::uint64_t stress_atoms;    // atoms_fingerprint() when the stresses were made
    enum CommWhat { COMM_SUMS, COMM_STRESS, COMM_RETURNED, COMM_DTHETA } comm_what;

    void allocate();
    void scale_materials();
    void grow(int nall);
    bool linkable(int itype, int jtype) const;
    void make_links(const StatePass &);
    void volumetric_strain(const StatePass &);
    void plastic_trial(const StatePass &);
    double linked_trial(int i, int j, double *v, const double *d, const double *n, double r,
                        const ClusterDyn::McaContact::Turn *turn) const;
    void pair_forces(const StatePass &, StateTally &);
    void contact(int i, int j, int &word, double *v, const double *d, const double *n,
                 double r, const ClusterDyn::McaContact::Turn *turn, int trial, double w,
                 StateTally &changes, double *fi, double *ft, double &evdwl);
    void manybody_changes(StateTally &changes);
    void manybody_energy();
    void stress_to_owners(bool to_pressure);
    [[noreturn]] void coincident(int i, int j) const;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
#endif
