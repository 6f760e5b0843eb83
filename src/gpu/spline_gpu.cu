// **************************************************************************
//   Cluster-dynamics plugin for LAMMPS: the device kernels of the spline
//   pair styles (pair_style morse/spline/gpu and its kin), in the GPU
//   package's kernel dialect (lib/gpu: lal_preprocessor.h, lal_aux_fun1.h).
//
//   The host prepends the variant as defines (spline_gpu_device.cpp):
//     SPLINE_LAW   0 morse, 1 harmonic, 2 lj, 3 mie (spline_laws.h)
//     SPLINE_TAIL  0 cut, 1 wagner, 2 lagunov (spline_tails.h)
//     SPLINE_KAPPA 1 where some pair of lj or mie has kappa != 1 (morse and
//                  harmonic fold kappa into their constants)
//   so each style and tail runs a kernel with only its own law in it.
//   Per type pair (SplineCoeff of spline_laws.h, in the kernel's precision):
//     coef1 = (cutsq, c1, c2, w)     the interaction end and what the law's force needs:
//                                    w = a (morse, harmonic) or c3 = a^2 (lj, mie)
//     coef2 = (a, D, kappa, offset)  energies; kappa's argument (lj, mie)
//     coef3 = (n, m, 0, 0)           mie's exponents
//     tailc = wagner (b^2, ac^2, A2, A3), lagunov (Rs^2, Rs, 1/(Rc-Rs)^2, 0)
//   Formulas: doc/pair_spline.rst; the CPU kernel: spline_kernel.h.
//   k_spline reads the coefficients from global memory; k_spline_fast first
//   stages them in local memory (at most MAX_SHARED_TYPES types), as the
//   GPU package's own kernels do, only the tables its variant reads.  Both
//   run the same pair loop (spline_atom): a cut Morse pair without energy
//   reads coef1 alone, as stock morse/gpu reads its mor1.
// **************************************************************************

#if defined(NV_KERNEL) || defined(USE_HIP)
#include "lal_aux_fun1.h"
#ifndef _DOUBLE_DOUBLE
_texture( pos_tex,float4);
#else
_texture_2d( pos_tex,int4);
#endif
#else
#define pos_tex x_
#endif

// the law at rsq: energy e (unshifted) and fpair = f(r)/r of the kappa-modified base
#if (SPLINE_LAW == 0)
#define spline_law(k1, k2, k3, rsq, e, fpair)                                 \
  {                                                                           \
    numtyp r_ = ucl_sqrt(rsq);                                                \
    numtyp dexp_ = ucl_exp(-k1.y * (r_ - k1.w));                              \
    fpair = k1.z * (dexp_ * dexp_ - dexp_) / r_;                              \
    e = k2.y * (dexp_ * dexp_ - (numtyp)2.0 * dexp_);                         \
  }
#elif (SPLINE_LAW == 1)
#define spline_law(k1, k2, k3, rsq, e, fpair)                                 \
  {                                                                           \
    numtyp r_ = ucl_sqrt(rsq);                                                \
    numtyp dr_ = r_ - k1.w;                                                   \
    fpair = -k1.z * dr_ / r_;                                                 \
    e = k1.y * dr_ * dr_ - k2.y;                                              \
  }
#elif (SPLINE_LAW == 2) && SPLINE_KAPPA
#define spline_law(k1, k2, k3, rsq, e, fpair)                                 \
  {                                                                           \
    numtyp r_ = ucl_sqrt(rsq);                                                \
    numtyp u_ = k2.x / (k2.z * (r_ - k2.x) + k2.x);                           \
    numtyp x6_ = u_ * u_ * u_ * u_ * u_ * u_;                                 \
    fpair = k2.z * k1.y * k2.x * u_ * x6_ * (x6_ - (numtyp)1.0) / r_;         \
    e = k2.y * x6_ * (x6_ - (numtyp)2.0);                                     \
  }
#elif (SPLINE_LAW == 2)
#define spline_law(k1, k2, k3, rsq, e, fpair)                                 \
  {                                                                           \
    numtyp x2_ = k1.w / rsq;                                                  \
    numtyp x6_ = x2_ * x2_ * x2_;                                             \
    fpair = k1.y * x2_ * x6_ * (x6_ - (numtyp)1.0);                           \
    e = k2.y * x6_ * (x6_ - (numtyp)2.0);                                     \
  }
#elif (SPLINE_LAW == 3) && SPLINE_KAPPA
#define spline_law(k1, k2, k3, rsq, e, fpair)                                 \
  {                                                                           \
    numtyp r_ = ucl_sqrt(rsq);                                                \
    numtyp u_ = k2.x / (k2.z * (r_ - k2.x) + k2.x);                           \
    numtyp xn_ = ucl_powr(u_, k3.x), xm_ = ucl_powr(u_, k3.y);                \
    fpair = k2.z * k1.z / k2.x * u_ * (xn_ - xm_) / r_;                       \
    e = k1.y * (k3.y * xn_ - k3.x * xm_);                                     \
  }
#else
#define spline_law(k1, k2, k3, rsq, e, fpair)                                 \
  {                                                                           \
    numtyp x2_ = k1.w / rsq;                                                  \
    numtyp xn_ = ucl_powr(x2_, (numtyp)0.5 * k3.x);                           \
    numtyp xm_ = ucl_powr(x2_, (numtyp)0.5 * k3.y);                           \
    fpair = k1.z * (xn_ - xm_) / rsq;                                         \
    e = k1.y * (k3.y * xn_ - k3.x * xm_);                                     \
  }
#endif

// the law with its tail at rsq < cutsq: e (unshifted) and fpair
#if (SPLINE_TAIL == 1)
#define spline_tail(k1, k2, k3, kt, rsq, e, fpair)                            \
  {                                                                           \
    spline_law(k1, k2, k3, rsq, e, fpair);                                    \
    if (rsq >= kt.x) {                                                        \
      numtyp w_ = kt.y - rsq;                                                 \
      fpair = (numtyp)2.0 * w_ * ((numtyp)3.0 * kt.w * w_ - (numtyp)2.0 * kt.z); \
      e = w_ * w_ * (kt.w * w_ - kt.z);                                       \
    }                                                                         \
  }
#elif (SPLINE_TAIL == 2)
#define spline_tail(k1, k2, k3, kt, rsq, e, fpair)                            \
  {                                                                           \
    spline_law(k1, k2, k3, rsq, e, fpair);                                    \
    if (rsq >= kt.x) {                                                        \
      numtyp r_ = ucl_sqrt(rsq);                                              \
      numtyp u_ = r_ - kt.y;                                                  \
      numtyp m_ = (numtyp)1.0 - u_ * u_ * kt.z;                               \
      fpair = m_ * (fpair * m_ + (numtyp)4.0 * u_ * kt.z * e / r_);           \
      e = e * m_ * m_;                                                        \
    }                                                                         \
  }
#else
#define spline_tail(k1, k2, k3, kt, rsq, e, fpair) spline_law(k1, k2, k3, rsq, e, fpair)
#endif

// atom ii's force, energy and virial over its neighbours (after the block's tables are staged),
// stored in the answers
#define spline_atom(coef1, coef2, coef3, tailc, ntypes_row)                   \
  acctyp3 f;                                                                  \
  f.x = (acctyp)0; f.y = (acctyp)0; f.z = (acctyp)0;                          \
  acctyp energy, virial[6];                                                   \
  if (EVFLAG) {                                                               \
    energy = (acctyp)0;                                                       \
    for (int v = 0; v < 6; v++) virial[v] = (acctyp)0;                        \
  }                                                                           \
  __syncthreads();                                                            \
  if (ii < inum) {                                                            \
    int nbor, nbor_end;                                                       \
    int i, numj;                                                              \
    nbor_info(dev_nbor, dev_packed, nbor_pitch, t_per_atom, ii, offset, i,    \
              numj, n_stride, nbor_end, nbor);                                \
    numtyp4 ix; fetch4(ix, i, pos_tex);                                       \
    int itype = ix.w;                                                         \
    for ( ; nbor < nbor_end; nbor += n_stride) {                              \
      ucl_prefetch(dev_packed + nbor + n_stride);                             \
      int j = dev_packed[nbor];                                               \
      numtyp factor_lj = sp_lj[sbmask(j)];                                    \
      j &= NEIGHMASK;                                                         \
      numtyp4 jx; fetch4(jx, j, pos_tex);                                     \
      int jtype = jx.w;                                                       \
      numtyp delx = ix.x - jx.x;                                              \
      numtyp dely = ix.y - jx.y;                                              \
      numtyp delz = ix.z - jx.z;                                              \
      numtyp rsq = delx * delx + dely * dely + delz * delz;                   \
      int mtype = itype * ntypes_row + jtype;                                 \
      numtyp4 k1 = coef1[mtype];                                              \
      if (rsq < k1.x) {                                                       \
        numtyp4 k2 = coef2[mtype];                                            \
        numtyp4 k3 = coef3[mtype];                                            \
        numtyp4 kt = tailc[mtype];                                            \
        numtyp e, fpair;                                                      \
        spline_tail(k1, k2, k3, kt, rsq, e, fpair);                           \
        fpair *= factor_lj;                                                   \
        f.x += delx * fpair;                                                  \
        f.y += dely * fpair;                                                  \
        f.z += delz * fpair;                                                  \
        if (EVFLAG && eflag) energy += factor_lj * (e - k2.w);                \
        if (EVFLAG && vflag) {                                                \
          virial[0] += delx * delx * fpair;                                   \
          virial[1] += dely * dely * fpair;                                   \
          virial[2] += delz * delz * fpair;                                   \
          virial[3] += delx * dely * fpair;                                   \
          virial[4] += delx * delz * fpair;                                   \
          virial[5] += dely * delz * fpair;                                   \
        }                                                                     \
      }                                                                       \
    }                                                                         \
  }                                                                           \
  store_answers(f, energy, virial, ii, inum, tid, t_per_atom, offset, eflag, vflag, ans, engv)

__kernel void k_spline(const __global numtyp4 *restrict x_,
                       const __global numtyp4 *restrict coef1,
                       const __global numtyp4 *restrict coef2,
                       const __global numtyp4 *restrict coef3,
                       const __global numtyp4 *restrict tailc,
                       const int ntypes_row,
                       const __global numtyp *restrict sp_lj_in,
                       const __global int *dev_nbor,
                       const __global int *dev_packed,
                       __global acctyp3 *restrict ans,
                       __global acctyp *restrict engv,
                       const int eflag, const int vflag, const int inum,
                       const int nbor_pitch, const int t_per_atom) {
  int tid, ii, offset;
  atom_info(t_per_atom, ii, tid, offset);

  __local numtyp sp_lj[4];
  int n_stride;
  local_allocate_store_pair();

  if (tid < 4) sp_lj[tid] = sp_lj_in[tid];


  spline_atom(coef1, coef2, coef3, tailc, ntypes_row);
}

__kernel void k_spline_fast(const __global numtyp4 *restrict x_,
                            const __global numtyp4 *restrict coef1_in,
                            const __global numtyp4 *restrict coef2_in,
                            const __global numtyp4 *restrict coef3_in,
                            const __global numtyp4 *restrict tailc_in,
                            const __global numtyp *restrict sp_lj_in,
                            const __global int *dev_nbor,
                            const __global int *dev_packed,
                            __global acctyp3 *restrict ans,
                            __global acctyp *restrict engv,
                            const int eflag, const int vflag, const int inum,
                            const int nbor_pitch, const int t_per_atom) {
  int tid, ii, offset;
  atom_info(t_per_atom, ii, tid, offset);

  __local numtyp4 coef1[MAX_SHARED_TYPES * MAX_SHARED_TYPES];
  __local numtyp4 coef2[MAX_SHARED_TYPES * MAX_SHARED_TYPES];
  __local numtyp4 coef3[MAX_SHARED_TYPES * MAX_SHARED_TYPES];
  __local numtyp4 tailc[MAX_SHARED_TYPES * MAX_SHARED_TYPES];
  __local numtyp sp_lj[4];
  int n_stride;
  local_allocate_store_pair();

  if (tid < 4) sp_lj[tid] = sp_lj_in[tid];
  for (int t = tid; t < MAX_SHARED_TYPES * MAX_SHARED_TYPES; t += BLOCK_SIZE_X) {
    coef1[t] = coef1_in[t];
#if EVFLAG || SPLINE_KAPPA || (SPLINE_TAIL == 2)
    coef2[t] = coef2_in[t];
#endif
#if (SPLINE_LAW == 3)
    coef3[t] = coef3_in[t];
#endif
#if (SPLINE_TAIL != 0)
    tailc[t] = tailc_in[t];
#endif
  }


  spline_atom(coef1, coef2, coef3, tailc, MAX_SHARED_TYPES);
}
