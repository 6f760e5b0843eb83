/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: a pair style whose components
   exchange per-atom columns (McaExchange) through the pair's forward and
   reverse communication: to_owners() and to_ghosts() name the rows and
   their columns, and the pair's pack and unpack move them (as pair eam
   moves its densities, for any number of arrays).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_COLUMN_EXCHANGE_H
#define LMP_CLUSTERDYN_PAIR_COLUMN_EXCHANGE_H

#include "mca_exchange.h"

#include "comm.h"
#include "error.h"
#include "force.h"
#include "pair.h"

#include <cstdlib>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class PairColumnExchange : public Pair, public McaExchange {
   public:
    explicit PairColumnExchange(LAMMPS *lmp) : Pair(lmp), rows(nullptr), columns(0) {}

    void to_owners(double **r, int c) override
    {
      if (c > comm_reverse) too_many(c, comm_reverse);
      if (!force->newton_pair) return;
      rows = r;
      columns = c;
      comm->reverse_comm(this, c);
    }
    void to_ghosts(double **r, int c) override
    {
      if (c > comm_forward) too_many(c, comm_forward);
      rows = r;
      columns = c;
      comm->forward_comm(this, c);
    }

    int pack_forward_comm(int n, int *list, double *buf, int, int *) override
    {
      int m = 0;
      for (int i = 0; i < n; i++)
        for (int k = 0; k < columns; k++) buf[m++] = rows[list[i]][k];
      return m;
    }
    void unpack_forward_comm(int n, int first, double *buf) override
    {
      int m = 0;
      for (int i = first; i < first + n; i++)
        for (int k = 0; k < columns; k++) rows[i][k] = buf[m++];
    }
    int pack_reverse_comm(int n, int first, double *buf) override
    {
      int m = 0;
      for (int i = first; i < first + n; i++)
        for (int k = 0; k < columns; k++) buf[m++] = rows[i][k];
      return m;
    }
    void unpack_reverse_comm(int n, int *list, double *buf) override
    {
      int m = 0;
      for (int i = 0; i < n; i++)
        for (int k = 0; k < columns; k++) rows[list[i]][k] += buf[m++];
    }

   private:
    double **rows;    // what pack and unpack move now
    int columns;

    // LAMMPS sizes its buffers by comm_forward and comm_reverse: a component that sends more
    // columns must raise them (the pair style's constructor)
    [[noreturn]] void too_many(int c, int most) const
    {
      error->one(FLERR, "Pair {}: a component exchanges {} columns per atom, more than the {} "
                 "the style declared (comm_forward, comm_reverse)", force->pair_style, c, most);
      std::abort();    // not reached: error->one() throws
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
