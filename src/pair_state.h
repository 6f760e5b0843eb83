/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: persistent pair state, the component
   a pair style composes to keep a state per neighbour pair (a flag, e.g.
   linked, and a fixed number of doubles) across list builds, restarts,
   atom migration, deletion and renumbering, minimization and rerun.

   It owns the lifecycle of its storage, fix PAIR_STATE (fix_pair_state.h):
   a placeholder fix at pair_style (as the granular styles do), replaced at
   the first init; the pairs of "fresh" atoms (all atoms after pair_style,
   atoms created since) are made at the next setup; the tally of changes
   (breaks, welds, energy jumps) with its restart; and the one accessor the
   computes use (view()).

   A pair style calls begin() at the start of compute() and end() after
   it; its kernel writes each pair's state word through state_word().  A
   pair that is not linked may still keep its doubles (a contact's
   friction): its word has the bit WORD_KEPT; a word of 0 keeps nothing.
   outside a minimization the word is the state; inside one, a trial point
   (a line-search evaluation) only marks its change (bit 1) and the change
   counts when the minimizer accepts the step (the next iteration, a save
   or the end of the run) - trial points never break or make pairs.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PAIR_STATE_H
#define LMP_CLUSTERDYN_PAIR_STATE_H

#include "lmptype.h"
#include "pointers.h"

#include <cstdio>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class NeighList;
class Pair;
namespace ClusterDyn {

  class FixPairState;

  // the changes of the pair states (a pair with a ghost counts 1/2 with newton off, as
  // both processors see it)
  struct StateTally {
    static constexpr int MAXWORK = 4;
    double broken = 0.0;    // pairs whose state went from 1 to 0
    double formed = 0.0;    // pairs whose state went from 0 to 1 during a run
    double ejump = 0.0;     // the sum of the pair-energy jumps of those changes
    double work[MAXWORK] = {0.0, 0.0, 0.0, 0.0};    // energies the owner tallies (dissipation)
    void add(const StateTally &o)
    {
      broken += o.broken;
      formed += o.formed;
      ejump += o.ejump;
      for (int k = 0; k < MAXWORK; k++) work[k] += o.work[k];
    }
    bool any() const { return broken != 0.0 || formed != 0.0; }
  };

  // how a pair's state may change in this evaluation: kept (only breaking), made at a setup
  // (a pair of a fresh atom: no tally), remade during a run (tallied)
  enum Making { MAKE_NONE = 0, MAKE_INITIAL = 1, MAKE_AGAIN = 2 };

  // a pair's state word: bit 0 = the state last accepted, bit 1 = a trial changed it,
  // bit 2 = an unlinked pair that keeps its doubles
  enum : int { WORD_KEPT = 4 };
  inline int state_now(int word)
  {
    return (word ^ (word >> 1)) & 1;
  }
  inline int state_word(int word, int now, int trial)
  {
    return (word & WORD_KEPT) | (trial ? (word & 1) | ((now ^ (word & 1)) << 1) : now);
  }
  inline int kept_word(int word, bool kept)
  {
    return kept ? word | WORD_KEPT : word & ~WORD_KEPT;
  }

  // what one force evaluation reads and writes
  struct StatePass {
    int *const *words;          // per neighbour pair of the pair style's list
    // per pair that may keep doubles (the first counts[i] of atom i's list): its nvalues + 1
    // doubles (the owner's, then the word's slot), null where the pair has none yet (the
    // pairs with no saved state get them when they claim them: claim())
    double **const *slots;
    FixPairState *store;
    const tagint *fresh;        // at a setup: per atom (own and ghost), 0 = fresh; else null
    const int *counts;          // per atom of the list: its first pairs that keep doubles
    int trial;                  // a minimizer's trial point: see state_word()
    double *pair_values(int i, int jj) const { return slots[i][jj]; }
    // the pair's doubles, zeroed if it had none (not thread-safe: the passes of pair mca)
    double *claim(int i, int jj) const;
  };

  // what the computes read: the state of pair jj of atom i is state_now(words[i][jj]) for the
  // first counts[i] pairs of its list (which hold every link), 0 for the rest
  struct StateView {
    const NeighList *list;
    int *const *words;          // null on a processor that has had no atoms
    const int *counts;
  };

  class PairState : protected Pointers {
   public:
    // nwork: the owner's energy sums in StateTally::work, reported after the three counts
    PairState(LAMMPS *, Pair *, const std::string &who, int nvalues, int nwork = 0);
    ~PairState();

    static constexpr const char *FIX_ID = "NEIGH_HISTORY_LINK";
    void enable();             // pair_style: a placeholder fix; again: the state starts afresh
    bool on() const { return enabled; }
    // pairs farther apart than reach[type_i] + reach[type_j] plus the neighbor skin at a list
    // build keep no doubles and word 0 until the next build: the owner's pairs of those types
    // never link or touch farther apart; empty (the default): every listed pair keeps them
    void keep_state_within(std::vector<double> per_type) { reach = std::move(per_type); }
    // the owner's doubles (indices) that hold only within a compute (written before they are
    // read in each): not saved, zero after a list build
    void within_compute(std::initializer_list<int> indices)
    {
      for (const int k : indices) within |= 1 << k;
    }
    void init();               // init_style(): the fix replaces its placeholder
    StatePass begin();         // start of compute()
    void end(const StateTally &pass, double *tally_out);    // tally_out: 3 + nwork (pvector)
    // the default transfer of a pair's doubles to the partner negates them: a pair style with
    // its own transfer_history() copies the word's slot with this
    void transfer_word(const double *source, double *target) const
    {
      target[nvalues] = source[nvalues];
    }
    bool made() const { return made_flag; }
    StateView view() const;
    const char *who() const { return name.c_str(); }
    // what the owner can say when links leave the neighbour list during a run (called on every
    // processor: it may communicate); empty: nothing
    void explain_lost_links(std::function<std::string()> why) { lost_links = std::move(why); }
    std::string lost_links_explained() const { return lost_links ? lost_links() : std::string(); }
    void write_restart(FILE *);
    void read_restart(FILE *);

    // called by the fix: a minimizer's step is accepted, or (before a save) settled; at the
    // end of a run also the totals onto processor 0 (for a write_restart noinit)
    void accept();
    void settle_before_save();
    void run_ended()
    {
      accept();
      consolidate();
    }

   private:
    Pair *pair;
    std::string name;          // the pair style, for messages
    std::function<std::string()> lost_links;    // explain_lost_links()
    int nvalues, nwork;
    int within;                // within_compute(): a bit per index
    std::vector<double> reach;    // keep_state_within()
    int enabled, made_flag;
    int afresh;                // re-issued before the fix was made: forget restored links
    FixPairState *fix;         // null until the first init
    StateTally total;          // this processor's share since the state was made
    StateTally pending;        // a minimizer's last evaluation, not yet accepted
    bigint pending_step;
    int trial_now;

    std::string placeholder() const;
    void add_placeholder();
    void check_fix() const;
    void check_neighbours() const;
    void check_reserved_ids() const;
    void settle_words(bool accept_trial);    // words = state_now (accept) or bit 0 (drop)
    void consolidate();        // every processor's share onto processor 0
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
