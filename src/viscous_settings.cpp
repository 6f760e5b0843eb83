/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative arguments
   (viscous_settings.h).
------------------------------------------------------------------------- */

#include "viscous_settings.h"

#include "arg_values.h"
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
  s.value = positive_arg("Fix viscous/relative", arg[3], arg[4], lmp);

  KeywordSet given(lmp, "Fix viscous/relative", Keywords::VISCOUS_RELATIVE);
  for (int iarg = 5; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    given.add(key);
    if (iarg + 1 >= narg)
      error->all(FLERR, "Fix viscous/relative: keyword {} needs a value", key);
    const std::string val = arg[iarg + 1];
    if (key == "mode") {
      if (val == "full") s.normal = 0;
      else if (val == "normal") s.normal = 1;
      else error->all(FLERR, "Fix viscous/relative: unknown mode '{}' (expected full or normal)", val);
    } else if (key == "weight") {
      if (val == "none") s.dpd = 0;
      else if (val == "dpd") s.dpd = 1;
      else error->all(FLERR, "Fix viscous/relative: unknown weight '{}' (expected none or dpd)", val);
    } else if (key == "cutoff") {
      s.cutoff = positive_arg("Fix viscous/relative", "cutoff", val.c_str(), lmp);
    }
  }
  return s;
}
