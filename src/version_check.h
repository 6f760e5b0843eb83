/* ----------------------------------------------------------------------
   The LAMMPS version a plugin file was compiled against must be the one
   that loads it (the C++ classes it derives from change between versions).
   host_version_matches() reads the host's version through the C library
   interface (lammps_version(): no use of the host's C++ layout) and, where
   it differs, prints a warning that names both versions.
------------------------------------------------------------------------- */

#ifndef CLUSTERDYN_VERSION_CHECK_H
#define CLUSTERDYN_VERSION_CHECK_H

namespace LAMMPS_NS::ClusterDyn {

// LAMMPS_VERSION strings ("4 Feb 2025") as YYYYMMDD (LAMMPS's num_ver); 0 if unreadable
int version_number(const char *version);

// true if the LAMMPS instance lmp has the version `built_for` (a LAMMPS_VERSION string);
// otherwise warns (on world rank 0) that the plugin `name` registers nothing
bool host_version_matches(void *lmp, const char *built_for, const char *name);

}    // namespace LAMMPS_NS::ClusterDyn

#endif
