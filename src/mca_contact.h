/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the mechanics of one pair of movable
   cellular automata (stateless, as spline_laws.h): the stiffness of the
   pair's two halves in series, the stored tangential stress carried with
   the pair (objective), and the layout of a linked pair's state.

   Element i's half of pair ij has length q_ij = r R_i/(R_i + R_j); its
   normal strain and shear take the stiffness a_i = 2 G_i / R_i per unit
   displacement (stress per length), so that the two halves in series give
   sigma_ij = sigma_ji (Newton's third law): a = a_i a_j / (a_i + a_j), and
   element i takes the share w_i = a_j / (a_i + a_j) of the pair's
   elongation (both from one division per pair: mca_pair_halves.h).
   Objectivity: between two evaluations the pair's frame turns
   by the spin of its contact, w = (q_ij omega_i + q_ji omega_j) / r; the
   stored tangential stress and last separation are turned by w dt before
   the new separation is compared with them, so that a rigid rotation makes
   no stress.  A link also carries a moment from the relative rotation of its
   elements (bending and twisting of its contact area).  Formulas:
   doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_CONTACT_H
#define LMP_CLUSTERDYN_MCA_CONTACT_H

#include <cmath>
#include <initializer_list>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaContact {
    // a pair's doubles, seen from the list's atom i (the partner's copy has the vectors
    // negated: partner_copy)
    enum {
      REF = 0, AREA = 1, TAU = 2, DPREV = 5, KAPPA = 8, EPL = 9, SIG = 10, ROT = 11, HG = 14,
      DR = 15, DTAU = 16, EHG = 17, FHG = 18, ET = 19, NVALUES = 20
    };
    // REF: the distance at linking (stress free); AREA: S_ij; TAU: the tangential stress on
    // i (3; effective, undamaged); DPREV: x_j - x_i at the last evaluation (3); KAPPA: the
    // largest effective equivalent stress (damage); EPL: the plastic elongation; SIG: the
    // trial normal stress of this step (plasticity); ROT: the rotation of j relative to i (3),
    // turned with the contact's spin as TAU; HG: the elongation beyond its elements' mean
    // velocity gradient (the hourglass spring of a shock equation of state); DR: this step's
    // change of the separation r (0 at a setup); DTAU: tau~ . du_t, du_t this step's slide of
    // the contact points (plasticity); EHG: the work the hourglass spring's force has done on
    // the pair (its energy); FHG: its pull at the last evaluation; ET: the tangential stress's
    // energy per area as the work done against it (slide: the trapezoid rule over each step's
    // motion, as velocity Verlet weighs the force; |tau~|^2 / (2a) where the pair's direction
    // holds, and second order in dt where it turns, where |tau~|^2 / (2a) is first order).  DR
    // and DTAU hold within a step: they weigh the plastic work by the trapezoid rule, as the
    // step weighs the forces' work (mca_linked_pair.h).  An unlinked contact uses TAU and DPREV.

    // the pair's doubles as its partner sees them (fix neigh/history's transfer_history): the
    // scalars copied, the vectors negated
    static void partner_copy(const double *source, double *target)
    {
      for (const int k : {REF, AREA, KAPPA, EPL, SIG, HG, DR, DTAU, EHG, FHG, ET})
        target[k] = source[k];
      for (int k = 0; k < 3; k++) {
        target[TAU + k] = -source[TAU + k];
        target[DPREV + k] = -source[DPREV + k];
        target[ROT + k] = -source[ROT + k];
      }
    }

    static double half_stiffness(double shear, double radius) { return 2.0 * shear / radius; }

    // the moment of a link (the review's K_ij) from the relative rotation rot of j against i:
    // a circular contact of area S bends with the stiffness a I and twists with a J
    // (I = S^2 / (4 pi), J = 2 I: the second moments of the area); in 2d (planar) the contact
    // is a strip of length S and unit thickness, I = S^3 / 12, and only bends; m: the moment
    // on i (its opposite acts on j); returns the energy
    static double moment(const double *rot, const double *n, double a, double area, bool planar,
                         double *m)
    {
      const double bend = planar ? a * area * area * area / 12.0 : a * area * area / (4.0 * M_PI);
      const double twist = 2.0 * bend;
      const double along = dot(rot, n);
      for (int k = 0; k < 3; k++) m[k] = bend * (rot[k] - along * n[k]) + twist * along * n[k];
      return 0.5 * (bend * (dot(rot, rot) - along * along) + twist * along * along);
    }

    // this step's change of the separation, r less |DPREV| (the last evaluation's)
    static double motion(const double *v, double r) { return r - sqrt(dot(v + DPREV, v + DPREV)); }

    static double dot(const double *a, const double *b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
    static void cross(const double *a, const double *b, double *c)
    {
      c[0] = a[1] * b[2] - a[2] * b[1];
      c[1] = a[2] * b[0] - a[0] * b[2];
      c[2] = a[0] * b[1] - a[1] * b[0];
    }

    // a turn by the rotation vector phi (angle a = |phi| about phi / a), Rodrigues' formula
    // with phi unnormalized: v' = v cos a + (phi x v) sin(a)/a + phi (phi.v) (1 - cos a)/a^2;
    // its three factors are taken once for all the vectors it turns, and below a = 1e-2
    // (a step's turn of a contact is far below) from their Taylor series to a^6, whose
    // remainder a^8/8! is below 1e-20: no square root, division or sine there, and no
    // cancellation in 1 - cos a
    struct Turn {
      static constexpr double SERIES = 1e-4;    // a^2 below which the series serve
      double phi[3] = {0.0, 0.0, 0.0}, c = 1.0, sa = 1.0, ca = 0.5;
      bool none = true;
      Turn() = default;    // no turn
      explicit Turn(const double *rotation)
      {
        const double a2 = dot(rotation, rotation);
        if (a2 == 0.0) return;
        for (int m = 0; m < 3; m++) phi[m] = rotation[m];
        if (a2 < SERIES) {
          series(a2, c, sa, ca);
        } else {
          const double a = sqrt(a2);
          c = cos(a);
          sa = sin(a) / a;
          ca = (1.0 - c) / a2;
        }
        none = false;
      }
      // the same turn where a^2 < SERIES is known: no branch to the sine, so that a batch of
      // turns runs as vectors (mca_link_turns.h)
      static Turn in_series(const double *rotation)
      {
        Turn turn;
        const double a2 = dot(rotation, rotation);
        for (int m = 0; m < 3; m++) turn.phi[m] = rotation[m];
        series(a2, turn.c, turn.sa, turn.ca);
        turn.none = a2 == 0.0;
        return turn;
      }
      void apply(double *v) const
      {
        if (none) return;
        double pv[3];
        cross(phi, v, pv);
        const double pdv = dot(phi, v) * ca;
        for (int m = 0; m < 3; m++) v[m] = v[m] * c + pv[m] * sa + phi[m] * pdv;
      }

     private:
      static void series(double a2, double &c, double &sa, double &ca)
      {    // the constants are reciprocals, multiplied
        c = 1.0 - 0.5 * a2 * (1.0 - a2 * (1.0 / 12.0) * (1.0 - a2 * (1.0 / 30.0)));
        sa = 1.0 - a2 * (1.0 / 6.0) * (1.0 - a2 * (1.0 / 20.0) * (1.0 - a2 * (1.0 / 42.0)));
        ca = 0.5 *
            (1.0 - a2 * (1.0 / 12.0) * (1.0 - a2 * (1.0 / 30.0) * (1.0 - a2 * (1.0 / 56.0))));
      }
    };

    // the tangential stress after this step's slide: tau and the last separation dprev turn
    // with the contact's spin (null: they do not turn), tau is brought into the tangent plane
    // of n at its magnitude, then grows by a du_t, du_t the slide of the contact points (into
    // dut where not null); work (where not null) gains the work done against the stress over
    // the motion du = d - dprev, (tau_before + tau_after) . du / 2
    static void slide(double *tau, double *dprev, const double *d, const double *n,
                      const Turn *turn, double a, double *dut = nullptr, double *work = nullptr)
    {
      if (turn) {
        turn->apply(tau);
        turn->apply(dprev);
      }
      const double du[3] = {d[0] - dprev[0], d[1] - dprev[1], d[2] - dprev[2]};
      const double before = work ? dot(tau, du) : 0.0;
      // a stress left out of the new tangent plane (the pair turned otherwise than its
      // contact spins) is brought into it at its magnitude
      const double tau_old2 = dot(tau, tau), taun = dot(tau, n);
      if (taun != 0.0) {
        const double keep = tau_old2 > taun * taun ? sqrt(tau_old2 / (tau_old2 - taun * taun)) : 0.0;
        for (int k = 0; k < 3; k++) tau[k] = (tau[k] - taun * n[k]) * keep;
      }
      const double dun = dot(du, n);
      for (int k = 0; k < 3; k++) {
        tau[k] += a * (du[k] - dun * n[k]);
        dprev[k] = d[k];
        if (dut) dut[k] = du[k] - dun * n[k];
      }
      if (work) *work += 0.5 * (before + dot(tau, du));
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
