/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair styles morse/spline, lj/spline,
   mie/spline, harmonic/spline (doc/pair_spline.rst).

   PairSpline<Law> is the LAMMPS interface: it parses the settings
   (spline_settings.h) and coefficients into its table (spline_table.h),
   writes them to restart and data files, and runs each force evaluation
   in the one kernel (spline_kernel.h), in the variant of its tail, mode
   and flags (spline_dispatch.h), so a scene pays only for what it uses.
   The laws, tails and the link rule are stateless policies (spline_laws.h,
   spline_tails.h, spline_links.h; one pair's law outside the force loop:
   spline_pair_law.h); the link state is a PairState (pair_state.h).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_SPLINE_H
#define LMP_CLUSTERDYN_PAIR_SPLINE_H

#include "law_source.h"
#include "pair.h"
#include "pair_state.h"
#include "spline_dispatch.h"
#include "spline_pair_law.h"
#include "spline_step_check.h"
#include "spline_table.h"

#include "force.h"

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

    void law_derivs(int i, int j, double r, double *d, bool tail) const override
    {
      pair_law_derivs<Law>(table.at(i, j), setting.tail, r, d, tail);
    }
    double law_a(int i, int j) const override { return table.at(i, j).a; }
    double law_b(int i, int j) const override
    {
      return pair_law_inflection<Law>(table.at(i, j), setting.tail);
    }

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
    void check_run();
    void derive_table();
    SplineKernelData kernel_data(const DampingPass *fused = nullptr) const
    {
      return {table.coeffs, links.coeff.data(), links.making(), setting.chain_n,
              chain_scale.data(), fused};
    }
    // the kernel variant of this step; fuse: fix viscous/relative's pass (damping_this_step)
    SplineVariant variant(int eflag, bool fuse) const
    {
      return {setting.tail, setting.chain_n, kappa_any, links.on(), evflag, eflag,
              force->newton_pair, fuse};
    }
    // fix viscous/relative's pass on this step: offered, no tallies, and a kernel mode that damps
    // (PLAIN and KAPPA; the slot outlives a pair_style line that sets chain or link)
    DampingPass *damping_this_step() const
    {
      return damping && damping->fd && !evflag && !links.on() && !setting.chain_n ? damping
                                                                                   : nullptr;
    }
    StatePass start_compute() { return links.on() ? state.begin() : StatePass(); }
    void finish_compute(const StateTally &changes);
    [[noreturn]] void singular_error(int i, int j, double rsq) const;
  };

  using PairMorseSpline = PairSpline<MorseLaw>;
  using PairLJSpline = PairSpline<LJLaw>;
  using PairMieSpline = PairSpline<MieLaw>;
  using PairHarmonicSpline = PairSpline<HarmonicLaw>;

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
