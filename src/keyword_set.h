/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the keywords a command has given so
   far.  A keyword given twice is an error: the last value would otherwise
   win silently.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_KEYWORD_SET_H
#define LMP_CLUSTERDYN_KEYWORD_SET_H

#include "error.h"
#include "lammps.h"

#include <set>
#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class KeywordSet {
   public:
    KeywordSet(LAMMPS *lmp, const std::string &who) : lmp(lmp), who(who) {}
    void add(const std::string &key)
    {
      if (!seen.insert(key).second)
        lmp->error->all(FLERR, "{}: keyword {} given twice", who, key);
    }

   private:
    LAMMPS *lmp;
    std::string who;
    std::set<std::string> seen;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
