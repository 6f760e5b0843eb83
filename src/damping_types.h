/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative's tables per
   type pair: the damping range (the pair style's cutoff, or the cutoff
   keyword), the stiffness C of style J (the pair style's extract "C"),
   and the coefficients of the pass (damping_pass.h) for per-type masses.
   Filled at the fix's init and, under fix adapt, before each of its loops.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_DAMPING_TYPES_H
#define LMP_CLUSTERDYN_DAMPING_TYPES_H

#include "damping_pass.h"
#include "viscous_settings.h"

#include "pointers.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  class DampingTypes : protected Pointers {
   public:
    struct TypePair {
      double cutsq;        // damping range, squared
      double stiffness;    // C_ij from the pair style (J style)
    };

    DampingTypes(LAMMPS *lmp, const ViscousSettings &opt);
    ~DampingTypes();
    DampingTypes(const DampingTypes &) = delete;
    DampingTypes &operator=(const DampingTypes &) = delete;

    void fill();
    const TypePair *row(int itype) const { return typepair + itype * np1; }
    const DampingCoeff *coeff_row(int itype) const { return coeff + itype * np1; }
    const DampingCoeff *coeffs() const { return coeff; }
    double rate(const TypePair &tp, double mij) const;                  // G_ij (1/time)
    double friction(const TypePair &tp, double mi, double mj) const;    // m_ij G_ij / ftm2v
    double memory_usage() const;

   private:
    const ViscousSettings &opt;
    int np1;
    TypePair *typepair;     // (ntypes+1)^2
    DampingCoeff *coeff;    // (ntypes+1)^2: m_ij G_ij / ftm2v (per-type masses), 1 / range
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
