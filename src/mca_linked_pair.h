/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the law of a linked pair of movable
   cellular automata at one step (stateless, as spline_laws.h; its state is
   the pair's doubles, mca_contact.h).  The pair transmits (1 - D) of its
   effective stresses through its area S:
     sigma~ = a (r - r_ref - e_p) [+ the many-body part, mca_manybody.h]
     tau~  += a du_t (McaContact::slide)
   plastic flow returns them radially by phi about the mean stress of the
   two elements and stores the plastic elongation; the relative rotation
   of the elements gives a moment (McaContact::moment); the pair's energy
   is S (a e^2 / 2 + |tau~|^2 / (2a)) + the moment's; from this step's
   stresses (mca_response.h), with the mean stress of the elements'
   pressure (a shock equation of state, mca_element_eos.h), the pair
   damages (from the next step) or breaks (now); with that pressure it
   also breaks when stretched to RUPTURE r_ref, and where an element's spall
   kinetics has damaged it fully.  Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_LINKED_PAIR_H
#define LMP_CLUSTERDYN_MCA_LINKED_PAIR_H

#include "mca_contact.h"
#include "mca_pair_tally.h"
#include "mca_pair_walk.h"
#include "mca_response.h"
#include "mca_settings.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaLinkedPair {
    using C = McaContact;
    enum Outcome { HOLDS = 0, DAMAGES = 1, BREAKS = 2 };
    // with a shock equation of state, a link of a material with a strength breaks at the
    // stretch r / r_ref of the neighbour list's reach: an element that lost its volume pulls
    // with its deviator alone, which yield caps below the strength
    static constexpr double RUPTURE = McaSettings::REACH;

    const McaResponse &response;
    double *v;         // the pair's state
    double a;          // the stiffness of its halves in series
    double intact;     // 1 - D
    double area;       // S
    bool planar;       // dimension 2: the contact is a strip (its bending, McaContact::moment)

    McaLinkedPair(const McaResponse &response, double *v, double a, bool planar = false) :
        response(response), v(v), a(a), intact(response.intact(v[C::KAPPA])), area(v[C::AREA]),
        planar(planar)
    {
    }

    // the trial tangential stress of this step: after this step's slide (stored in v with its
    // energy ET; turn: null where the pair does not turn); a batch of links in the plastic pass
    // slides side by side (mca_link_turns.h)
    static void slide(double *v, double a, const McaPairFrame &p, const C::Turn *turn)
    {
      C::slide(v + C::TAU, v + C::DPREV, p.d, p.n, turn, a, nullptr, v + C::ET);
    }

    // the elastic part of the effective normal stress at separation r (the trial normal stress
    // before any return, with the many-body part)
    static double elastic_stress(const double *v, double a, double r)
    {
      return a * (r - v[C::REF] - v[C::EPL]);
    }

    // the radial return by phi < 1 about the mean stress: sigma and tau move, the plastic
    // elongation grows; returns the work dissipated (per pair); dv: the pair's volume change.
    // The work: the energy the return takes from the trial state, less half the return's drop
    // of force times this step's motion (DR, DTAU: the trapezoid rule of the step's work,
    // sigma dp summed at the stresses after the returns that open and close the step), which
    // the velocity-Verlet step, weighing its forces so, does not see; an energy drop without it
    // counts S a dp dr / 2 too much each step (first order in dt)
    double plastic_return(double &sigma, double phi, double mean, double r, double &dv)
    {
      double *tau = v + C::TAU;
      const double back = (intact * sigma - mean) * (1.0 - phi) / intact;
      const double e_old = elongation(r), tau2_old = C::dot(tau, tau);
      v[C::EPL] += back / a;
      sigma -= back;
      for (int k = 0; k < 3; k++) tau[k] *= phi;
      const double e_new = e_old - back / a;
      dv = -intact * area * back / a;
      v[C::ET] -= 0.5 * (tau2_old - C::dot(tau, tau)) / a;    // what the return takes
      return intact * area *
          (0.5 * a * (e_old * e_old - e_new * e_new) + 0.5 * (tau2_old - C::dot(tau, tau)) / a -
           0.5 * (back * v[C::DR] + (1.0 - phi) * v[C::DTAU]));
    }

    // the relative rotation of j against i (in the pair's state v): turned with the contact,
    // then advanced by dt (omega_j - omega_i)
    static void rotate(double *v, const C::Turn &turn, const double *omega_i,
                       const double *omega_j, double dt)
    {
      double step[3];
      rotation_step(omega_i, omega_j, dt, step);
      rotate(v + C::ROT, turn, step);
    }
    // ... with the relative rotation rot alone, and this step's advance dt (omega_j - omega_i)
    static void rotate(double *rot, const C::Turn &turn, const double *step)
    {
      turn.apply(rot);
      for (int k = 0; k < 3; k++) rot[k] += step[k];
    }
    static void rotation_step(const double *omega_i, const double *omega_j, double dt,
                              double *step)
    {
      for (int k = 0; k < 3; k++) step[k] = dt * (omega_j[k] - omega_i[k]);
    }

    // the elastic elongation at separation r: r - r_ref - e_p
    static double elongation(const double *v, double r) { return r - v[C::REF] - v[C::EPL]; }
    double elongation(double r) const { return elongation(v, r); }

    // the effective energy at elongation elong with the tangential energy tangential per area
    // (ET; |tau~|^2 / (2a) where the pair does not turn) (moment: the effective moment on i)
    double energy(const double *n, double elong, double tangential, double *moment) const
    {
      const double erot = C::moment(v + C::ROT, n, a, area, planar, moment);
      return area * (0.5 * a * elong * elong + tangential) + erot;
    }

    // damage and breaking at this step's stresses: HOLDS, the equivalent stress is not above
    // kappa (nothing changes); DAMAGES, kappa rises to it and lost is the share of the
    // effective stresses lost (0 below sigma_d); BREAKS, it reaches the peak (lost: all)
    Outcome respond(double sigma, double tau2, double &lost)
    {
      const double s = response.active() ? McaResponse::equivalent(sigma, tau2) : 0.0;
      if (!(s > v[C::KAPPA])) return HOLDS;
      if (s >= response.peak()) {
        lost = intact;
        return BREAKS;
      }
      lost = intact - response.intact(s);
      v[C::KAPPA] = s;
      return DAMAGES;
    }

    // this step after the trial stress sigma: the plastic return by phi about mean (phi < 1),
    // the rotation (turn: null where the elements do not turn, or where the plastic pass has
    // turned the link already), damage or breaking (under sigma and the elements' mean stress
    // from their pressure: pressure, null where there is none), the force; false: the pair
    // breaks and transmits nothing from now on.  Inlined into the force pass: as a call it
    // costs 10 % of pair mca's Pair time (bench/bench_pair_ab.sh)
    [[gnu::always_inline]] bool step(double sigma, double phi, double mean, const McaPairFrame &p,
                                     const C::Turn *turn, const double *omega_i,
                                     const double *omega_j, double dt, const McaPairTally &tally,
                                     bool energy_wanted, const McaPressureLoad *pressure,
                                     McaPairForce &out)
    {
      if (phi < 1.0) {
        double dv;
        tally.work(WORK_PLASTIC, plastic_return(sigma, phi, mean, p.r, dv));
        tally.volume_change(McaVolumeChanges::CHANGE_PLASTIC, dv);
      }
      if (turn) rotate(v, *turn, omega_i, omega_j, dt);
      double moment[3], lost = 0.0;
      const double elong = elongation(p.r), tau2 = C::dot(v + C::TAU, v + C::TAU);
      const double epair = energy(p.n, elong, v[C::ET], moment);
      Outcome outcome = respond(sigma + (pressure ? pressure->stress : 0.0), tau2, lost);
      if (pressure && outcome != BREAKS &&
          (pressure->spalled ||
           ((response.active() || pressure->kinetic) && p.r > RUPTURE * v[C::REF]))) {
        lost = intact;    // an element spalled, or a ligament flowed to the reach of the list
        outcome = BREAKS;
      }
      if (outcome != HOLDS)
        tally.volume_change(outcome == BREAKS ? McaVolumeChanges::CHANGE_STATE
                                              : McaVolumeChanges::CHANGE_DAMAGE,
                            -lost * area * elong);
      if (outcome == BREAKS) {
        tally.changes.broken += tally.w;
        tally.changes.ejump += tally.w * (intact * epair);
        return false;
      }
      if (outcome == DAMAGES) tally.work(WORK_DAMAGE, lost * epair);
      const double *tau = v + C::TAU;
      for (int k = 0; k < 3; k++) {
        out.ft[k] = intact * area * tau[k];
        out.fi[k] = intact * area * sigma * p.n[k] + out.ft[k];
        if (pressure) out.fi[k] += intact * pressure->f[k];
        out.mom[k] = intact * moment[k];
      }
      if (energy_wanted) out.evdwl = intact * epair;
      return true;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
