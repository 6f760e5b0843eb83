/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the keywords a command has given so
   far, checked against the command's table (style_keywords.h).  A keyword
   outside the table is an error that lists the table; a keyword given twice
   is an error: the last value would otherwise win silently.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_KEYWORD_SET_H
#define LMP_CLUSTERDYN_KEYWORD_SET_H

#include "error.h"
#include "lammps.h"
#include "style_keywords.h"

#include <set>
#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class KeywordSet {
   public:
    KeywordSet(LAMMPS *lmp, const std::string &who, const KeywordTable &known) :
        lmp(lmp), who(who), known(known)
    {
    }
    // the table's entry of key; unknown or repeated keys stop with an error
    const StyleKeyword &add(const std::string &key)
    {
      const StyleKeyword *entry = find(key);
      if (!entry)
        lmp->error->all(FLERR, "{}: unknown keyword '{}' (expected {})", who, key, names());
      if (!seen.insert(key).second)
        lmp->error->all(FLERR, "{}: keyword {} given twice", who, key);
      return *entry;
    }
    // the count of values key takes in the table (0 where it is not a keyword there)
    int values_of(const std::string &key) const
    {
      const StyleKeyword *entry = find(key);
      return entry ? entry->values : 0;
    }

   private:
    const StyleKeyword *find(const std::string &key) const
    {
      for (const StyleKeyword &k : known)
        if (key == k.name) return &k;
      return nullptr;
    }
    // "a, b or c"
    std::string names() const
    {
      std::string list;
      for (std::size_t i = 0; i < known.size(); i++)
        list += (i == 0 ? "" : i + 1 == known.size() ? " or " : ", ") + std::string(known[i].name);
      return list;
    }

    LAMMPS *lmp;
    std::string who;
    const KeywordTable &known;
    std::set<std::string> seen;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
