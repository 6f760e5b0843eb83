/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the contact of an element k of one
   body with a segment i-j of the other body's surface, in two dimensions
   (stateless, as spline_laws.h): the method of segments of the review of
   movable cellular automata (Psakhie et al., Chebyshevskii Sbornik 18(3),
   2017, section 6, eqs 10-16).
     the segment's point nearest to k: p = x_i + t (x_j - x_i), t in
       [0, 1]; its height h = |x_k - p|, the normal n = (x_k - p) / h and
       the tangent e = z x n
     normal force on k (eq 10)  F_N = k_n (h0 - h) n  for h < h0,
       h0 = sqrt(3)/2 (R_k + R_s), R_s = (1 - t) R_i + t R_j (sqrt(3) R
       for equal elements: k in the hollow of the row), k_n = 3/2 S a
       (the two contacts of an element in a hollow, S a each, at 30
       degrees from the normal)
     shares (eqs 11, 12): i takes -(1 - t) and j takes -t of k's force,
       so that the three forces sum to zero and are the gradient of the
       energy k_n (h0 - h)^2 / 2 (the foot slides along the segment)
     friction (eqs 13-16): the slide of k's contact point over the
       segment's, V_t = e.(v_k - v_s) - R_k w_k - (h - R_k) w_s, loads a
       tangential spring xi (stiffness k_t = S a, as an unlinked pair's)
       capped at the dry limit f = min(mu0 K_mu F_N, S sigma0 / sqrt(3))
       (Coulomb with the micro-roughness K_mu, and the shear strength of
       a fully plastic junction), with the viscous eta0 S V_t beside it:
       F_t = -(k_t xi + eta0 S V_t) e
     torques: k turns with -R_k F_t, the segment with -(h - R_k) F_t
       shared as the forces, so that angular momentum is kept and the
       friction's power is F_t V_t
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_SEGMENT_LAW_H
#define LMP_CLUSTERDYN_MCA_SEGMENT_LAW_H

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaSegmentLaw {
    double mu0 = 0.0;       // dry friction coefficient
    double eta0 = 0.0;      // viscous friction, stress per velocity (energy/volume units)
    double sigma0 = 0.0;    // elastic limit of the junctions (0: no cap)

    // the law at t of a segment whose ends have laws li (t = 0) and lj (t = 1): mu0 and eta0
    // interpolated, sigma0 by its inverse (no limit: 0), so that the contact does not jump
    // where it passes from one end to the other
    static McaSegmentLaw between(const McaSegmentLaw &li, const McaSegmentLaw &lj, double t)
    {
      const double soft = (1.0 - t) * (li.sigma0 > 0.0 ? 1.0 / li.sigma0 : 0.0) +
          t * (lj.sigma0 > 0.0 ? 1.0 / lj.sigma0 : 0.0);
      return {(1.0 - t) * li.mu0 + t * lj.mu0, (1.0 - t) * li.eta0 + t * lj.eta0,
              soft > 0.0 ? 1.0 / soft : 0.0};
    }

    // the segment's point nearest to xk (2d: x, y); t in [0, 1]; returns h
    struct Foot {
      double t = 0.0, h = 0.0, n[2] = {0.0, 0.0}, e[2] = {0.0, 0.0};
    };
    static Foot nearest(const double *xi, const double *xj, const double *xk)
    {
      Foot f;
      const double s[2] = {xj[0] - xi[0], xj[1] - xi[1]};
      const double len2 = s[0] * s[0] + s[1] * s[1];
      double t = len2 > 0.0 ? ((xk[0] - xi[0]) * s[0] + (xk[1] - xi[1]) * s[1]) / len2 : 0.0;
      t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
      const double d[2] = {xk[0] - xi[0] - t * s[0], xk[1] - xi[1] - t * s[1]};
      f.t = t;
      f.h = sqrt(d[0] * d[0] + d[1] * d[1]);
      if (f.h > 0.0) {
        f.n[0] = d[0] / f.h;
        f.n[1] = d[1] / f.h;
      }
      f.e[0] = -f.n[1];
      f.e[1] = f.n[0];
      return f;
    }

    static double rest_height(double rk, double ri, double rj, double t)
    {
      return 0.5 * sqrt(3.0) * (rk + (1.0 - t) * ri + t * rj);
    }

    // the normal force on k (> 0: pushes k away) and its energy
    static double normal(double kn, double h0, double h, double &energy)
    {
      if (h >= h0) {
        energy = 0.0;
        return 0.0;
      }
      energy = 0.5 * kn * (h0 - h) * (h0 - h);
      return kn * (h0 - h);
    }

    // the dry limit of a junction pressed with fn through the contact length s
    double dry_limit(double fn, double kmu, double s) const
    {
      const double coulomb = mu0 * kmu * fn;
      const double junction = sigma0 / sqrt(3.0) * s;
      return sigma0 > 0.0 && junction < coulomb ? junction : coulomb;
    }

    // the tangential spring xi after a slide vt dt, capped at limit / kt; returns the tangential
    // force on k (along e) and sets the work the slip dissipated and the spring's energy
    double friction(double &xi, double vt, double dt, double kt, double limit, double s,
                    double &work, double &energy) const
    {
      xi += vt * dt;
      work = 0.0;
      const double cap = limit / kt;
      if (fabs(xi) > cap) {
        const double kept = xi > 0.0 ? cap : -cap;
        work = limit * fabs(xi - kept);
        xi = kept;
      }
      energy = 0.5 * kt * xi * xi;
      const double viscous = eta0 * s * vt;
      work += viscous * vt * dt;
      return -(kt * xi + viscous);
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
