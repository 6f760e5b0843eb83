/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the /omp variants of the pair styles,
   a plugin file of their own (clusterdyn_omp.so) because they need the
   OPENMP package's ThrOMP symbols.  clusterdynplugin.so loads it when the
   host LAMMPS has OPENMP, so that the core styles load everywhere.
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

#include "pair_spline_omp.h"
#include "register_pair.h"

#include <string>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

namespace {

template <class Law>
void register_pair_omp(void *lmp, void *handle, lammpsplugin_regfunc register_plugin)
{
  static const std::string name = std::string(Law::style) + "/omp";    // LAMMPS keeps the pointers
  static const std::string info = std::string("cluster-dynamics pair style ") + Law::style +
      " with OpenMP threads";
  register_pair_class<PairSplineOMP<Law>>(name.c_str(), info.c_str(), lmp, handle,
                                           register_plugin);
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto register_plugin = (lammpsplugin_regfunc) regfunc;
  register_pair_omp<MorseLaw>(lmp, handle, register_plugin);
  register_pair_omp<LJLaw>(lmp, handle, register_plugin);
  register_pair_omp<MieLaw>(lmp, handle, register_plugin);
  register_pair_omp<HarmonicLaw>(lmp, handle, register_plugin);
}
