/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pages of pointers, the per-pair slots
   of the persistent pair state (fix_pair_state.h): LAMMPS's MyPage holds
   numbers only.  Chunks of n pointers from pages of at least PAGE, kept
   across resets (a list build reuses them), so that a build costs no
   allocation and the slack is one page.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SLOT_PAGES_H
#define LMP_CLUSTERDYN_SLOT_PAGES_H

#include <algorithm>
#include <cstddef>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class SlotPages {
   public:
    static constexpr std::size_t PAGE = 65536;

    void reset()
    {
      page = 0;
      used = 0;
    }

    double **get(std::size_t n)
    {
      while (page < pages.size() && used + n > pages[page].size()) {
        page++;
        used = 0;
      }
      if (page == pages.size()) pages.emplace_back(std::max(PAGE, n));
      double **chunk = pages[page].data() + used;
      used += n;
      return chunk;
    }

    double bytes() const
    {
      double sum = 0.0;
      for (const auto &p : pages) sum += p.size() * sizeof(double *);
      return sum;
    }

   private:
    std::vector<std::vector<double *>> pages;
    std::size_t page = 0, used = 0;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
