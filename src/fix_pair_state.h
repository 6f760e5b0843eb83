/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix PAIR_STATE, the storage of the
   persistent pair state (class PairState, pair_state.h).  Internal, as fix
   NEIGH_HISTORY is: the pair state creates it at the first init.

   It is fix neigh/history (a flag and dnum values per neighbour pair, kept
   across list builds by atom IDs) storing each pair's saved state once, and
   made safe for everything LAMMPS does to atoms between and inside runs:
   - a save keeps each pair at the atom its list put first (fix
     neigh/history keeps it at both atoms); the next list build looks at both
     atoms, the ghosts' saved pairs sent from their owners first, and turns
     a pair found at its other atom round (transfer_history()); the owner's
     doubles that hold only within a compute are not saved (a bit mask, the
     fix's fifth argument): dnum is the saved entry's width, layout.row the list's;
   - the neighbour data are saved to the atoms only while they describe the
     current atoms (from a list build or a run's setup to the end of the
     run): write_restart after a run no longer saves from a list whose ghost
     indices are stale;
   - the end of every setup saves (rerun: each frame, which has no list
     build inside a run);
   - each atom carries the ID it had when its partners were saved: after
     reset_atoms id or delete_atoms compress yes the partners are relabelled
     to the new IDs, and a partner whose saved ID no atom carries any more is
     dropped, also when an atom created since holds that ID now; an atom
     created since (saved ID 0) is "fresh": its pairs are made at the next
     setup;
   - after each list build the saved links are counted against the list: a
     link whose partner no longer exists ended with its atom (logged), a
     link missing from the list while both atoms exist is an error;
   - in a minimization the owner settles tentative changes before a save;
   - a pair's whole state word (linked, or an unlinked pair that keeps its
     doubles) is saved in the last of its dnum doubles and restored from it
     (the base class restores every saved pair as flag 1);
   - where the owner names a reach (keep_state_within), a list build puts
     first in each atom's list the pairs that keep doubles: those with a
     saved state and those closer than the types' reaches plus the skin, which
     may touch before the next build (as the list's own cutoff plus skin
     holds every pair that may interact); the pairs beyond keep no word (it
     is 0) and no doubles, and the pair style's passes skip them; of the
     kept pairs only those with a saved state get doubles at the build, the
     others when a pass claims them (claim()).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_FIX_PAIR_STATE_H
#define LMP_CLUSTERDYN_FIX_PAIR_STATE_H

#include "atom.h"
#include "fix_neigh_history.h"
#include "pair_state_layout.h"
#include "pair_state_pages.h"
#include "pair_state_slots.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class PairState;

  class FixPairState : public FixNeighHistory {
   public:
    FixPairState(class LAMMPS *, int, char **);
    ~FixPairState() override;
    int setmask() override;
    void init() override;
    void setup(int) override
    {
      nds_current = 1;
      save();
    }
    void min_setup(int vflag) override { setup(vflag); }
    void pre_exchange() override { save(); }
    void min_pre_exchange() override;
    void post_neighbor() override;
    void post_run() override;
    void write_restart(FILE *) override;

    void grow_arrays(int) override;
    void copy_arrays(int, int, int) override;
    void set_arrays(int) override;
    int pack_exchange(int, double *) override;
    int unpack_exchange(int, double *) override;
    int pack_restart(int, double *) override;
    void unpack_restart(int, int) override;
    int size_restart(int) override;
    int maxsize_restart() override;
    int pack_forward_comm(int, int *, double *, int, int *) override;
    void unpack_forward_comm(int, int, double *) override;
    double memory_usage() override;

    PairState *owner;           // settles tentative changes; names the style in errors
    const tagint *forward_saved_ids();    // saved IDs of my atoms and ghosts (0 = fresh)
    bigint count_saved_links();           // links in the atoms' partner arrays, all processors
    void forget();                        // every atom fresh, no partner (a re-issued style)
    // pairs farther apart than reach[type_i] + reach[type_j] + skin at a list build keep no
    // doubles until the next build (empty: every listed pair keeps them)
    void keep_state_within(const std::vector<double> &per_type) { reach = per_type; }
    // per atom of the list: how many of its first listed pairs keep doubles
    const int *state_counts() const { return nstate; }
    // per atom of the list: the doubles of each of those pairs (null: none yet)
    double **const *state_slots() const { return slots.all(); }
    double *claim(int i, int jj);    // pair jj of atom i's list gets its doubles, zeroed

   private:
    friend class PairStateAudit;    // reads and relabels the saved pairs
    tagint *saved_id;           // per atom: its ID when its partners were saved; 0 = fresh
    int nds_current;            // the neighbour data describe the current atoms
    std::vector<double> reach;    // keep_state_within()
    int *nstate;                // state_counts(), maxstate of them
    int maxstate;
    bigint saved_entries;       // pairs my atoms held after the last save or restart
    // forward communication: the saved IDs, or the saved pairs PER_ROUND at a time
    enum { SAVED_IDS, PARTNERS };
    static constexpr int PER_ROUND = 1;
    int forward_mode, forward_round;
    PairStateLayout layout;               // the list's rows and the saved doubles
    PairStateSlots slots;                 // state_slots(), maxstate of them
    PairStatePages ghosts;    // the ghosts' saved pairs during a list build
    void size_pages();        // the pages' sizes (pair_state_pages.h)
    void first_pages()        // a restart file's atoms before the first init
    {
      allocate_pages();
      size_pages();
    }
    void save();
    void save_one_copy();
    // atom i's saved state of its pair with the atom of ID partner_id, seen from i (null: none)
    const double *saved_state(int i, tagint partner_id) const
    {
      for (int m = 0; m < npartner[i]; m++)
        if (partner[i][m] == partner_id) return valuepartner[i] + dnum * m;
      return nullptr;
    }
    // the atom whose saved states atom j's are: j, or the owned atom a ghost is an image of
    // (with an atom map)
    int holder(int j) const
    {
      if (j < atom->nlocal || atom->map_style == Atom::MAP_NONE) return j;
      const int m = atom->map(atom->tag[j]);
      return m >= 0 && m < atom->nlocal ? m : j;
    }
    // after a list build the ghosts keep no saved pairs, and their pages go back to one page each
    void drop_ghost_partners()
    {
      for (int g = atom->nlocal; g < atom->nlocal + atom->nghost; g++) npartner[g] = 0;
      ghosts.drop(error);
    }
    void forward_partners();
    void restore();             // the saved states into the new list (FixNeighHistory's, sorted)
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
