/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair_style mca, movable cellular
   automata (Psakhie et al.): elements with the bulk and shear moduli of
   their material, linked pairs (tension, compression, shear, torques) and
   unlinked pairs (compression only), and the many-body volumetric term
   that makes an element respond as a piece of isotropic continuum.
   The style is a shell around its models, as GRANULAR's pair styles are
   around granular_model: the per-type input and per-type-pair models
   (mca_type_table.h, mca_pair_model.h), the linked pair's law
   (mca_linked_pair.h), the unlinked contact (mca_unlinked_pair.h), the
   many-body term (mca_manybody.h), plasticity (mca_plasticity.h), the
   element stresses (mca_element_stress.h), stiffnesses
   (mca_element_stiffness.h) and pressure (mca_element_eos.h,
   mca_pressure_pair.h) and the persistent pair state (pair_state.h); it
   keeps the LAMMPS interface and the passes over the neighbour list
   (mca_pair_walk.h).  Formulas, units and limits:
   doc/pair_mca.rst; the layout: doc/Developer.rst.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(mca,PairMCA);
// clang-format on
#else

#ifndef LMP_CLUSTERDYN_PAIR_MCA_H
#define LMP_CLUSTERDYN_PAIR_MCA_H

#include "mca_element_eos.h"
#include "mca_element_stiffness.h"
#include "mca_element_stress.h"
#include "mca_guard.h"
#include "mca_linked_pair.h"
#include "mca_linking.h"
#include "mca_manybody.h"
#include "mca_material_report.h"
#include "mca_pair_tally.h"
#include "mca_pair_walk.h"
#include "mca_plasticity.h"
#include "mca_segment_contact.h"
#include "mca_settings.h"
#include "mca_type_table.h"
#include "pair_column_exchange.h"
#include "pair_state.h"

#include "atom.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  class PairMCA : public PairColumnExchange {
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
    void write_data(FILE *fp) override;
    void write_data_all(FILE *fp) override;
    void init_list(int id, NeighList *ptr) override;
    void transfer_history(double *, double *, int, int) override;
    void *extract(const char *, int &) override;
    double memory_usage() override;

    // for compute mca/atom: the element stresses (McaElementStress), asked for at its init
    void request_element_stress() { stress.request(); }
    double **element_stress() const { return stress.current(); }
    double packing_fraction() const { return setting.fraction; }
    // the damage D of owned element i by its spall kinetics (0: none)
    double element_damage(int i) const
    {
      return eos.kinetic(atom->type[i]) ? eos.damage(i) : 0.0;
    }
    // 2d: an element's sigma_zz from its in-plane stresses (plane strain: nu (sxx + syy) -
    // E eps_p,zz, no strain along z; plane stress: 0)
    double out_of_plane_stress(int i, double sxx, double syy) const
    {
      if (setting.plane != McaSettings::STRAIN) return 0.0;
      return plasticity.out_of_plane(i, types.as_given()[atom->type[i]], sxx, syy);
    }

   private:
    McaSettings setting;
    McaTypeTable types;                   // materials, link flags, per-type-pair models
    McaGuard guard;                       // checks; the largest radius per type
    McaPlasticity plasticity;
    McaManybody manybody;
    McaElementStress stress;
    McaElementEos eos;                    // the pressure of elements with a shock law
    McaElementStiffness stiffness;        // a_i, and the hourglass springs' b_i
    PairState state;
    bool tracks_changes;                  // the many-body term follows breaking, damage, flow
    McaLinking linking;
    McaSegmentContact segments;           // two bodies' contact by the method of segments (2d)
    McaMaterialReport report;             // the materials' derived numbers in the log
    NeighList *full;                      // its full list (id 1)

    void allocate();
    void grow();
    void volumetric_strain(const StatePass &);
    void plastic_trial(const StatePass &);
    void pair_forces(const StatePass &, StateTally &);
    // a linked pair's trial stresses: the tangential one slid (stored), the normal one returned
    double trial_stresses(int i, int j, double *v, const McaPairFrame &p,
                          const McaContact::Turn *turn, const McaPairHalves &halves)
    {
      McaLinkedPair::slide(v, halves.series(), p, turn);
      return normal_trial(i, j, v, p.r, halves);
    }
    // the effective normal stress before any return, with its many-body part (inline: as a
    // call per link it cost 4 % of the step)
    double normal_trial(int i, int j, const double *v, double r, const McaPairHalves &halves) const
    {
      return McaLinkedPair::elastic_stress(v, halves.series(), r) +
          (setting.manybody ? manybody.pair_stress(i, j, halves) : 0.0);
    }
    bool elements_turn() const;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
#endif
