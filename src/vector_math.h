/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: glibc's vector math (libmvec) for
   the `#pragma omp simd` loops of the force kernels.

   glibc declares the vector variants of exp and pow only under -ffast-math;
   this declares them (as glibc's bits/math-vector.h does) so that a simd
   loop of the kernels calls _ZGV?N?v_exp / _ZGV?N?vv_pow (errors of at
   most 4 ulp) while the rest of the plugin keeps IEEE semantics.  Only
   with GCC on x86-64 glibc, where libmvec has these variants; elsewhere
   the loops call the scalar functions.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_VECTOR_MATH_H
#define LMP_CLUSTERDYN_VECTOR_MATH_H

#include <cmath>

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

#endif
