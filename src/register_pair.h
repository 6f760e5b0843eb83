/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: registration of one pair style class
   with LAMMPS, shared by the two plugin files (clusterdynplugin.so and
   clusterdyn_omp.so).  LAMMPS keeps the name and info pointers: the caller
   passes strings that live as long as the plugin.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_REGISTER_PAIR_H
#define LMP_CLUSTERDYN_REGISTER_PAIR_H

#include "lammpsplugin.h"
#include "version.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  template <class T> Pair *create_pair(LAMMPS *lmp)
  {
    return new T(lmp);
  }

  template <class T>
  void register_pair_class(const char *name, const char *info, void *lmp, void *handle,
                           lammpsplugin_regfunc register_plugin)
  {
    lammpsplugin_t plugin;
    plugin.version = LAMMPS_VERSION;
    plugin.style = "pair";
    plugin.name = name;
    plugin.info = info;
    plugin.author = "cluster-dynamics plugin developers";
    plugin.creator.v1 = (lammpsplugin_factory1 *) &create_pair<T>;
    plugin.handle = handle;
    (*register_plugin)(&plugin, lmp);
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
