/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair styles morse/spline, lj/spline,
   mie/spline, harmonic/spline (doc/pair_spline.rst).

   PairSpline<Law> keeps the coefficients (per type pair input and the
   packed kernel data), their I/O (restart, data files, extract) and the
   dispatch to the one force kernel (pair_spline_kernel.h), compiled per
   tail, per mode (every kappa 1, some kappa != 1, chain N, link L) and per
   energy/virial/newton flags, so a scene pays only for what it uses.  The
   laws (spline_laws.h), tails (spline_tails.h) and the link rule
   (spline_links.h) are stateless policies; the link state is a PairState
   (pair_state.h).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_SPLINE_H
#define LMP_CLUSTERDYN_PAIR_SPLINE_H

#include "atom.h"
#include "force.h"
#include "law_source.h"
#include "pair.h"
#include "pair_state.h"
#include "spline_laws.h"
#include "spline_links.h"
#include "spline_tails.h"
#include "xyz3.h"

#include <type_traits>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  template <class Law> class PairSpline : public Pair, public LawSource {
   public:
    PairSpline(class LAMMPS *);
    ~PairSpline() override;

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
    double single(int, int, int, int, double, double, double, double &) override;
    void born_matrix(int, int, int, int, double, double, double, double &, double &) override;
    void *extract(const char *, int &) override;
    double memory_usage() override;

    void law_derivs(int i, int j, double r, double *d, bool tail) const override;
    double law_a(int i, int j) const override { return pair_coeff(i, j).a; }
    double law_b(int i, int j) const override;

   protected:
    int tail;                   // Tail
    double rc_global;           // tail end in units of a (cut, lagunov)
    double rs_global;           // lagunov start in units of a; 0 = the inflection point b

    // per type pair input, as given (the LAMMPS interface: extract, restart, data)
    double **d0, **a0, **p0, **q0, **kappa, **rc_pair, **rs_pair;    // rc, rs: 0 = global
    double **cut;
    double **stiffness;         // C = Pi''(a) of the kappa-modified law (extract "C")

    SplineCoeff *coeffs;        // (ntypes+1)^2 packed kernel data
    int kappa_any;              // some pair has kappa != 1: use the general kernel
    int chain_n;                // chain N: pairs up to N apart in atom ID, Pi(r/n); 0 = off
    std::vector<double> chain_scale;    // 1/n^2 for n = 0..N (0 for n = 0)
    static constexpr int MAX_CHAIN = 1000;
    int step_warned;            // the time-step warning was given (once per pair style)
    bigint step_next_check;     // no check before this step (except at a run's setup)
    static constexpr int STEP_CHECK_EVERY = 20;

    SplineLinks links;          // link L: the rule
    PairState state;            // link L: the state of each neighbour pair

    void allocate();
    void set_chain_scale();
    void set_links(double l, int relink);
    void finish_compute(const StateTally &changes);
    void check_time_step();    // on steps that rebuilt the neighbor list (doc: time step)
    void check_skin() const;
    void derive(int i, int j);    // checks and fills coeffs for i,j; errors name the pair
    const SplineCoeff &pair_coeff(int itype, int jtype) const
    {
      return coeffs[itype * (atom->ntypes + 1) + jtype];
    }
    [[noreturn]] void singular_error(int i, int j, double rsq) const;
    std::string data_args(int i, int j) const;

    // kernel variants: PLAIN (every kappa 1), KAPPA (some kappa != 1), CHAIN (chain N),
    // LINK and LINK_KAPPA (link L)
    enum Mode { PLAIN = 0, KAPPA = 1, CHAIN = 2, LINK = 3, LINK_KAPPA = 4 };
    static constexpr bool mode_kappa(int mode) { return mode != PLAIN && mode != LINK; }
    static constexpr bool mode_link(int mode) { return mode == LINK || mode == LINK_KAPPA; }

    // calls run(tail policy, mode, evflag, eflag, newton_pair) with compile-time constants
    template <class Run> void dispatch(int eflag, Run &&run) const;

    // the force kernel of the serial and /omp styles (pair_spline_kernel.h): the pairs of
    // list entries iifrom..iito-1, forces into f, energy and virial through tally
    template <class TailT, int MODE, int EVFLAG, int EFLAG, int NEWTON_PAIR, class Tally>
    void eval(int iifrom, int iito, xyz3 *f, const StatePass &pass, StateTally &changes,
              Tally &&tally) const;
  };

  template <class Law>
  template <class Run>
  void PairSpline<Law>::dispatch(int eflag, Run &&run) const
  {
    auto with_flags = [&](auto t, auto k) {
      using I0 = std::integral_constant<int, 0>;
      using I1 = std::integral_constant<int, 1>;
      if (evflag) {
        if (eflag) {
          if (force->newton_pair) run(t, k, I1(), I1(), I1());
          else run(t, k, I1(), I1(), I0());
        } else {
          if (force->newton_pair) run(t, k, I1(), I0(), I1());
          else run(t, k, I1(), I0(), I0());
        }
      } else {
        if (force->newton_pair) run(t, k, I0(), I0(), I1());
        else run(t, k, I0(), I0(), I0());
      }
    };
    with_tail(tail, [&](auto t) {
      if (chain_n) return with_flags(t, std::integral_constant<int, CHAIN>());
      if constexpr (Law::kappa_kernel) {
        if (kappa_any) {
          if (links.on()) return with_flags(t, std::integral_constant<int, LINK_KAPPA>());
          return with_flags(t, std::integral_constant<int, KAPPA>());
        }
      }
      if (links.on()) return with_flags(t, std::integral_constant<int, LINK>());
      with_flags(t, std::integral_constant<int, PLAIN>());
    });
  }

  using PairMorseSpline = PairSpline<MorseLaw>;
  using PairLJSpline = PairSpline<LJLaw>;
  using PairMieSpline = PairSpline<MieLaw>;
  using PairHarmonicSpline = PairSpline<HarmonicLaw>;

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
