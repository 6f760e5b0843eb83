/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the base interaction laws.

   Each law is a stateless struct used as a template argument of PairSpline:
     read()        parse and check the law's pair_coeff arguments
     args()        the same arguments as text (data files)
     setup()       constants of the force kernel (SplineCoeff::c1..c3)
     inflection()  b of the unmodified base (Pi''(b) = 0, b > a), or 0 if there is none
     derivs()      Pi, Pi', Pi'', Pi''' of the unmodified base at argument s (after
                   setup(): Mie's reads its constants)
     wide_well_hint, overflow_hint   what to change when the wagner tail has no
                   cutoff or the law overflows (error messages)
     eval<KAPPA>() energy and fpair = f(r)/r of the kappa-modified base at rsq;
                   KAPPA = false is the fast path used when every kappa is 1
   Formulas: doc/pair_spline.rst (Krivtsov & Krivtsova 2002, sections 1 and 2).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_LAWS_H
#define LMP_CLUSTERDYN_SPLINE_LAWS_H

#include "arg_values.h"
#include "vector_math.h"    // before the laws use exp and pow
#include "error.h"
#include "pointers.h"
#include "utils.h"

#include <cmath>
#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  // per type pair data of the force kernel, packed for cache locality

  struct SplineCoeff {
    double cutsq;                   // square of the interaction end (Rc a or ac)
    double d, a, kappa, p, q;       // D, a, kappa and the law's extra parameters
    double c1, c2, c3;              // law constants (Law::setup)
    double bsq, acsq, wa2, wa3;     // wagner: b^2, ac^2 and the spline coefficients
    double rs, rssq, inv_l2;        // lagunov: start, start^2, 1/(Rc - Rs)^2
    double rc;                      // end of the interaction (absolute)
    double offset;                  // energy shift (cut tail with pair_modify shift yes)
    double hardsq;                  // r^2 at or below which the law is singular
  };

  // "D alpha a": the arguments of the Morse and harmonic laws

  inline void read_d_alpha_a(const char *style, char **arg, SplineCoeff &c, LAMMPS *lmp)
  {
    const std::string who = std::string("Pair ") + style;
    c.d = positive_arg(who, "D", arg[0], lmp);
    c.p = positive_arg(who, "alpha", arg[1], lmp);
    c.a = positive_arg(who, "a", arg[2], lmp);
    c.q = 0.0;
  }

  inline std::string args_d_alpha_a(const SplineCoeff &c)
  {
    return fmt::format("{} {} {}", c.d, c.p, c.a);
  }

  struct MorseLaw {
    static constexpr const char *style = "morse/spline";
    static constexpr const char *usage = "D alpha a";
    static constexpr const char *p_name = "alpha";
    static constexpr const char *q_name = nullptr;
    static constexpr int nargs = 3;
    static constexpr bool kappa_kernel = false;    // kappa folds into alpha
    static constexpr bool vector_stage = true;     // exp: libmvec in the block's SIMD loop
    static constexpr bool singular = false;
    static constexpr bool has_inflection = true;
    static constexpr const char *wide_well_hint = "Morse needs kappa alpha a >= 1.557";
    static constexpr const char *overflow_hint = "alpha a must be below about 700";

    static void read(char **arg, SplineCoeff &c, LAMMPS *lmp) { read_d_alpha_a(style, arg, c, lmp); }
    static std::string args(const SplineCoeff &c) { return args_d_alpha_a(c); }
    static void setup(SplineCoeff &c)
    {
      c.c1 = c.kappa * c.p;           // alpha kappa
      c.c2 = 2.0 * c.c1 * c.d;        // 2 alpha kappa D
      c.c3 = 0.0;
    }
    static double inflection(const SplineCoeff &c) { return c.a + M_LN2 / c.p; }
    static void derivs(const SplineCoeff &c, double s, double *d)
    {
      const double e = exp(-c.p * (s - c.a));
      const double k = 2.0 * c.p * c.d;
      d[0] = c.d * (e * e - 2.0 * e);
      d[1] = k * (e - e * e);
      d[2] = k * c.p * (2.0 * e * e - e);
      d[3] = k * c.p * c.p * (e - 4.0 * e * e);
    }
    template <bool KAPPA> static inline double eval(const SplineCoeff &c, double rsq, double &fpair)
    {
      const double r = sqrt(rsq);
      const double dexp = exp(-c.c1 * (r - c.a));
      fpair = c.c2 * (dexp * dexp - dexp) / r;
      return c.d * (dexp * dexp - 2.0 * dexp);
    }
  };

  struct HarmonicLaw {
    static constexpr const char *style = "harmonic/spline";
    static constexpr const char *usage = "D alpha a";
    static constexpr const char *p_name = "alpha";
    static constexpr const char *q_name = nullptr;
    static constexpr int nargs = 3;
    static constexpr bool kappa_kernel = false;    // kappa folds into the stiffness
    static constexpr bool vector_stage = false;    // a polynomial: applied as read
    static constexpr bool singular = false;
    static constexpr bool has_inflection = false;
    static constexpr const char *wide_well_hint = "";
    static constexpr const char *overflow_hint = "D alpha^2 a^2 is too large";

    static void read(char **arg, SplineCoeff &c, LAMMPS *lmp) { read_d_alpha_a(style, arg, c, lmp); }
    static std::string args(const SplineCoeff &c) { return args_d_alpha_a(c); }
    static void setup(SplineCoeff &c)
    {
      c.c1 = c.kappa * c.kappa * c.p * c.p * c.d;    // (alpha kappa)^2 D
      c.c2 = 2.0 * c.c1;
      c.c3 = 0.0;
    }
    static double inflection(const SplineCoeff &) { return 0.0; }
    static void derivs(const SplineCoeff &c, double s, double *d)
    {
      const double k = c.p * c.p * c.d;
      d[0] = k * (s - c.a) * (s - c.a) - c.d;
      d[1] = 2.0 * k * (s - c.a);
      d[2] = 2.0 * k;
      d[3] = 0.0;
    }
    template <bool KAPPA> static inline double eval(const SplineCoeff &c, double rsq, double &fpair)
    {
      const double r = sqrt(rsq);
      const double dr = r - c.a;
      fpair = -c.c2 * dr / r;
      return c.c1 * dr * dr - c.d;
    }
  };

  // Mie(n, m); Lennard-Jones is Mie(12, 6) with integer powers in the kernel

  struct MieLaw {
    static constexpr const char *style = "mie/spline";
    static constexpr const char *usage = "D a n m";
    static constexpr const char *p_name = "n";
    static constexpr const char *q_name = "m";
    static constexpr int nargs = 4;
    static constexpr bool kappa_kernel = true;
    static constexpr bool vector_stage = true;     // pow: libmvec in the block's SIMD loop
    static constexpr bool singular = true;
    static constexpr bool has_inflection = true;
    static constexpr const char *wide_well_hint = "raise kappa or the exponents n, m";
    static constexpr const char *overflow_hint = "the exponents n and m must be below about 1000";

    static void read(char **arg, SplineCoeff &c, LAMMPS *lmp)
    {
      const std::string who = std::string("Pair ") + style;
      c.d = positive_arg(who, "D", arg[0], lmp);
      c.a = positive_arg(who, "a", arg[1], lmp);
      c.p = number_arg(who, "n", arg[2], lmp);
      c.q = positive_arg(who, "m", arg[3], lmp);
      if (!(c.p > c.q)) lmp->error->all(FLERR, "Pair {}: n must be > m (got n = {}, m = {})",
                                        style, arg[2], arg[3]);
    }
    static std::string args(const SplineCoeff &c)
    {
      return fmt::format("{} {} {} {}", c.d, c.a, c.p, c.q);
    }
    static void setup(SplineCoeff &c)
    {
      c.c1 = c.d / (c.p - c.q);       // D/(n-m)
      c.c2 = c.p * c.q * c.c1;        // nmD/(n-m)
      c.c3 = c.a * c.a;
    }
    static double inflection(const SplineCoeff &c)
    {
      return c.a * pow((c.p + 1.0) / (c.q + 1.0), 1.0 / (c.p - c.q));
    }
    static void derivs(const SplineCoeff &c, double s, double *d)
    {
      const double n = c.p, m = c.q, x = c.a / s;
      const double xn = pow(x, n), xm = pow(x, m);
      const double k = c.c2 / c.a;
      d[0] = c.c1 * (m * xn - n * xm);
      d[1] = k * x * (xm - xn);
      d[2] = k / c.a * x * x * ((n + 1.0) * xn - (m + 1.0) * xm);
      d[3] = k / (c.a * c.a) * x * x * x * ((m + 1.0) * (m + 2.0) * xm - (n + 1.0) * (n + 2.0) * xn);
    }
    template <bool KAPPA> static inline double eval(const SplineCoeff &c, double rsq, double &fpair)
    {
      if (KAPPA) {
        const double r = sqrt(rsq);
        const double x = c.a / (c.kappa * (r - c.a) + c.a);
        const double xn = pow(x, c.p), xm = pow(x, c.q);
        fpair = c.kappa * c.c2 / c.a * x * (xn - xm) / r;
        return c.c1 * (c.q * xn - c.p * xm);
      }
      const double x2 = c.c3 / rsq;
      const double xn = pow(x2, 0.5 * c.p), xm = pow(x2, 0.5 * c.q);
      fpair = c.c2 * (xn - xm) / rsq;
      return c.c1 * (c.q * xn - c.p * xm);
    }
  };

  struct LJLaw {
    static constexpr const char *style = "lj/spline";
    static constexpr const char *usage = "D a";
    static constexpr const char *p_name = nullptr;
    static constexpr const char *q_name = nullptr;
    static constexpr int nargs = 2;
    static constexpr bool kappa_kernel = true;
    static constexpr bool vector_stage = false;    // powers by products: applied as read
    static constexpr bool singular = true;
    static constexpr bool has_inflection = true;
    static constexpr const char *wide_well_hint = "raise kappa";
    static constexpr const char *overflow_hint = "D / a^3 is beyond double precision";

    static void read(char **arg, SplineCoeff &c, LAMMPS *lmp)
    {
      const std::string who = std::string("Pair ") + style;
      c.d = positive_arg(who, "D", arg[0], lmp);
      c.a = positive_arg(who, "a", arg[1], lmp);
      c.p = 12.0;
      c.q = 6.0;
    }
    static std::string args(const SplineCoeff &c) { return fmt::format("{} {}", c.d, c.a); }
    static void setup(SplineCoeff &c)
    {
      c.c1 = 12.0 * c.d / (c.a * c.a);
      c.c2 = 0.0;
      c.c3 = c.a * c.a;
    }
    static double inflection(const SplineCoeff &c) { return MieLaw::inflection(c); }
    static void derivs(const SplineCoeff &c, double s, double *d)
    {
      const double x = c.a / s, x2 = x * x, x6 = x2 * x2 * x2, x12 = x6 * x6;
      const double k = 12.0 * c.d / c.a;
      d[0] = c.d * (x12 - 2.0 * x6);
      d[1] = k * x * (x6 - x12);
      d[2] = k / c.a * x2 * (13.0 * x12 - 7.0 * x6);
      d[3] = k / (c.a * c.a) * x2 * x * (56.0 * x6 - 182.0 * x12);
    }
    template <bool KAPPA> static inline double eval(const SplineCoeff &c, double rsq, double &fpair)
    {
      if (KAPPA) {
        const double r = sqrt(rsq);
        const double x = c.a / (c.kappa * (r - c.a) + c.a);
        const double x2 = x * x, x6 = x2 * x2 * x2;
        fpair = c.kappa * c.c1 * c.a * x * x6 * (x6 - 1.0) / r;
        return c.d * x6 * (x6 - 2.0);
      }
      const double x2 = c.c3 / rsq, x6 = x2 * x2 * x2;
      fpair = c.c1 * x2 * x6 * (x6 - 1.0);
      return c.d * x6 * (x6 - 2.0);
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
