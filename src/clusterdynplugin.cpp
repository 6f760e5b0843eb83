/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: registers every style of the package
   (and its /omp variant) with LAMMPS on "plugin load clusterdynplugin.so".
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

#include "compute_dust.h"
#include "compute_pair_params.h"
#include "fix_viscous_relative.h"
#include "pair_spline.h"
#include "pair_spline_omp.h"

using namespace LAMMPS_NS;
using namespace ClusterDyn;

namespace {

template <class T> Pair *create_pair(LAMMPS *lmp)
{
  return new T(lmp);
}

template <class Law>
void register_pair(void *lmp, void *handle, lammpsplugin_regfunc register_plugin)
{
  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.author = "cluster-dynamics plugin developers";
  plugin.handle = handle;
  // LAMMPS keeps these pointers: one static copy per style
  static const std::string name = Law::style;
  static const std::string info = "cluster-dynamics pair style " + name;
  static const std::string omp_name = name + "/omp";
  static const std::string omp_info = info + " with OpenMP threads";
  plugin.name = name.c_str();
  plugin.info = info.c_str();
  plugin.creator.v1 = (lammpsplugin_factory1 *) &create_pair<PairSpline<Law>>;
  (*register_plugin)(&plugin, lmp);

  plugin.name = omp_name.c_str();
  plugin.info = omp_info.c_str();
  plugin.creator.v1 = (lammpsplugin_factory1 *) &create_pair<PairSplineOMP<Law>>;
  (*register_plugin)(&plugin, lmp);
}

Fix *create_fix_viscous_relative(LAMMPS *lmp, int narg, char **arg)
{
  return new FixViscousRelative(lmp, narg, arg);
}

Compute *create_compute_dust(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeDust(lmp, narg, arg);
}

Compute *create_compute_pair_params(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputePairParams(lmp, narg, arg);
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto register_plugin = (lammpsplugin_regfunc) regfunc;
  register_pair<MorseLaw>(lmp, handle, register_plugin);
  register_pair<LJLaw>(lmp, handle, register_plugin);
  register_pair<MieLaw>(lmp, handle, register_plugin);
  register_pair<HarmonicLaw>(lmp, handle, register_plugin);

  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "fix";
  plugin.name = "viscous/relative";
  plugin.info = "cluster-dynamics damping on pairwise relative velocities";
  plugin.author = "cluster-dynamics plugin developers";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_fix_viscous_relative;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "compute";
  plugin.name = "pair/params";
  plugin.info = "characteristic parameters of a pair law";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_compute_pair_params;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "dust";
  plugin.info = "fragments of the bond graph and the dust";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_compute_dust;
  (*register_plugin)(&plugin, lmp);
}
