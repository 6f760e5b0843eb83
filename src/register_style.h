/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: registration of the package's style
   classes with LAMMPS, shared by the two plugin files (clusterdynplugin.so
   and clusterdyn_omp.so).  The kind of style (pair, fix, compute) and its
   creator follow from the class's LAMMPS base.  LAMMPS keeps the name and
   info pointers: the caller passes strings that live as long as the plugin.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_REGISTER_STYLE_H
#define LMP_CLUSTERDYN_REGISTER_STYLE_H

#include "lammpsplugin.h"
#include "version.h"

#include "compute.h"
#include "fix.h"
#include "pair.h"

#include <type_traits>

namespace LAMMPS_NS {
namespace ClusterDyn {

  template <class T> Pair *create_pair(LAMMPS *lmp)
  {
    return new T(lmp);
  }

  template <class T> Fix *create_fix(LAMMPS *lmp, int narg, char **arg)
  {
    return new T(lmp, narg, arg);
  }

  template <class T> Compute *create_compute(LAMMPS *lmp, int narg, char **arg)
  {
    return new T(lmp, narg, arg);
  }

  // lammpsplugin_init's arguments: add<T>(name, info) registers class T as style name
  class StyleRegistrar {
   public:
    StyleRegistrar(void *lmp, void *handle, void *regfunc) :
        lmp_(lmp), handle_(handle), register_plugin_((lammpsplugin_regfunc) regfunc)
    {
    }

    template <class T> void add(const char *name, const char *info) const
    {
      lammpsplugin_t plugin;
      plugin.version = LAMMPS_VERSION;
      plugin.name = name;
      plugin.info = info;
      plugin.author = "cluster-dynamics plugin developers";
      plugin.handle = handle_;
      if constexpr (std::is_base_of_v<Pair, T>) {
        plugin.style = "pair";
        plugin.creator.v1 = (lammpsplugin_factory1 *) &create_pair<T>;
      } else if constexpr (std::is_base_of_v<Fix, T>) {
        plugin.style = "fix";
        plugin.creator.v2 = (lammpsplugin_factory2 *) &create_fix<T>;
      } else {
        static_assert(std::is_base_of_v<Compute, T>, "a pair, fix or compute style");
        plugin.style = "compute";
        plugin.creator.v2 = (lammpsplugin_factory2 *) &create_compute<T>;
      }
      (*register_plugin_)(&plugin, lmp_);
    }

   private:
    void *lmp_;
    void *handle_;
    lammpsplugin_regfunc register_plugin_;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
