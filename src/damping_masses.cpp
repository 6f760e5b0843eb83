/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: ghost atoms' per-atom masses
   (damping_masses.h).
------------------------------------------------------------------------- */

#include "damping_masses.h"

#include "fix_property_atom.h"
#include "lammps.h"
#include "modify.h"

using namespace LAMMPS_NS;
using namespace ClusterDyn;

namespace {
// fix property/atom keeps whether it defines rmass and whether it sends its values to ghost
// atoms in protected members, without an accessor: a derived class may name them, and its
// member pointers read them on any fix property/atom
struct PropertyAtomFlags : FixPropertyAtom {
  static bool rmass_without_ghosts(const FixPropertyAtom *fix)
  {
    return fix->*(&PropertyAtomFlags::rmass_flag) && !(fix->*(&PropertyAtomFlags::border));
  }
};
}    // namespace

std::string ClusterDyn::ghostless_rmass_fix(LAMMPS *lmp)
{
  for (const Fix *fix : lmp->modify->get_fix_by_style("^property/atom"))
    if (PropertyAtomFlags::rmass_without_ghosts(static_cast<const FixPropertyAtom *>(fix)))
      return fix->id;
  return "";
}
