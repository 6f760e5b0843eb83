/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair styles morse/spline, lj/spline,
   mie/spline, harmonic/spline (doc/pair_spline.rst).

   PairSpline<Law> holds what every law shares: the tail (cut, wagner,
   lagunov), the kappa modification, coefficients, restart, data files,
   single(), born_matrix() and extract().  The force loop is compiled per
   tail and per mode (every kappa 1, some kappa != 1, chain N, link L), so a
   scene pays only for what it uses.  With link L the pair state (linked or
   not) is the flag fix neigh/history keeps per neighbour pair.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_SPLINE_H
#define LMP_CLUSTERDYN_PAIR_SPLINE_H

#include "atom.h"
#include "force.h"
#include "law_source.h"
#include "pair.h"
#include "spline_laws.h"

#include <type_traits>
#include <vector>

namespace LAMMPS_NS {
class FixNeighHistory;
namespace ClusterDyn {

  enum Tail { CUT = 0, WAGNER = 1, LAGUNOV = 2 };

  // view of the x and f arrays as packed triplets (as OPT and OPENMP do)
  struct xyz3 {
    double x, y, z;
  };

  // energy and fpair of a pair inside the cutoff (rsq < c.cutsq), unshifted

  template <int TAIL, bool KAPPA, class Law>
  inline double tail_eval(const SplineCoeff &c, double rsq, double &fpair)
  {
    if (TAIL == WAGNER && rsq >= c.bsq) {
      const double w = c.acsq - rsq;
      fpair = 2.0 * w * (3.0 * c.wa3 * w - 2.0 * c.wa2);
      return w * w * (c.wa3 * w - c.wa2);
    }
    if (TAIL == LAGUNOV && rsq >= c.rssq) {
      const double r = sqrt(rsq);
      double fbase;
      const double e = Law::template eval<KAPPA>(c, rsq, fbase);
      const double x = r - c.rs;
      const double m = 1.0 - x * x * c.inv_l2;
      fpair = m * (fbase * m + 4.0 * x * c.inv_l2 * e / r);
      return e * m * m;
    }
    return Law::template eval<KAPPA>(c, rsq, fpair);
  }

  // link L: what the state changes of one kernel pass add up to (a pair with a ghost
  // counts 1/2 with newton off, as both processors see it)
  struct LinkTally {
    double broken = 0.0;    // links broken
    double formed = 0.0;    // links formed by relink
    double ejump = 0.0;     // sum of the pair-energy jumps of those changes
  };
  enum Linking { LINK_KEEP = 0, LINK_INITIAL = 1, LINK_RELINK = 2 };

  // energy (shifted) and fpair of a pair under the link model, updating its state;
  // false when the pair does not interact.  Linked: the full law and tail up to Rc a,
  // where the link breaks for good.  Unlinked: the repulsive branch r < a, zero at a.
  template <int TAIL, bool KAPPA, class Law>
  inline bool link_eval(const SplineCoeff &c, double rsq, int &linked, int linking, double w,
                        LinkTally &t, double &e, double &fpair)
  {
    if (linked) {
      if (rsq >= c.cutsq) {
        linked = 0;
        t.broken += w;
        t.ejump -= w * c.ebreak;
        return false;
      }
    } else if (linking != LINK_KEEP && rsq < c.linksq) {
      linked = 1;
      if (linking == LINK_RELINK) {
        double f;
        const double eu = rsq < c.asq ? Law::template eval<KAPPA>(c, rsq, f) - c.ea : 0.0;
        t.formed += w;
        t.ejump += w * (tail_eval<TAIL, KAPPA, Law>(c, rsq, f) - c.offset - eu);
      }
    }
    if (linked) {
      e = tail_eval<TAIL, KAPPA, Law>(c, rsq, fpair) - c.offset;
      return true;
    }
    if (rsq >= c.asq) return false;
    e = Law::template eval<KAPPA>(c, rsq, fpair) - c.ea;
    return true;
  }

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

    // link L (0 = off): pair state kept by fix neigh/history, its flag per neighbour pair
    double link_l;
    int relink;                          // unlinked pairs closer than L a link again
    int links_made;                      // the first run's setup has linked the pairs
    LAMMPS_NS::FixNeighHistory *fix_history;  // replaces the dummy fix at the first init
    LinkTally link_total;                // this processor's share since the links were made
    static constexpr const char *LINK_FIX_ID = "NEIGH_HISTORY_LINK";
    int linking_now() const;             // Linking of this compute() call
    void link_done(const LinkTally &pass);
    void link_settings_changed(double new_l);
    void consolidate_link_total();       // every processor's share onto processor 0

    void allocate();
    void set_chain_scale();
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

    // energy (shifted) and fpair of a pair at rsq_law, the law's argument squared (with link:
    // updating the pair's flag linked, weight w in the tallies); false: no interaction.
    // The serial and /omp kernels share it.
    template <int TAIL, int MODE>
    static bool pair_eval(const SplineCoeff &c, double rsq_law, int *linked, int linking, double w,
                          LinkTally &t, double &e, double &fpair)
    {
      if constexpr (mode_link(MODE)) {
        return link_eval<TAIL, mode_kappa(MODE), Law>(c, rsq_law, *linked, linking, w, t, e, fpair);
      } else {
        if (rsq_law >= c.cutsq) return false;
        e = tail_eval<TAIL, mode_kappa(MODE), Law>(c, rsq_law, fpair) - c.offset;
        return true;
      }
    }
    // calls run(tail, mode, evflag, eflag, newton_pair) with compile-time constants
    template <class Run> void dispatch(int eflag, Run &&run) const;

   private:
    template <int TAIL, int MODE, int EVFLAG, int EFLAG, int NEWTON_PAIR> void eval(LinkTally &);
  };

  template <class Law>
  template <class Run>
  void PairSpline<Law>::dispatch(int eflag, Run &&run) const
  {
    auto with_kappa = [&](auto t, auto k) {
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
    auto with_tail = [&](auto t) {
      if (chain_n) return with_kappa(t, std::integral_constant<int, CHAIN>());
      if constexpr (Law::kappa_kernel) {
        if (kappa_any) {
          if (link_l > 0.0) return with_kappa(t, std::integral_constant<int, LINK_KAPPA>());
          return with_kappa(t, std::integral_constant<int, KAPPA>());
        }
      }
      if (link_l > 0.0) return with_kappa(t, std::integral_constant<int, LINK>());
      with_kappa(t, std::integral_constant<int, PLAIN>());
    };
    if (tail == CUT) with_tail(std::integral_constant<int, CUT>());
    else if (tail == WAGNER) with_tail(std::integral_constant<int, WAGNER>());
    else with_tail(std::integral_constant<int, LAGUNOV>());
  }

  using PairMorseSpline = PairSpline<MorseLaw>;
  using PairLJSpline = PairSpline<LJLaw>;
  using PairMieSpline = PairSpline<MieLaw>;
  using PairHarmonicSpline = PairSpline<HarmonicLaw>;

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
