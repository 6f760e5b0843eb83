/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the contact of an unlinked pair of
   movable cellular automata closer than R_i + R_j (stateless, as
   spline_laws.h; a contact with dry friction keeps its tangential stress
   in the pair's doubles while it lasts, mca_contact.h):
     compression  S_u a (r - R_i - R_j) on the face S_u of the harmonic mean
                  radius (McaElement::unlinked_area)
     friction     the elastic tangential stress capped at mu |sigma_n| and
                  eta v_t (mca_friction.h)
     welding      pressed at the weld stress, the pair links where it is
                  (r_ref = its contact distance, its force unchanged) if its types link
   The contact distance is R_i + R_j, or, for a link that broke, the link's
   stress-free separation r_ref + e_p (the elements' deformed shapes: a link
   that flowed in compression and broke does not push its elements apart at
   once), kept until the pair opens.
   The seam for another contact law (segments, roughness).
   Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_UNLINKED_PAIR_H
#define LMP_CLUSTERDYN_MCA_UNLINKED_PAIR_H

#include "mca_contact.h"
#include "mca_element.h"
#include "mca_pair_model.h"
#include "mca_pair_tally.h"
#include "mca_pair_walk.h"
#include "pair_state.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaUnlinkedPair {
    using C = McaContact;

    double area;          // S_u
    double overlap;       // r - contact < 0
    double sigma;         // a overlap
    double contact;       // the contact distance, where a weld links the pair

    McaUnlinkedPair(double ri, double rj, double contact, double a, double r, int dimension) :
        area(McaElement::unlinked_area(ri, rj, dimension)), overlap(r - contact), sigma(a * overlap),
        contact(contact)
    {
    }

    // the contact's normal energy S_u a overlap^2 / 2
    double energy() const { return 0.5 * area * sigma * overlap; }

    // the contact distance of an unlinked pair (word, v: its state)
    static double contact_distance(int word, const double *v, double ri, double rj)
    {
      return (word & WORD_KEPT) && v[C::REF] > 0.0 ? v[C::REF] : ri + rj;
    }

    // a link that breaks (not at a minimizer's trial point) keeps its stress-free separation as
    // its contact distance, the rest of its state cleared (a contact starts from no tangential
    // stress; d: x_j - x_i now); returns the pair's word
    static int keep_contact(int word, double *v, const double *d)
    {
      const double distance = v[C::REF] + v[C::EPL];
      for (int k = 0; k < C::NVALUES; k++) v[k] = 0.0;
      v[C::REF] = distance > 0.0 ? distance : 0.0;
      for (int k = 0; k < 3; k++) v[C::DPREV + k] = d[k];
      return kept_word(word, true);
    }

    // the contact a link leaves as it breaks (keep_contact): a contact left pressed stores
    // energy the break did not release (tallied against it); returns the pair's word
    static int left_by_break(int word, double *v, const McaPairFrame &p, double ri, double rj,
                             double a, int dimension, const McaPairTally &tally)
    {
      word = keep_contact(word, v, p.d);
      const McaUnlinkedPair left(ri, rj, v[C::REF], a, p.r, dimension);
      if (left.overlap < 0.0) tally.changes.ejump -= tally.w * left.energy();
      return word;
    }

    // an open contact (closer than R_i + R_j, rsq = r^2, d = x_j - x_i) keeps nothing but a broken
    // link's contact distance, and that while the pair is closer than R_i + R_j (its tangential
    // stress cleared, d kept for the next slide); returns the pair's word
    static int open(int word, double *v, double rsq, const double *d, double ri_plus_rj)
    {
      if (!(word & WORD_KEPT) || !(v[C::REF] > 0.0) || rsq >= ri_plus_rj * ri_plus_rj)
        return kept_word(word, false);
      for (int k = 0; k < 3; k++) {
        v[C::TAU + k] = 0.0;
        v[C::DPREV + k] = d[k];
      }
      return word;
    }

    // the dry part: a new contact starts from no stress; tau slides and is capped (stored in
    // v); returns the work dissipated per area
    double dry(const McaFriction &fr, bool fresh, double *v, const double *d, const double *n,
               const C::Turn *turn, double a) const
    {
      if (fresh) {
        for (int k = 0; k < C::NVALUES; k++) v[k] = 0.0;
        for (int k = 0; k < 3; k++) v[C::DPREV + k] = d[k];
      }
      C::slide(v + C::TAU, v + C::DPREV, d, n, turn, a);
      return fr.cap(v + C::TAU, sigma, a);
    }

    // the viscous stress eta v_t from the velocity of j's contact point relative to i's
    // (arms qi, qj); returns |visc|^2 (the power dissipated per area is |visc|^2 / eta)
    static double viscous(double eta, const double *vi, const double *vj, const double *omega_i,
                          const double *omega_j, const double *n, double qi, double qj,
                          double *visc)
    {
      double wi[3], wj[3], vr[3];
      C::cross(omega_i, n, wi);
      C::cross(omega_j, n, wj);
      for (int k = 0; k < 3; k++) vr[k] = vj[k] - vi[k] - qj * wj[k] - qi * wi[k];
      const double vn = C::dot(vr, n);
      for (int k = 0; k < 3; k++) visc[k] = eta * (vr[k] - vn * n[k]);
      return C::dot(visc, visc);
    }

    // this step of the contact (word, v: the pair's state; turn: null where the elements do
    // not turn; vel, omega: null in a minimizer, where velocities mean nothing) and, pressed
    // at the weld stress, its welding: the pair links where it is, with the contact's stresses
    // (no jump of the pair's force or energy; the many-body term gains the link)
    // Inlined into the force pass, as McaLinkedPair::step
    [[gnu::always_inline]] void step(const McaPairModel &model, int &word, int trial, double *v,
                                     const McaPairFrame &p, const C::Turn *turn, double a,
                                     double *const *vel, double *const *omega, double dt,
                                     const McaPairTally &tally, bool energy_wanted,
                                     McaPairForce &out) const
    {
      const McaFriction &fr = model.friction;
      double tau[3] = {0.0, 0.0, 0.0}, visc[3] = {0.0, 0.0, 0.0};
      if (fr.keeps_state()) {
        const bool fresh = !(word & WORD_KEPT);
        if (fresh) word = kept_word(word, true);
        tally.work(WORK_FRICTION, area * dry(fr, fresh, v, p.d, p.n, turn, a));
        for (int k = 0; k < 3; k++) tau[k] = v[C::TAU + k];
      }
      if (fr.eta > 0.0 && vel) {
        const int i = tally.i, j = tally.j;
        const double power = viscous(fr.eta, vel[i], vel[j], omega[i], omega[j], p.n, p.qi, p.qj, visc);
        if (turn) tally.work(WORK_FRICTION, area * power / fr.eta * dt);
      }
      for (int k = 0; k < 3; k++) {
        out.ft[k] = area * (tau[k] + visc[k]);
        out.fi[k] = area * sigma * p.n[k] + out.ft[k];
      }
      if (energy_wanted) out.evdwl = energy() + area * 0.5 * C::dot(tau, tau) / a;
      if (fr.weld > 0.0 && -sigma >= fr.weld && model.links) {
        v[C::REF] = contact;
        v[C::AREA] = area;
        v[C::ET] = 0.5 * C::dot(tau, tau) / a;    // the tangential stress's energy it keeps
        v[C::KAPPA] = v[C::EPL] = 0.0;
        v[C::ROT] = v[C::ROT + 1] = v[C::ROT + 2] = 0.0;
        word = state_word(kept_word(word, false), 1, trial);
        tally.changes.formed += tally.w;
        tally.volume_change(McaVolumeChanges::CHANGE_STATE, area * overlap);
      }
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
