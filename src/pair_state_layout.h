/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the layout of a pair's doubles in fix
   PAIR_STATE (fix_pair_state.h), stateless as spline_laws.h: in the list, a
   row of the owner's doubles and the state word's slot; saved with the
   atoms, the owner's doubles that outlive a compute and the word (those the
   owner declared within a compute are left out, and come back zero).  And
   the restart record of an atom's saved pairs: since 29 Nov 2026 the saved
   doubles of each pair once, before that whole rows at both atoms of a pair.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_STATE_LAYOUT_H
#define LMP_CLUSTERDYN_PAIR_STATE_LAYOUT_H

#include "lmptype.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct PairStateLayout {
    int row = 1;                 // doubles per pair in the list (the word's last)
    std::vector<int> columns;    // the owner's doubles that are saved

    // row doubles; within: a bit per owner's double that lives within a compute
    void choose(int doubles, int within)
    {
      row = doubles;
      columns.clear();
      for (int k = 0; k < row - 1; k++)
        if (!((within >> k) & 1)) columns.push_back(k);
    }
    int saved() const { return static_cast<int>(columns.size()) + 1; }

    // a pair's word rides in the last of its doubles (n of them)
    static int word(const double *values, int n) { return static_cast<int>(fabs(values[n - 1])); }

    void to_saved(const double *values, double *kept) const
    {
      for (std::size_t k = 0; k < columns.size(); k++) kept[k] = values[columns[k]];
      kept[saved() - 1] = values[row - 1];
    }

    void to_row(const double *kept, double *values) const
    {
      std::fill(values, values + row, 0.0);
      for (std::size_t k = 0; k < columns.size(); k++) values[columns[k]] = kept[k];
      values[row - 1] = kept[saved() - 1];
    }

    // an atom's restart record of n pairs and `length` values in all (its length, n, the
    // pairs, its saved ID, the marker ONE_COPY; last: its last value): CURRENT, BEFORE (whole
    // rows at both atoms, no marker: the last value is the ID's bits), or neither
    static constexpr double ONE_COPY = 1.0;
    enum Record { CURRENT, BEFORE, UNKNOWN };
    Record record(int length, int n, double last) const
    {
      if (length == 4 + n * (saved() + 1) && last == ONE_COPY) return CURRENT;
      return length == 3 + n * (row + 1) ? BEFORE : UNKNOWN;
    }

    // the saved ID of such a record's atom (entries: its n pairs, each a partner ID and its
    // doubles)
    tagint owner_id(const double *entries, int n, Record kind) const
    {
      return (tagint) ubuf(entries[n * ((kind == CURRENT ? saved() : row) + 1)]).i;
    }

    // its pairs into partner and kept (saved() doubles each); of a record from before, only the
    // copies of the atom with the smaller ID; returns how many
    int read(const double *entries, int n, Record kind, tagint own, tagint *partner,
             double *kept) const
    {
      const int width = kept_width(kind);
      int count = 0;
      for (int e = 0; e < n; e++) {
        const double *entry = entries + e * (width + 1);
        const tagint other = (tagint) ubuf(entry[0]).i;
        if (kind == BEFORE && other < own) continue;
        partner[count] = other;
        if (kind == CURRENT) memcpy(kept + count * saved(), entry + 1, saved() * sizeof(double));
        else to_saved(entry + 1, kept + count * saved());
        count++;
      }
      return count;
    }

   private:
    int kept_width(Record kind) const { return kind == CURRENT ? saved() : row; }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
