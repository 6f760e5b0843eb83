/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative arguments
   (viscous_settings.h).
------------------------------------------------------------------------- */

#include "viscous_settings.h"

#include "keyword_set.h"

#include "error.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

ViscousSettings ViscousSettings::parse(LAMMPS *lmp, int narg, char **arg)
{
  Error *error = lmp->error;
  ViscousSettings s;
  if (narg < 5)
    error->all(FLERR, "Fix viscous/relative: expected fix ID group viscous/relative gamma G | J J "
               "[mode full|normal] [weight none|dpd] [cutoff d]");
  if (strcmp(arg[3], "gamma") == 0) s.by_j = 0;
  else if (strcmp(arg[3], "J") == 0) s.by_j = 1;
  else error->all(FLERR, "Fix viscous/relative: unknown style '{}' (expected gamma or J)", arg[3]);
  s.value = utils::numeric(FLERR, arg[4], false, lmp);
  if (!(s.value > 0.0))
    error->all(FLERR, "Fix viscous/relative: {} must be > 0 (got {})", arg[3], arg[4]);

  KeywordSet given(lmp, "Fix viscous/relative");
  for (int iarg = 5; iarg < narg; iarg += 2) {
    given.add(arg[iarg]);
    if (iarg + 1 >= narg)
      error->all(FLERR, "Fix viscous/relative: keyword {} needs a value", arg[iarg]);
    const std::string key = arg[iarg], val = arg[iarg + 1];
    if (key == "mode") {
      if (val == "full") s.normal = 0;
      else if (val == "normal") s.normal = 1;
      else error->all(FLERR, "Fix viscous/relative: unknown mode '{}' (expected full or normal)", val);
    } else if (key == "weight") {
      if (val == "none") s.dpd = 0;
      else if (val == "dpd") s.dpd = 1;
      else error->all(FLERR, "Fix viscous/relative: unknown weight '{}' (expected none or dpd)", val);
    } else if (key == "cutoff") {
      s.cutoff = utils::numeric(FLERR, val, false, lmp);
      if (!(s.cutoff > 0.0))
        error->all(FLERR, "Fix viscous/relative: cutoff must be > 0 (got {})", val);
    } else
      error->all(FLERR, "Fix viscous/relative: unknown keyword '{}' (expected mode, weight or "
                 "cutoff)", key);
  }
  return s;
}
