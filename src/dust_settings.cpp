/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute dust arguments
   (dust_settings.h).
------------------------------------------------------------------------- */

#include "dust_settings.h"

#include "arg_values.h"
#include "keyword_set.h"

#include "error.h"

#include <string>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

DustSettings DustSettings::parse(LAMMPS *lmp, int narg, char **arg)
{
  Error *error = lmp->error;
  DustSettings s;
  KeywordSet given(lmp, "Compute dust", Keywords::DUST);
  for (int iarg = 3; iarg < narg; iarg++) {
    const std::string key = arg[iarg];
    given.add(key);
    if (key == "links") {    // a flag: the bonds are the pair style's links
      s.links = 1;
      continue;
    }
    if (++iarg >= narg) error->all(FLERR, "Compute dust: keyword {} needs a value", key);
    const std::string value = arg[iarg];
    if (key == "cutoff") {
      s.cutoff = positive_arg("Compute dust", "cutoff", value.c_str(), lmp);
    } else if (key == "maxsize") {
      const double m = integer_arg("Compute dust", "maxsize", value.c_str(), lmp);
      if (m < 1) error->all(FLERR, "Compute dust: maxsize must be >= 1 (got {})", value);
      s.maxsize = (bigint) m;
    } else {
      if (value != "all" && value != "dust")
        error->all(FLERR, "Compute dust: rows must be all or dust (got {})", value);
      s.dust_rows = value == "dust";
    }
  }
  if (s.links && s.cutoff > 0.0)
    error->all(FLERR, "Compute dust: keywords links and cutoff exclude each other (the links are "
               "the bonds)");
  return s;
}
