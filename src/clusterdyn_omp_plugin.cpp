/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the /omp variants of the pair styles,
   a plugin file of their own (clusterdyn_omp.so) because they need the
   OPENMP package's ThrOMP symbols.  clusterdynplugin.so loads it when the
   host LAMMPS has OPENMP, so that the core styles load everywhere.
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

#include "pair_spline_omp.h"

#include <string>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

namespace {

template <class T> Pair *create_pair(LAMMPS *lmp)
{
  return new T(lmp);
}

template <class Law>
void register_pair_omp(void *lmp, void *handle, lammpsplugin_regfunc register_plugin)
{
  static const std::string name = std::string(Law::style) + "/omp";    // LAMMPS keeps the pointers
  static const std::string info = std::string("cluster-dynamics pair style ") + Law::style +
      " with OpenMP threads";
  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.name = name.c_str();
  plugin.info = info.c_str();
  plugin.author = "cluster-dynamics plugin developers";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &create_pair<PairSplineOMP<Law>>;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);
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
