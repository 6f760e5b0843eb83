/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the choice of the force kernel's
   variant (spline_kernel.h) for one force evaluation of a spline pair
   style, serial or /omp.  What is known only at run time (tail, mode,
   energy/virial/newton flags, the damping pass) becomes the compile-time
   arguments of the one kernel, so a scene pays only for what it uses.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_DISPATCH_H
#define LMP_CLUSTERDYN_SPLINE_DISPATCH_H

#include "spline_kernel.h"
#include "spline_tails.h"

#include <type_traits>
#include <utility>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct SplineVariant {
    int tail;     // Tail
    int chain;    // chain N
    int kappa;    // some pair has kappa != 1 (the KAPPA modes where Law::kappa_kernel)
    int link;     // link L
    int evflag, eflag, newton_pair;
    bool fuse;    // fix viscous/relative's pass on this step (PLAIN and KAPPA modes)
  };

  // spline_kernel<Law, tail policy, mode, evflag, eflag, newton_pair, damp>(args...) of the
  // variant; damp 1 (PLAIN and KAPPA modes) where fuse is set: a step without tallies
  template <class Law, class... Args> void run_spline_kernel(const SplineVariant &v, Args &&...args)
  {
    using I0 = std::integral_constant<int, 0>;
    using I1 = std::integral_constant<int, 1>;
    auto run = [&](auto t, auto k, auto ev, auto e, auto n, auto d) {
      spline_kernel<Law, decltype(t), decltype(k)::value, decltype(ev)::value, decltype(e)::value,
                    decltype(n)::value, decltype(d)::value>(std::forward<Args>(args)...);
    };
    auto with_flags = [&](auto t, auto k) {
      constexpr int MODE = decltype(k)::value;
      if (v.evflag) {
        if (v.eflag) {
          if (v.newton_pair) run(t, k, I1(), I1(), I1(), I0());
          else run(t, k, I1(), I1(), I0(), I0());
        } else {
          if (v.newton_pair) run(t, k, I1(), I0(), I1(), I0());
          else run(t, k, I1(), I0(), I0(), I0());
        }
        return;
      }
      if constexpr (MODE == SplineMode::PLAIN || MODE == SplineMode::KAPPA) {
        if (v.fuse) {
          if (v.newton_pair) run(t, k, I0(), I0(), I1(), I1());
          else run(t, k, I0(), I0(), I0(), I1());
          return;
        }
      }
      if (v.newton_pair) run(t, k, I0(), I0(), I1(), I0());
      else run(t, k, I0(), I0(), I0(), I0());
    };
    using M = SplineMode;
    with_tail(v.tail, [&](auto t) {
      if (v.chain) return with_flags(t, std::integral_constant<int, M::CHAIN>());
      if constexpr (Law::kappa_kernel) {
        if (v.kappa) {
          if (v.link) return with_flags(t, std::integral_constant<int, M::LINK_KAPPA>());
          return with_flags(t, std::integral_constant<int, M::KAPPA>());
        }
      }
      if (v.link) return with_flags(t, std::integral_constant<int, M::LINK>());
      with_flags(t, std::integral_constant<int, M::PLAIN>());
    });
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
