/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the coefficients of a spline pair
   style.  Per type pair the input as pair_coeff gave it (the LAMMPS
   interface: extract, restart, data files) and the packed kernel data
   derived from it with the law (spline_laws.h), the tail (spline_tails.h),
   the shift and the link rule (spline_links.h); errors name the pair.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_TABLE_H
#define LMP_CLUSTERDYN_SPLINE_TABLE_H

#include "spline_links.h"
#include "spline_settings.h"

#include "comm.h"
#include "memory.h"

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  template <class Law> class SplineTable : protected Pointers {
   public:
    double **d0, **a0, **p0, **q0, **kappa, **rc_pair, **rs_pair;    // rc, rs: 0 = global
    double **stiffness;         // C = Pi''(a) of the kappa-modified law (extract "C")
    SplineCoeff *coeffs;        // (ntypes+1)^2 packed kernel data
    std::vector<double> stiffness_made;    // C as mirror() last derived it
    int np1;

    explicit SplineTable(LAMMPS *lmp) : Pointers(lmp), coeffs(nullptr), np1(0)
    {
      d0 = a0 = p0 = q0 = kappa = rc_pair = rs_pair = stiffness = nullptr;
    }
    ~SplineTable()
    {
      for (double **v : {d0, a0, p0, q0, kappa, rc_pair, rs_pair, stiffness}) memory->destroy(v);
      delete[] coeffs;
    }
    void allocate(int ntypes)
    {
      np1 = ntypes + 1;
      for (double ***v : {&d0, &a0, &p0, &q0, &kappa, &rc_pair, &rs_pair, &stiffness})
        memory->create(*v, np1, np1, "pair:spline");
      for (int i = 0; i < np1; i++)
        for (int j = 0; j < np1; j++) stiffness[i][j] = 0.0;
      stiffness_made.assign(np1 * np1, 0.0);
      coeffs = new SplineCoeff[np1 * np1]();
    }
    const SplineCoeff &at(int i, int j) const { return coeffs[i * np1 + j]; }

    // one pair's input (pair_coeff), checked at once by derive()
    void set(int i, int j, const SplineCoeff &in, double kappa_one, double rc, double rs)
    {
      d0[i][j] = in.d;
      a0[i][j] = in.a;
      p0[i][j] = in.p;
      q0[i][j] = in.q;
      kappa[i][j] = kappa_one;
      rc_pair[i][j] = rc;
      rs_pair[i][j] = rs;
    }
    // as pair lj/cut resets explicitly set cutoffs, a new pair_style command resets every
    // per-pair rc and rs to the new global values (those of one tail mean nothing to another)
    void reset_cutoffs()
    {
      for (int i = 1; i < np1; i++)
        for (int j = i; j < np1; j++) rc_pair[i][j] = rs_pair[i][j] = 0.0;
    }
    // init_one(): j,i as i,j; the stiffness C, which is derived, not a parameter: a value
    // written into it (fix adapt through extract "C") would be lost here
    void mirror(int i, int j)
    {
      for (auto *v : {d0, a0, p0, q0, kappa, rc_pair, rs_pair}) v[j][i] = v[i][j];
      if (stiffness[i][j] != stiffness_made[i * np1 + j])
        error->all(FLERR, "Pair {}: C of types {} {} is the law's stiffness, derived from its "
                   "parameters: fix adapt cannot set it (adapt D, a, kappa{}{})", Law::style, i, j,
                   Law::p_name ? std::string(", ") + Law::p_name : "",
                   Law::q_name ? std::string(", ") + Law::q_name : "");
      double d[4];
      kappa_derivs<Law>(at(i, j), at(i, j).a, d);
      stiffness[i][j] = stiffness[j][i] = d[2];
      stiffness_made[i * np1 + j] = stiffness_made[j * np1 + i] = d[2];
    }

    void derive(int i, int j, const SplineSettings &s, int offset_flag, SplineLinks &links);
    void write_restart(FILE *fp, int **setflag) const;
    void read_restart(FILE *fp, int **setflag);
    void write_data(FILE *fp, bool all_pairs) const;    // data files: i i, or every i j
    void *extract(const char *str) const;
  };

  /* ----------------------------------------------------------------------
     kernel data of one type pair from its input and the settings
  ------------------------------------------------------------------------- */

  template <class Law>
  void SplineTable<Law>::derive(int i, int j, const SplineSettings &s, int offset_flag,
                                SplineLinks &links)
  {
    SplineCoeff &c = coeffs[i * np1 + j];
    c = SplineCoeff();
    c.d = d0[i][j];
    c.a = a0[i][j];
    c.p = p0[i][j];
    c.q = q0[i][j];
    c.kappa = kappa[i][j];
    // pair_coeff checked these; fix adapt may change them
    const bool two = Law::q_name != nullptr;
    if (!(c.d > 0.0 && c.a > 0.0 && c.kappa > 0.0 && (Law::p_name == nullptr || c.p > 0.0) &&
          (!two || (c.q > 0.0 && c.p > c.q))))
      error->all(FLERR, "Pair {}: types {} {} need D, a, kappa > 0{} (got D = {}, a = {}, kappa = "
                 "{}, {})", Law::style, i, j, two ? ", n > m > 0" : Law::p_name ? ", alpha > 0" : "",
                 c.d, c.a, c.kappa, Law::args(c));
    Law::setup(c);

    // the kappa-modified law must stay finite under deep compression, down to half the
    // equilibrium distance (Mie n = 1e6 overflows right below a; Morse and harmonic with a
    // large kappa alpha a at r = a/2); a singular law is checked where its base is at a/2
    {
      double d[4];
      const double r = Law::singular ? c.a - 0.5 * c.a / c.kappa : 0.5 * c.a;
      kappa_derivs<Law>(c, r, d);
      for (int k = 0; k < 4; k++)
        if (!std::isfinite(d[k]))
          error->all(FLERR, "Pair {}: law of types {} {}{} overflows at r = {} ({}): '{}' gives "
                     "derivative {} = {} there", Law::style, i, j,
                     c.kappa == 1.0 ? "" : fmt::format(" with kappa {}", c.kappa),
                     c.kappa == 1.0 ? "a/2" : fmt::format("{:.6g} a", r / c.a),
                     Law::overflow_hint, Law::args(c), k, d[k]);
    }

    // inflection point b and bond strength f* of the kappa-modified base
    double b = 0.0, pib = 0.0, fstar = 0.0;
    if (Law::has_inflection) {
      const double b0 = Law::inflection(c);
      double d[4];
      Law::derivs(c, b0, d);
      b = c.a + (b0 - c.a) / c.kappa;
      pib = d[0];
      fstar = c.kappa * fabs(d[1]);
    }
    const TailShape shape{b, pib, fstar, rc_pair[i][j] > 0.0 ? rc_pair[i][j] : s.rc,
                          rs_pair[i][j] > 0.0 ? rs_pair[i][j] : s.rs, i, j};
    with_tail(s.tail, [&](auto t) { decltype(t)::template derive<Law>(c, shape, lmp); });
    c.cutsq = c.rc * c.rc;

    if (s.tail == CUT && offset_flag) {
      double d[4];
      Law::derivs(c, c.kappa * (c.rc - c.a) + c.a, d);
      c.offset = d[0];
    }
    if (links.on()) links.derive<Law>(c, s.tail, i, j, np1, lmp);
    if (Law::singular && c.kappa > 1.0) {    // in the chain: r/n at or inside that distance
      const double rh = c.a * (1.0 - 1.0 / c.kappa);
      c.hardsq = rh * rh;
    }
    coeffs[j * np1 + i] = c;
  }

  template <class Law> void SplineTable<Law>::write_restart(FILE *fp, int **setflag) const
  {
    for (int i = 1; i < np1; i++) {
      for (int j = i; j < np1; j++) {
        fwrite(&setflag[i][j], sizeof(int), 1, fp);
        if (setflag[i][j])
          for (auto *v : {d0, a0, p0, q0, kappa, rc_pair, rs_pair})
            fwrite(&v[i][j], sizeof(double), 1, fp);
      }
    }
  }

  template <class Law> void SplineTable<Law>::read_restart(FILE *fp, int **setflag)
  {
    const int me = comm->me;
    for (int i = 1; i < np1; i++) {
      for (int j = i; j < np1; j++) {
        if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
        MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
        if (setflag[i][j]) {
          for (auto *v : {d0, a0, p0, q0, kappa, rc_pair, rs_pair}) {
            if (me == 0) utils::sfread(FLERR, &v[i][j], sizeof(double), 1, fp, nullptr, error);
            MPI_Bcast(&v[i][j], 1, MPI_DOUBLE, 0, world);
          }
        }
      }
    }
  }

  // data files: the law's arguments, then every keyword explicitly
  template <class Law> void SplineTable<Law>::write_data(FILE *fp, bool all_pairs) const
  {
    for (int i = 1; i < np1; i++)
      for (int j = i; j < (all_pairs ? np1 : i + 1); j++) {
        SplineCoeff c{};
        c.d = d0[i][j];
        c.a = a0[i][j];
        c.p = p0[i][j];
        c.q = q0[i][j];
        std::string text = Law::args(c) + fmt::format(" kappa {}", kappa[i][j]);
        if (rc_pair[i][j] > 0.0) text += fmt::format(" rc {}", rc_pair[i][j]);
        if (rs_pair[i][j] > 0.0) text += fmt::format(" rs {}", rs_pair[i][j]);
        if (all_pairs) utils::print(fp, "{} {} {}\n", i, j, text);
        else utils::print(fp, "{} {}\n", i, text);
      }
  }

  // the per type pair arrays of extract() (dim 2)
  template <class Law> void *SplineTable<Law>::extract(const char *str) const
  {
    if (strcmp(str, "D") == 0) return (void *) d0;
    if (strcmp(str, "a") == 0) return (void *) a0;
    if (strcmp(str, "kappa") == 0) return (void *) kappa;
    if (strcmp(str, "C") == 0) return (void *) stiffness;
    if constexpr (Law::p_name != nullptr)
      if (strcmp(str, Law::p_name) == 0) return (void *) p0;
    if constexpr (Law::q_name != nullptr)
      if (strcmp(str, Law::q_name) == 0) return (void *) q0;
    return nullptr;
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
