/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: registers every style of the package
   with LAMMPS on "plugin load clusterdynplugin.so".  The /omp variants live
   in clusterdyn_omp.so beside it (they need the OPENMP package's symbols);
   it is loaded from here when the host LAMMPS has OPENMP, so that this file
   loads into any LAMMPS with PLUGIN.
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

#include "compute_dust.h"
#include "compute_free_surface.h"
#include "compute_links_atom.h"
#include "compute_mca_atom.h"
#include "compute_pair_params.h"
#include "fix_descent_normalized.h"
#include "fix_viscous_relative.h"
#include "pair_mca.h"
#include "pair_spline.h"
#include "register_pair.h"
#include "version_check.h"

#include "comm.h"
#include "info.h"
#include "lammps.h"
#include "platform.h"
#include "utils.h"

#include <dlfcn.h>

namespace LAMMPS_NS {
int plugin_load(const char *, LAMMPS *);    // PLUGIN/plugin.h
}

using namespace LAMMPS_NS;
using namespace ClusterDyn;

// the LAMMPS version this file is built for; only the test of the version check sets another
#ifndef CLUSTERDYN_BUILT_FOR
#define CLUSTERDYN_BUILT_FOR LAMMPS_VERSION
#endif

namespace {

template <class Law>
void register_pair(void *lmp, void *handle, lammpsplugin_regfunc register_plugin)
{
  static const std::string info = std::string("cluster-dynamics pair style ") + Law::style;
  register_pair_class<PairSpline<Law>>(Law::style, info.c_str(), lmp, handle, register_plugin);
}

// clusterdyn_omp.so from the folder of this file, if the host LAMMPS has OPENMP
void load_omp_variants(LAMMPS *lmp)
{
  const bool me0 = lmp->comm->me == 0;
  if (!Info::has_package("OPENMP")) {
    if (me0)
      utils::logmesg(lmp, "  cluster-dynamics plugin: this LAMMPS has no OPENMP package; the "
                     "/omp pair styles are not loaded\n");
    return;
  }
  Dl_info self;
  if (!dladdr((void *) &load_omp_variants, &self) || !self.dli_fname) return;
  const std::string file = platform::path_join(platform::path_dirname(self.dli_fname),
                                               "clusterdyn_omp.so");
  if (!platform::file_is_readable(file)) {
    if (me0)
      utils::logmesg(lmp, "  cluster-dynamics plugin: {} not found; the /omp pair styles are not "
                     "loaded\n", file);
    return;
  }
  plugin_load(file.c_str(), lmp);
}

Fix *create_fix_viscous_relative(LAMMPS *lmp, int narg, char **arg)
{
  return new FixViscousRelative(lmp, narg, arg);
}

Fix *create_fix_descent_normalized(LAMMPS *lmp, int narg, char **arg)
{
  return new FixDescentNormalized(lmp, narg, arg);
}

Compute *create_compute_dust(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeDust(lmp, narg, arg);
}

Compute *create_compute_free_surface(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeFreeSurface(lmp, narg, arg);
}

Compute *create_compute_links_atom(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeLinksAtom(lmp, narg, arg);
}

Compute *create_compute_mca_atom(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeMcaAtom(lmp, narg, arg);
}

Compute *create_compute_pair_params(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputePairParams(lmp, narg, arg);
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  if (!host_version_matches(lmp, CLUSTERDYN_BUILT_FOR, "clusterdynplugin.so")) return;
  auto register_plugin = (lammpsplugin_regfunc) regfunc;
  register_pair<MorseLaw>(lmp, handle, register_plugin);
  register_pair<LJLaw>(lmp, handle, register_plugin);
  register_pair<MieLaw>(lmp, handle, register_plugin);
  register_pair<HarmonicLaw>(lmp, handle, register_plugin);
  register_pair_class<PairMCA>("mca", "movable cellular automata", lmp, handle, register_plugin);

  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "fix";
  plugin.name = "viscous/relative";
  plugin.info = "cluster-dynamics damping on pairwise relative velocities";
  plugin.author = "cluster-dynamics plugin developers";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_fix_viscous_relative;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "descent/normalized";
  plugin.info = "Chernyshev's quasi-static iteration: normalized steps along the force";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_fix_descent_normalized;
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

  plugin.name = "free/surface";
  plugin.info = "velocity of a body's free face, dust excluded (a simulated VISAR)";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_compute_free_surface;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "links/atom";
  plugin.info = "intact links per atom of a pair style with link L";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_compute_links_atom;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "mca/atom";
  plugin.info = "element stress and links of pair_style mca";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &create_compute_mca_atom;
  (*register_plugin)(&plugin, lmp);

  load_omp_variants((LAMMPS *) lmp);
}
