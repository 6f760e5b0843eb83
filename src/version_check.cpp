/* ----------------------------------------------------------------------
   Version check of the cluster-dynamics plugin at load (version_check.h)
------------------------------------------------------------------------- */

#include "version_check.h"

#include "library.h"

#include <cstdio>
#include <cstring>
#include <string>

namespace LAMMPS_NS::ClusterDyn {

int version_number(const char *version)
{
  static const char *months[] = {"Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                 "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
  int day = 0, year = 0;
  char month[4] = {0};
  if (!version || std::sscanf(version, "%d %3s %d", &day, month, &year) != 3) return 0;
  for (int m = 0; m < 12; ++m)
    if (std::strcmp(month, months[m]) == 0) return year * 10000 + (m + 1) * 100 + day;
  return 0;
}

bool host_version_matches(void *lmp, const char *built_for, const char *name)
{
  const int host = lammps_version(lmp);
  const int built = version_number(built_for);
  if (host == built) return true;
  if (lammps_extract_setting(lmp, "world_rank") == 0) {
    const std::string msg = std::string(name) + " was compiled for LAMMPS " + built_for + " (" +
        std::to_string(built) + ") but this LAMMPS is version " + std::to_string(host) +
        ": none of its styles are registered. Rebuild the plugin against this LAMMPS "
        "(doc/Build.rst, Compatibility)";
    lammps_error(lmp, LMP_ERROR_WARNING, msg.c_str());
  }
  return false;
}

}    // namespace LAMMPS_NS::ClusterDyn
