/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the pressure of the elements of
   pair_style mca whose material has a shock equation of state
   (mca_shock_eos.h), per element i:
     K_i = sum_j w_ij x_ij x_ij^T,  w_ij = (1 - D_ij) S_ij / r_ref,ij
     H_i = sum_j w_ij dx_ij x_ij^T K_i^-1   (its displacement gradient over
                                             the step, L_i dt)
   over its linked pairs (x_ij = x_j - x_i, dx_ij its change since the last
   step: positions, whatever moved them), summed onto owners; a dynamics
   step advances its volume ratio J_i by exp((tr H_i + tr H_i') / 2) (H_i'
   with the last step's separations) and its internal energy u_i (per
   reference volume) by the work of the pressure and bulk viscosity,
   (P'_i : M'_i + P_i : M_i) / 2 (M = sum w dx x^T), what velocity Verlet's
   forces of the two steps spend; it sends P_i = (p_i + q_i) Omega_i J_i K_i^-1 to its ghosts,
   with the symmetric part of H_i and -p_i, and a linked pair pushes its elements
   apart with
     f_j = -f_i = (P_i + P_j) x_ij w_ij
   whose power is -(p_i + q_i) dV_i/dt summed: the work of the pressure is
   the change of the internal energy, and the force of a homogeneous
   pressure is -p I in Love's formula on any packing.  A pair's response
   (damage, breaking) reads its elements' mean stress -p (the viscosity q
   is numerical), not its share of their force, which grows where an
   element has fewer links.  An element whose
   links span no volume (the smallest eigenvalue of K_i below 0.1 tr K_i / 3:
   a fragment of a few links, a sheet, a chain, whose K_i^-1 would multiply
   the pressure's force) keeps J_i and u_i and pushes no pair.  An element
   of a material with spall kinetics (mca_spall_kinetics.h) damages under
   its tension -p: it transmits (1 - D_i) of it (its energy follows the
   transmitted pressure's work), and at D_i = 1 its links break.  The
   plastic work heats the elements after the forces of its step: the next
   step's old pressure leaves that heat out, as those forces did.  J - 1,
   u, q, D and that heat live in a fix property/atom (migration, restart).
   Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_ELEMENT_EOS_H
#define LMP_CLUSTERDYN_MCA_ELEMENT_EOS_H

#include "mca_exchange.h"
#include "mca_material.h"
#include "mca_pair_changes.h"
#include "mca_shock_eos.h"
#include "mca_spall_kinetics.h"

#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class FixPropertyAtom;
namespace ClusterDyn {

  class McaElementEos final : protected Pointers {
   public:
    // the columns summed onto owners (K: 6, M = sum w dx x^T: 9, N = sum w dx dx^T: 6; the
    // last step's K' = K - M - M^T + N and M' = M - N) and sent to ghosts (P: 6, the symmetric
    // part of H: 6, whether the element has a volume: 1, its mean stress -p: 1, its damage: 1)
    enum { MOVES = 15, SUMS = 21, FORWARD = 15, GRADIENT = 6, HAS_VOLUME = 12, MEAN = 13,
           DAMAGE = 14 };
    static constexpr const char *FIX_ID = "PAIR_MCA_EOS";

    McaElementEos(LAMMPS *lmp, McaExchange &exchange);
    ~McaElementEos() override;

    // the materials (scaled to energy/volume) and the packing fraction; with any shock
    // material, the per-element state is made (or found) and active() is true
    void init(const std::vector<McaMaterial> &scaled, double packing_fraction);
    bool active() const { return !laws.empty(); }
    // whether elements of this type have a shock law
    bool has_law(int type) const { return !laws.empty() && laws[type].bulk > 0.0; }
    void grow(int nmax_atoms);
    double memory_usage() const;

    // the sums over linked pairs: zero, add each pair (d = x_j - x_i now, before: at the last
    // evaluation), then finish: advance J, u and q, and send the pressures to ghosts.  STEP: a
    // dynamics step of dt (q from its rate); MOVED: the setup of a run, where positions may
    // have changed since the last evaluation (change_box, displace_atoms, set): that change
    // compresses the elements as a step would, at the viscosity they had (no rate); NONE: the
    // pressure of the state
    enum Advance { NONE, STEP, MOVED };
    void begin(int nall);
    void add_pair(int i, int j, const double *d, const double *before, double w, bool jown)
    {
      const double dv[3] = {d[0] - before[0], d[1] - before[1], d[2] - before[2]};
      const double s[SUMS] = {d[0] * d[0],   d[1] * d[1],   d[2] * d[2],   d[0] * d[1],
                              d[0] * d[2],   d[1] * d[2],   dv[0] * d[0],  dv[0] * d[1],
                              dv[0] * d[2],  dv[1] * d[0],  dv[1] * d[1],  dv[1] * d[2],
                              dv[2] * d[0],  dv[2] * d[1],  dv[2] * d[2],  dv[0] * dv[0],
                              dv[1] * dv[1], dv[2] * dv[2], dv[0] * dv[1], dv[0] * dv[2],
                              dv[1] * dv[2]};
      double ws[SUMS];    // apart from the rows, so that the two sums run as vectors
      for (int k = 0; k < SUMS; k++) ws[k] = w * s[k];
      for (int k = 0; k < SUMS; k++) sums[i][k] += ws[k];
      if (jown)
        for (int k = 0; k < SUMS; k++) sums[j][k] += ws[k];
    }
    void finish(Advance how, double dt);

    // why links left the neighbour list, where the elements' compression explains it (all
    // processors); empty: it does not
    std::string lost_links_reason() const;

    // whether element i (owned or ghost) has a shock law and links that span a volume
    bool has_volume(int i) const { return pressures[i][HAS_VOLUME] > 0.0; }

    // whether element i or j (owned or ghost, with a volume) is fully damaged by its spall
    // kinetics: the pair breaks
    bool spalled(int i, int j) const
    {
      return pressures[i][DAMAGE] >= 1.0 || pressures[j][DAMAGE] >= 1.0;
    }
    // whether elements of this type fracture by spall kinetics
    bool kinetic(int type) const { return !kinetics.empty() && kinetics[type].active(); }
    // the damage of owned element i (0: none or no kinetics)
    double damage(int i) const;

    // the mean stress of the pair's elements that have a volume (0: neither has)
    double pair_stress(int i, int j) const
    {
      const double hi = pressures[i][HAS_VOLUME], hj = pressures[j][HAS_VOLUME];
      return hi + hj > 0.0 ? (pressures[i][MEAN] + pressures[j][MEAN]) / (hi + hj) : 0.0;
    }

    // the force on i of the pair's pressure, f_i = -(P_i + P_j) d w
    void pair_force(int i, int j, const double *d, double w, double *f) const
    {
      const double *pi = pressures[i], *pj = pressures[j];
      double p[6];
      for (int k = 0; k < 6; k++) p[k] = pi[k] + pj[k];
      f[0] = -w * (p[0] * d[0] + p[3] * d[1] + p[4] * d[2]);
      f[1] = -w * (p[3] * d[0] + p[1] * d[1] + p[5] * d[2]);
      f[2] = -w * (p[4] * d[0] + p[5] * d[1] + p[2] * d[2]);
    }

    // the pair's elongation over the step that its elements' displacement gradients give,
    // r n.(H_i + H_j)/2.n (one element's where the other has no volume); false: neither has
    bool affine_elongation(int i, int j, const double *n, double r, double &rate) const
    {
      const double hi = pressures[i][HAS_VOLUME], hj = pressures[j][HAS_VOLUME];
      if (hi + hj == 0.0) return false;
      const double nn[6] = {n[0] * n[0], n[1] * n[1], n[2] * n[2],
                            2.0 * n[0] * n[1], 2.0 * n[0] * n[2], 2.0 * n[1] * n[2]};
      double sum = 0.0;
      for (int k = 0; k < 6; k++)
        sum += nn[k] * (hi * pressures[i][GRADIENT + k] + hj * pressures[j][GRADIENT + k]);
      rate = r * sum / (hi + hj);
      return true;
    }

    // the plastic work of a pair heats its elements, shared as its elongation (a_i, a_j: the
    // half stiffnesses); zero, add, then finish (summed onto owners, into u)
    void begin_heat(int nall);
    McaElementShares heat_shares() const { return {active() ? heat : nullptr}; }
    void finish_heat();

    // the elements' internal energies u Omega added to the total and per atom (null: not
    // wanted)
    void tally_energy(double *total, double *per_atom) const;

   private:
    McaExchange &exchange;
    // per element (owned and ghost): the sums over its links (begin() to finish()), then in
    // the same rows the columns sent to ghosts (finish() to the next begin())
    double **sums, **pressures, **heat;
    int nmax;
    double fraction;
    const std::vector<McaMaterial> *scaled;
    std::vector<McaShockEos> laws;    // per type; bulk 0: no shock law
    std::vector<McaSpallKinetics> kinetics;    // per type; strength 0: none
    FixPropertyAtom *store;
    bool made;                        // this style made the store
    int dvolume, energy, visc, damaged, heated;    // the store's columns: J - 1, u, q, D, and the
                                                   // heat added after the last step's forces

    double volume(int i) const;
    bool advance_element(int i, Advance how, double dt);
    void check_densities() const;
    [[noreturn]] void beyond_limit(int i, double ratio) const;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
