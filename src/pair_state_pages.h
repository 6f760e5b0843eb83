/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the pages of fix PAIR_STATE
   (fix_pair_state.h).
   - Their size: FixNeighHistory::allocate_pages() makes each page hold
     neigh_modify page pairs (100,000 by default): 14.4 MB for pair mca's
     18 doubles per pair, and the first pages of its four kinds took 30 MB,
     mostly empty, on a small system.  Pages of PAGE_BYTES instead, or of
     the largest chunk (one atom's neigh_modify one pairs) where that is
     larger.
   - The saved pairs of the owned atoms across new pages: where
     neigh_modify page or one changes between runs, FixNeighHistory's
     init() frees its pages and makes new ones, and the atoms' saved pairs
     pointed into the freed ones (a crash, or links lost without a word);
     they are copied out before and into the new pages after.
   - The ghosts' saved pairs, sent by their owners for a list build
     (FixPairState::forward_partners()), in pages of their own that go back
     to one page each after the build: in FixNeighHistory's pages of the
     owned atoms' pairs they stayed as the pages' high water (a 14 MB page
     per processor on 2 processors of a wide plate).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_STATE_PAGES_H
#define LMP_CLUSTERDYN_PAIR_STATE_PAGES_H

#include "error.h"
#include "lmptype.h"
#include "my_page.h"

#include <algorithm>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class PairStatePages {
   public:
    static constexpr int PAGE_BYTES = 1 << 18;

    // pages (emptied: their contents are dropped) for chunks of at most `most` values of T
    template <class T> static void size(MyPage<T> &pages, int most, Error *error)
    {
      const int page = std::max(most, PAGE_BYTES / (int) sizeof(T));
      if (pages.init(most, page) != 0)
        error->one(FLERR, "Fix PAIR_STATE: cannot allocate a page of {} values (neigh_modify one)",
                   page);
    }

    // the saved pairs of atoms 0..n-1, copied out of pages about to be freed
    struct Carried {
      std::vector<int> counts;
      std::vector<tagint> ids;
      std::vector<double> values;
    };
    static Carried carry_out(int n, const int *npartner, tagint *const *partner,
                             double *const *valuepartner, int dnum)
    {
      Carried c;
      for (int i = 0; i < n; i++) {
        c.counts.push_back(npartner[i]);
        c.ids.insert(c.ids.end(), partner[i], partner[i] + npartner[i]);
        c.values.insert(c.values.end(), valuepartner[i], valuepartner[i] + dnum * npartner[i]);
      }
      return c;
    }
    // ... and into the new pages
    static void carry_in(const Carried &c, int *npartner, tagint **partner, double **valuepartner,
                         int dnum, MyPage<tagint> &ids, MyPage<double> &values, Error *error)
    {
      const tagint *id = c.ids.data();
      const double *value = c.values.data();
      for (int i = 0; i < (int) c.counts.size(); i++) {
        const int n = npartner[i] = c.counts[i];
        partner[i] = ids.get(n);
        valuepartner[i] = values.get(dnum * n);
        if (!partner[i] || !valuepartner[i])
          error->one(FLERR, "Fix PAIR_STATE: an atom keeps {} saved pairs, more than neigh_modify "
                     "one allows: boost neigh_modify one", n);
        std::copy(id, id + n, partner[i]);
        std::copy(value, value + dnum * n, valuepartner[i]);
        id += n;
        value += dnum * n;
      }
    }

    // the ghosts' pages, for at most `pairs` pairs per atom of `doubles` doubles each; emptied
    void size_ghosts(int pairs, int doubles, Error *error)
    {
      most = pairs;
      values = doubles;
      size(ids, most, error);
      size(saved, most * values, error);
    }
    // a ghost's IDs and doubles for n pairs (null: more than `most` pairs)
    tagint *ghost_ids(int n) { return ids.get(n); }
    double *ghost_values(int n) { return saved.get(n * values); }
    void reset()
    {
      ids.reset();
      saved.reset();
    }
    // the ghosts' pages freed back to one page each (after a list build)
    void drop(Error *error) { size_ghosts(most, values, error); }
    double bytes() const { return ids.size() + saved.size(); }

   private:
    MyPage<tagint> ids;
    MyPage<double> saved;
    int most = 0, values = 0;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
