/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: glibc's vector math (libmvec) for
   the `#pragma omp simd` loops of the force kernels, and blend(), the
   choice those loops make without a branch.

   glibc declares the vector variants of exp and pow only under -ffast-math;
   this declares them (as glibc's bits/math-vector.h does) so that a simd
   loop of the kernels calls _ZGV?N?v_exp / _ZGV?N?vv_pow (errors of at
   most 4 ulp) while the rest of the plugin keeps IEEE semantics.  Only
   with GCC on x86-64 glibc, where libmvec has these variants; elsewhere
   the loops call the scalar functions.

   blend(a, x, y) is a ? x : y by bit masks.  GCC 12 turns a `?:` of two
   computed doubles into a branch that computes each in its own arm; with
   -ftrapping-math (the default) it then vectorizes the loop only with
   AVX-512's masked arithmetic and leaves it scalar with AVX2.  The masks
   are integers, which cannot trap: AVX2 vectorizes them too (a blend).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_VECTOR_MATH_H
#define LMP_CLUSTERDYN_VECTOR_MATH_H

#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__GLIBC__) && \
    !defined(__FAST_MATH__) && !defined(CLUSTERDYN_NO_LIBMVEC)
extern "C" {
double exp(double) noexcept __attribute__((__simd__("notinbranch")));
double pow(double, double) noexcept __attribute__((__simd__("notinbranch")));
}
#define CLUSTERDYN_LIBMVEC 1
#else
#define CLUSTERDYN_LIBMVEC 0
#endif

namespace LAMMPS_NS {
namespace ClusterDyn {

  // a ? x : y, branch-free (both computed)
  inline double blend(bool a, double x, double y)
  {
    const uint64_t mask = -static_cast<uint64_t>(a);
    uint64_t bx, by;
    memcpy(&bx, &x, sizeof bx);
    memcpy(&by, &y, sizeof by);
    const uint64_t bits = (bx & mask) | (by & ~mask);
    double out;
    memcpy(&out, &bits, sizeof out);
    return out;
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
