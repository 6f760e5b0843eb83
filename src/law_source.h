/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the interface through which this
   package's pair styles give their interaction law analytically (used by
   compute pair/params; other pair styles are probed through single()).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_LAW_SOURCE_H
#define LMP_CLUSTERDYN_LAW_SOURCE_H

namespace LAMMPS_NS {
namespace ClusterDyn {

  class LawSource {
   public:
    // Pi, Pi', Pi'', Pi''' at r of the law of types i,j: with tail = true as the
    // pair style computes it (tail, shift), with tail = false the kappa-modified base
    virtual void law_derivs(int i, int j, double r, double *d, bool tail) const = 0;
    virtual double law_a(int i, int j) const = 0;    // equilibrium distance
    // inflection point b > a of the law (the base's unless a smooth tail starts
    // before it), 0 if there is none
    virtual double law_b(int i, int j) const = 0;

   protected:
    ~LawSource() = default;    // not deleted through this interface
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
