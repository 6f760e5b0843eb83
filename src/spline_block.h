/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: a packed block of neighbour pairs,
   the vector stage of the spline force kernel (spline_kernel.h).

   The kernel copies up to SIZE list entries into the block with their
   separations and rsq (a scalar loop: the positions of the partners are
   read as the list orders them), then one `#pragma omp simd` loop over the
   block computes the law with its tail for every pair: energy and fpair
   inside the interaction end, zero outside.
   The exponentials and powers of that loop are glibc's vector math
   (libmvec, vector_math.h); the vector width is the compiler's for the
   instruction set the plugin is built for (CMake option
   CLUSTERDYN_SIMD_ARCH, doc/Build.rst).  The
   kernel then scatters the forces, tallies and applies the link rule in
   list order, one pair at a time.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_BLOCK_H
#define LMP_CLUSTERDYN_SPLINE_BLOCK_H

#include "damping_pass.h"
#include "spline_tails.h"
#include "vector_math.h"
#include "xyz3.h"

#include "lmptype.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct SplineBlock {
    static constexpr int SIZE = 128;    // pairs per block (doc/benchmarks/bench_pair_spline.md)

    // filled by the kernel, one list entry after another
    alignas(64) int i[SIZE];
    alignas(64) int jraw[SIZE];    // the list entry: j with its special bits
    alignas(64) int jj[SIZE];      // link L: the entry's place in i's list (state words)
    alignas(64) int tp[SIZE];      // the type pair: type[i] * (ntypes + 1) + type[j]
    alignas(64) double delx[SIZE], dely[SIZE], delz[SIZE];
    alignas(64) double rsq[SIZE];     // of the law: chain N scales it by 1/n^2
    alignas(64) double scale[SIZE];   // chain N: 1/n^2
    int n = 0;
    // written by compute()
    alignas(64) double fpair[SIZE];   // f(r)/r of the law with its tail (0 outside its end)
    alignas(64) double e[SIZE];       // its energy, shifted (0 outside)
    // fix viscous/relative's damping in the pass (damping_pass.h): v_i - v_j, filled by the
    // kernel, and the damping force on i, written by damp()
    alignas(64) double dvx[SIZE], dvy[SIZE], dvz[SIZE];
    alignas(64) double dfx[SIZE], dfy[SIZE], dfz[SIZE];

    // the vector stage: the law with its tail at every rsq; UNIFORM: every pair has the
    // coefficients c0 (one atom type), else those of tp.  Pairs beyond the interaction end
    // (only with link state) are zeroed.  The loop and the tails hold no branch: every
    // choice is a blend (vector_math.h), which GCC 12 vectorizes with AVX2 as with AVX-512
    // (a `?:` of computed values or an `if` it vectorizes only with AVX-512's masks).
    // Every block is computed whole, the entries past n padded with the first one: a pair's
    // values never come from a scalar remainder loop (scalar exp differs from libmvec's in
    // the last bits), so they do not depend on where in a block the pair falls.
    // (not inlined: inside the kernel's loops GCC 12 leaves some instances scalar)
    template <class Law, class TailT, bool KAPPA, bool UNIFORM>
    __attribute__((noinline)) void compute(const SplineCoeff *_noalias coeffs, int ntp1)
    {
      const SplineCoeff &c0 = coeffs[ntp1 + 1];
      for (int k = n; k < SIZE; k++) {
        rsq[k] = rsq[0];
        tp[k] = tp[0];
      }
#pragma omp simd
      for (int k = 0; k < SIZE; k++) {
        const SplineCoeff &c = UNIFORM ? c0 : coeffs[tp[k]];
        const double r2 = rsq[k];
        const bool inside = r2 < c.cutsq;
        double fp;
        const double en = TailT::template eval<KAPPA, Law, true>(c, r2, fp);
        fpair[k] = blend(inside, fp, 0.0);
        e[k] = blend(inside, en - c.offset, 0.0);
      }
    }

    // the damping forces of the block's pairs (all inside the interaction end), padded as
    // compute() pads
    template <bool NORMAL, bool DPD, bool UNIFORM>
    __attribute__((noinline)) void damp(const DampingCoeff *_noalias dcoeffs,
                                        const SplineCoeff *_noalias coeffs, int ntp1)
    {
      for (int k = n; k < SIZE; k++) {
        delx[k] = delx[0];
        dely[k] = dely[0];
        delz[k] = delz[0];
        dvx[k] = dvx[0];
        dvy[k] = dvy[0];
        dvz[k] = dvz[0];
      }
      const DampingCoeff &d0 = dcoeffs[ntp1 + 1];
      const double cutsq0 = coeffs[ntp1 + 1].cutsq;
#pragma omp simd
      for (int k = 0; k < SIZE; k++) {
        const DampingCoeff &d = UNIFORM ? d0 : dcoeffs[tp[k]];
        damping_force<NORMAL, DPD>(d.coef, d.inv_cut, rsq[k], UNIFORM ? cutsq0 : coeffs[tp[k]].cutsq,
                                   dvx[k], dvy[k], dvz[k], delx[k], dely[k], delz[k], dfx[k],
                                   dfy[k], dfz[k]);
      }
    }

    // damp() with the pass's mode and weight
    template <bool UNIFORM>
    void damp(const DampingPass &pass, const SplineCoeff *coeffs, int ntp1)
    {
      if (pass.normal) {
        if (pass.dpd) damp<true, true, UNIFORM>(pass.coeff, coeffs, ntp1);
        else damp<true, false, UNIFORM>(pass.coeff, coeffs, ntp1);
      } else {
        if (pass.dpd) damp<false, true, UNIFORM>(pass.coeff, coeffs, ntp1);
        else damp<false, false, UNIFORM>(pass.coeff, coeffs, ntp1);
      }
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
