/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the slots of fix PAIR_STATE's list
   (fix_pair_state.h): per atom of the list, a pointer per pair that may
   keep doubles, to its row of doubles (row of them: the owner's and the
   word's slot) or null where it has none yet.  The rows of the pairs with a
   saved state come from the list build; a pair that needs one between
   builds claims it here, zeroed, from a pool that the next build renews
   (and gives back where it grew beyond a page: a setup claims every link).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_STATE_SLOTS_H
#define LMP_CLUSTERDYN_PAIR_STATE_SLOTS_H

#include "slot_pages.h"

#include "my_page.h"

#include <algorithm>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class PairStateSlots {
   public:
    static constexpr int SPARE_ROWS = 4096;    // per page of the pool

    PairStateSlots() = default;
    PairStateSlots(const PairStateSlots &) = delete;
    PairStateSlots &operator=(const PairStateSlots &) = delete;
    ~PairStateSlots() { delete spares; }

    void set_row(int doubles) { row = doubles; }
    void grow(int natoms) { slots.resize(std::max<std::size_t>(slots.size(), natoms)); }

    // a list build: every atom's slots anew, the last build's claims given back
    void renew()
    {
      pages.reset();
      if (!spares || spares->size() > (double) SPARE_ROWS * row * sizeof(double)) {
        delete spares;
        spares = new MyPage<double>;
        spares->init(row, SPARE_ROWS * row);
      } else
        spares->reset();
    }

    double **of(int i, int n) { return slots[i] = pages.get(n); }
    double **const *all() const { return slots.data(); }

    // pair jj of atom i gets a row, zeroed (null: the pool is exhausted)
    double *claim(int i, int jj)
    {
      double *v = spares->get(row);
      if (v) std::fill(v, v + row, 0.0);
      return slots[i][jj] = v;
    }

    double bytes() const
    {
      return slots.capacity() * sizeof(double **) + pages.bytes() + (spares ? spares->size() : 0.0);
    }

   private:
    int row = 1;
    std::vector<double **> slots;
    SlotPages pages;
    MyPage<double> *spares = nullptr;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
