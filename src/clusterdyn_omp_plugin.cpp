/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the /omp variants of the pair styles,
   a plugin file of their own (clusterdyn_omp.so) because they need the
   OPENMP package's ThrOMP symbols.  clusterdynplugin.so loads it when the
   host LAMMPS has OPENMP, so that the core styles load everywhere.
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

#include "pair_spline_omp.h"
#include "register_style.h"

#include <string>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

namespace {

template <class Law> void add_spline_omp_style(const StyleRegistrar &styles)
{
  static const std::string name = std::string(Law::style) + "/omp";    // LAMMPS keeps the pointers
  static const std::string info = std::string("cluster-dynamics pair style ") + Law::style +
      " with OpenMP threads";
  styles.add<PairSplineOMP<Law>>(name.c_str(), info.c_str());
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  const StyleRegistrar styles(lmp, handle, regfunc);
  add_spline_omp_style<MorseLaw>(styles);
  add_spline_omp_style<LJLaw>(styles);
  add_spline_omp_style<MieLaw>(styles);
  add_spline_omp_style<HarmonicLaw>(styles);
}
