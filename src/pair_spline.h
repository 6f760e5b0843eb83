/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair styles morse/spline, lj/spline,
   mie/spline, harmonic/spline (doc/pair_spline.rst).

   PairSpline<Law> is the LAMMPS interface: it parses the settings
   (spline_settings.h) and coefficients into its table (spline_table.h),
   writes them to restart and data files, and dispatches each force
   evaluation to the one kernel (spline_kernel.h), compiled per tail, mode
   and flags, so a scene pays only for what it uses.  The laws, tails and
   the link rule are stateless policies (spline_laws.h, spline_tails.h,
   spline_links.h); the link state is a PairState (pair_state.h).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_SPLINE_H
#define LMP_CLUSTERDYN_PAIR_SPLINE_H

#include "law_source.h"
#include "pair.h"
#include "pair_state.h"
#include "spline_kernel.h"
#include "spline_step_check.h"
#include "spline_table.h"

#include "force.h"

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
    void setup() override;
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
    double law_a(int i, int j) const override { return table.at(i, j).a; }
    double law_b(int i, int j) const override;

   protected:
    SplineSettings setting;                // pair_style
    SplineTable<Law> table;             // pair_coeff and the kernel data
    SplineLinks links;                  // link L: the rule
    PairState state;                    // link L: the state of each neighbour pair
    SplineStepCheck step_check;
    std::vector<double> chain_scale;    // 1/n^2 for n = 0..N (0 for n = 0)
    int kappa_any;                      // some pair has kappa != 1: the general kernel
    DampingPass *damping;               // the slot: fix viscous/relative's pass
                                        // (damping_pass.h), claimed at its init
    int listed;                         // this run's neighbour lists are made (setup)

    void allocate();
    void apply(const SplineSettings &s);
    SplineKernelData kernel_data(const DampingPass *fused = nullptr) const
    {
      return {table.coeffs, links.coeff.data(), links.making(), setting.chain_n,
              chain_scale.data(), fused};
    }
    // fix viscous/relative's pass on this step: offered, no tallies, and a kernel mode that damps
    // (dispatch: PLAIN and KAPPA; the slot outlives a pair_style line that sets chain or link)
    DampingPass *damping_this_step() const
    {
      return damping && damping->fd && !evflag && !links.on() && !setting.chain_n ? damping
                                                                                   : nullptr;
    }
    StatePass start_compute() { return links.on() ? state.begin() : StatePass(); }
    void finish_compute(const StateTally &changes);
    [[noreturn]] void singular_error(int i, int j, double rsq) const;

    // calls run(tail policy, mode, evflag, eflag, newton_pair, damp) with compile-time
    // constants; damp 1 (PLAIN and KAPPA modes) where fuse is set: a step without tallies
    template <class Run> void dispatch(int eflag, bool fuse, Run &&run) const;
  };

  template <class Law>
  template <class Run>
  void PairSpline<Law>::dispatch(int eflag, bool fuse, Run &&run) const
  {
    auto with_flags = [&](auto t, auto k) {
      using I0 = std::integral_constant<int, 0>;
      using I1 = std::integral_constant<int, 1>;
      constexpr int MODE = decltype(k)::value;
      if (evflag) {
        if (eflag) {
          if (force->newton_pair) run(t, k, I1(), I1(), I1(), I0());
          else run(t, k, I1(), I1(), I0(), I0());
        } else {
          if (force->newton_pair) run(t, k, I1(), I0(), I1(), I0());
          else run(t, k, I1(), I0(), I0(), I0());
        }
        return;
      }
      if constexpr (MODE == SplineMode::PLAIN || MODE == SplineMode::KAPPA) {
        if (fuse) {
          if (force->newton_pair) run(t, k, I0(), I0(), I1(), I1());
          else run(t, k, I0(), I0(), I0(), I1());
          return;
        }
      }
      if (force->newton_pair) run(t, k, I0(), I0(), I1(), I0());
      else run(t, k, I0(), I0(), I0(), I0());
    };
    using M = SplineMode;
    with_tail(setting.tail, [&](auto t) {
      if (setting.chain_n) return with_flags(t, std::integral_constant<int, M::CHAIN>());
      if constexpr (Law::kappa_kernel) {
        if (kappa_any) {
          if (links.on()) return with_flags(t, std::integral_constant<int, M::LINK_KAPPA>());
          return with_flags(t, std::integral_constant<int, M::KAPPA>());
        }
      }
      if (links.on()) return with_flags(t, std::integral_constant<int, M::LINK>());
      with_flags(t, std::integral_constant<int, M::PLAIN>());
    });
  }

  using PairMorseSpline = PairSpline<MorseLaw>;
  using PairLJSpline = PairSpline<LJLaw>;
  using PairMieSpline = PairSpline<MieLaw>;
  using PairHarmonicSpline = PairSpline<HarmonicLaw>;

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
