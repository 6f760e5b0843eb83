/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: registers every style of the package
   with LAMMPS on "plugin load clusterdynplugin.so".  The /omp variants live
   in clusterdyn_omp.so beside it (they need the OPENMP package's symbols),
   the /gpu variants in clusterdyn_gpu.so (the GPU package's); each is
   loaded from here when the host LAMMPS has its package, so that this file
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
#include "register_style.h"
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

template <class Law> void add_spline_style(const StyleRegistrar &styles)
{
  static const std::string info = std::string("cluster-dynamics pair style ") + Law::style;
  styles.add<PairSpline<Law>>(Law::style, info.c_str());
}

// a plugin file of variants (clusterdyn_omp.so, clusterdyn_gpu.so) from the folder of this
// file, if the host LAMMPS has their package
void load_variants(LAMMPS *lmp, const char *package, const char *file_name, const char *styles)
{
  const bool me0 = lmp->comm->me == 0;
  if (!Info::has_package(package)) {
    if (me0)
      utils::logmesg(lmp, "  cluster-dynamics plugin: this LAMMPS has no {} package; the {} pair "
                     "styles are not loaded\n", package, styles);
    return;
  }
  Dl_info self;
  if (!dladdr((void *) &load_variants, &self) || !self.dli_fname) return;
  const std::string file =
      platform::path_join(platform::path_dirname(self.dli_fname), file_name);
  if (!platform::file_is_readable(file)) {
    if (me0)
      utils::logmesg(lmp, "  cluster-dynamics plugin: {} not found; the {} pair styles are not "
                     "loaded\n", file, styles);
    return;
  }
  plugin_load(file.c_str(), lmp);
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  if (!host_version_matches(lmp, CLUSTERDYN_BUILT_FOR, "clusterdynplugin.so")) return;
  const StyleRegistrar styles(lmp, handle, regfunc);
  add_spline_style<MorseLaw>(styles);
  add_spline_style<LJLaw>(styles);
  add_spline_style<MieLaw>(styles);
  add_spline_style<HarmonicLaw>(styles);
  styles.add<PairMCA>("mca", "movable cellular automata");
  styles.add<FixViscousRelative>("viscous/relative",
                                 "cluster-dynamics damping on pairwise relative velocities");
  styles.add<FixDescentNormalized>("descent/normalized",
                                   "Chernyshev's quasi-static iteration: normalized steps along "
                                   "the force");
  styles.add<ComputePairParams>("pair/params", "characteristic parameters of a pair law");
  styles.add<ComputeDust>("dust", "fragments of the bond graph and the dust");
  styles.add<ComputeFreeSurface>(
      "free/surface", "velocity of a body's free face, dust excluded (a simulated VISAR)");
  styles.add<ComputeLinksAtom>("links/atom", "intact links per atom of a pair style with link L");
  styles.add<ComputeMcaAtom>("mca/atom", "element stress and links of pair_style mca");

  load_variants((LAMMPS *) lmp, "OPENMP", "clusterdyn_omp.so", "/omp");
  load_variants((LAMMPS *) lmp, "GPU", "clusterdyn_gpu.so", "/gpu");
}
