/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the audit of fix PAIR_STATE's saved
   pairs at a list build (fix_pair_state.h): before it, at a setup, the
   partners follow atoms renumbered since the save (reset_atoms id,
   delete_atoms compress yes; a partner whose saved ID no atom carries any
   more is dropped); after it, the saved pairs are counted against the list:
   a link whose atom was deleted ended with it (logged, each once), a link
   missing from the list while both its atoms exist is an error.  And the
   count of the saved links (a pair style re-issued reports it).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_STATE_AUDIT_H
#define LMP_CLUSTERDYN_PAIR_STATE_AUDIT_H

#include "lmptype.h"
#include "pointers.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  class FixPairState;

  class PairStateAudit : protected Pointers {
   public:
    PairStateAudit(LAMMPS *lmp, FixPairState &storage) : Pointers(lmp), fix(storage) {}
    void relabel_partners();    // IDs changed since the save: partners follow
    void check_lost_links();    // the saved pairs against the list just built
    bigint count_saved_links();    // links in the atoms' saved pairs, all processors

   private:
    FixPairState &fix;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
