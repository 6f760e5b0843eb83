/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the /gpu variants of the spline pair
   styles, a plugin file of their own (clusterdyn_gpu.so) because they need
   the GPU package's symbols (lib/gpu).  clusterdynplugin.so loads it when
   the host LAMMPS has GPU, so that the core styles load everywhere.
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

#include "pair_spline_gpu.h"
#include "register_style.h"

#include <string>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

namespace {

template <class Law> void add_spline_gpu_style(const StyleRegistrar &styles)
{
  static const std::string name = std::string(Law::style) + "/gpu";    // LAMMPS keeps the pointers
  static const std::string info = std::string("cluster-dynamics pair style ") + Law::style +
      " on the GPU package";
  styles.add<PairSplineGPU<Law>>(name.c_str(), info.c_str());
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  const StyleRegistrar styles(lmp, handle, regfunc);
  add_spline_gpu_style<MorseLaw>(styles);
  add_spline_gpu_style<LJLaw>(styles);
  add_spline_gpu_style<MieLaw>(styles);
  add_spline_gpu_style<HarmonicLaw>(styles);
}
