/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the micro-roughness K_mu(x) of a
   surface of movable cellular automata (stateless once made, as
   spline_laws.h): the review's eq 18 (Psakhie et al., Chebyshevskii
   Sbornik 18(3), 2017, section 7), two piecewise sinusoids about 1,
       K_mu(x) = 1 + sum_m A_mp sin(pi (x - x_mp) / l_m),  x in piece p
   each sinusoid m made of regular pieces: a piece has n_p whole periods
   2 l_m (l_m the half-period; n_p a random integer of mean d_m / (2 l_m):
   the regularity d_m is the mean length of a regular piece) and its own
   amplitude A_mp, uniform in [A_m / 2, 3 A_m / 2], with a random sign;
   every piece starts and ends at a zero, so K_mu is continuous, and its
   mean over every piece is 1.  Laid over [x0, x0 + L) of an x axis
   (periodic: the last piece of each sinusoid fills the rest with whole
   periods, stretched).  An element's contact of length S reads the mean
   of K_mu over it, (Phi(x + S/2) - Phi(x - S/2)) / S with Phi the exact
   antiderivative: a sinusoid's swing falls as sin(pi S / 2 l) / (pi S /
   2 l) once S is beyond its half-period, and to zero as S grows past the
   pieces, the review's fall of the oscillation with the element's size.
   The random numbers are Park and Miller's minimal standard (LAMMPS's
   RanPark), the same on every rank and machine.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_ROUGHNESS_H
#define LMP_CLUSTERDYN_MCA_ROUGHNESS_H

#include <cmath>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaRoughness {
   public:
    struct Wave {
      double amplitude = 0.0, half_period = 0.0, regularity = 0.0;
    };

    McaRoughness() = default;
    // waves: the two sinusoids; seed > 0; the profile over [x0, x0 + length)
    McaRoughness(const Wave *waves, int seed, double x0, double length) : x0(x0), length(length)
    {
      int state = seed;
      for (int m = 0; m < 2; m++) lay(waves[m], state, pieces[m]);
    }

    bool flat() const { return pieces[0].empty() && pieces[1].empty(); }

    double value(double x) const
    {
      x = wrapped(x);
      double k = 1.0;
      for (const auto &sine : pieces) {
        if (sine.empty()) continue;
        const Piece &p = sine[find(sine, x)];
        k += p.amplitude * sin(M_PI * (x - p.start) / p.half_period);
      }
      return k;
    }

    // the mean over [x - s/2, x + s/2] (s > 0)
    double mean(double x, double s) const
    {
      if (flat() || !(s > 0.0)) return flat() ? 1.0 : value(x);
      return (integral(x + 0.5 * s) - integral(x - 0.5 * s)) / s;
    }

   private:
    struct Piece {
      double start, half_period, amplitude;
    };
    double x0 = 0.0, length = 1.0;
    std::vector<Piece> pieces[2];

    // Park-Miller minimal standard, as LAMMPS's RanPark::uniform
    static double uniform(int &state)
    {
      const int IA = 16807, IM = 2147483647, IQ = 127773, IR = 2836;
      const int k = state / IQ;
      state = IA * (state - k * IQ) - IR * k;
      if (state < 0) state += IM;
      return state / static_cast<double>(IM);
    }

    void lay(const Wave &w, int &state, std::vector<Piece> &out) const
    {
      out.clear();
      if (!(w.amplitude > 0.0)) return;
      const double mean_periods = 0.5 * w.regularity / w.half_period;    // >= 1
      double at = 0.0;
      while (at < length) {
        int n = 1 + static_cast<int>(uniform(state) * (2.0 * mean_periods - 1.0));
        const double sign = uniform(state) < 0.5 ? -1.0 : 1.0;
        const double amp = sign * w.amplitude * (0.5 + uniform(state));
        double half = w.half_period;
        if (at + 2.0 * (n + 1) * half > length) {    // the last piece fills the rest
          n = static_cast<int>(floor((length - at) / (2.0 * half) + 0.5));
          if (n < 1) n = 1;
          half = (length - at) / (2.0 * n);
        }
        out.push_back({at, half, amp});
        at += 2.0 * n * half;
      }
    }

    static int find(const std::vector<Piece> &sine, double x)
    {
      int lo = 0, hi = static_cast<int>(sine.size()) - 1;
      while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (sine[mid].start <= x) lo = mid;
        else hi = mid - 1;
      }
      return lo;
    }

    double wrapped(double x) const
    {
      double u = fmod(x - x0, length);
      if (u < 0.0) u += length;
      return u;
    }

    // the integral of K_mu - 1 from x0 to x plus x - x0 (any x: every piece adds nothing whole)
    double integral(double x) const
    {
      double part = x - x0;
      const double u = wrapped(x);
      for (const auto &sine : pieces) {
        if (sine.empty()) continue;
        const Piece &p = sine[find(sine, u)];
        const double phase = M_PI * (u - p.start) / p.half_period;
        part += p.amplitude * p.half_period / M_PI * (1.0 - cos(phase));
      }
      return part;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
