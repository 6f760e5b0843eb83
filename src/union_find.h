/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: union-find over local indices (my
   atoms and ghosts) and over global labels (compute dust).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_UNION_FIND_H
#define LMP_CLUSTERDYN_UNION_FIND_H

#include "lmptype.h"

#include <algorithm>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class UnionFind {
   public:
    void reset(int n)
    {
      parent.resize(n);
      for (int i = 0; i < n; i++) parent[i] = i;
    }
    int find(int i)
    {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    }
    void join(int a, int b)
    {
      const int ra = find(a), rb = find(b);
      if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
    }
    double memory_usage() const { return (double) parent.capacity() * sizeof(int); }

   private:
    std::vector<int> parent;
  };

  // each label leads to the smallest label of its set
  class LabelUnion {
   public:
    tagint root(tagint t) const
    {
      for (auto it = up.find(t); it != up.end(); it = up.find(t)) t = it->second;
      return t;
    }
    void join(tagint a, tagint b)
    {
      const tagint ra = root(a), rb = root(b);
      if (ra != rb) up[std::max(ra, rb)] = std::min(ra, rb);
    }

   private:
    std::unordered_map<tagint, tagint> up;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
