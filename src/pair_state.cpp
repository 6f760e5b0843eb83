/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: persistent pair state (pair_state.h).
------------------------------------------------------------------------- */

#include "pair_state.h"

#include "fix_pair_state.h"
#include "periodic_images.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "neigh_list.h"
#include "output.h"
#include "pair.h"
#include "update.h"

#include <algorithm>
#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

// the internal fix style is known to LAMMPS only while a pair state creates its fix: it is
// not a style of the plugin's list, and users cannot define it
static Fix *create_fix_pair_state(LAMMPS *lmp, int narg, char **arg)
{
  return new FixPairState(lmp, narg, arg);
}

PairState::PairState(LAMMPS *lmp, Pair *owner_pair, const std::string &who, int nv, int nw) :
    Pointers(lmp), pair(owner_pair), name(who), nvalues(nv), nwork(nw), within(0), enabled(0),
    made_flag(0), afresh(0),
    fix(nullptr), pending_step(-1), trial_now(0)
{
}

PairState::~PairState()
{
  if (!enabled) return;
  for (const std::string &id : {std::string(FIX_ID), placeholder()})
    if (modify->get_fix_by_id(id) && (id != FIX_ID || modify->get_fix_by_id(id) == fix))
      modify->delete_fix(id);
}

std::string PairState::placeholder() const
{
  return std::string(FIX_ID) + "_DUMMY";
}

void PairState::add_placeholder()
{
  modify->add_fix(placeholder() + " all DUMMY");
}

/* ----------------------------------------------------------------------
   pair_style with state: the first time a placeholder; re-issued, the
   state starts afresh (its pairs are made again at the next setup)
------------------------------------------------------------------------- */

void PairState::enable()
{
  if (!enabled) {
    check_reserved_ids();
    if (modify->get_fix_by_id(FIX_ID) || modify->get_fix_by_id(placeholder()))
      error->all(FLERR, "{}: another pair style already keeps links (fix {}); one linked pair "
                 "style at a time", name, FIX_ID);
    if (!atom->tag_enable) error->all(FLERR, "{}: link needs atom IDs", name);
    add_placeholder();
    enabled = 1;
    return;
  }
  bigint discarded = 0;
  if (fix && modify->get_fix_by_id(FIX_ID) == fix) {
    discarded = fix->count_saved_links();
    modify->delete_fix(FIX_ID);
  }
  // a fix made later from this placeholder would take the links a restart file left
  // for its ID: it forgets them (init)
  if (!fix) afresh = 1;
  fix = nullptr;
  if (!modify->get_fix_by_id(placeholder())) add_placeholder();
  if (made_flag && comm->me == 0)
    utils::logmesg(lmp, "{}: pair_style re-issued: the {} links of the last run are discarded; "
                   "the pairs are linked afresh at the next setup\n", name, discarded);
  made_flag = 0;
  total = pending = StateTally();
}

// a fix of the user's with the state's IDs
void PairState::check_reserved_ids() const
{
  for (const std::string &id : {std::string(FIX_ID), placeholder()}) {
    const Fix *other = modify->get_fix_by_id(id);
    if (other && other != fix && strcmp(other->style, "DUMMY") != 0 &&
        strcmp(other->style, "PAIR_STATE") != 0)
      error->all(FLERR, "{}: fix ID {} is reserved for the link state (fix {} has it): rename "
                 "that fix", name, id, other->style);
  }
}

void PairState::init()
{
  check_reserved_ids();
  if (!fix) {
    if (!modify->get_fix_by_id(placeholder()))
      error->all(FLERR, "{}: its link state (fix {}) was deleted: re-issue pair_style to link "
                 "afresh", name, placeholder());
    (*modify->fix_map)["PAIR_STATE"] = &create_fix_pair_state;
    fix = dynamic_cast<FixPairState *>(modify->replace_fix(
        placeholder(), fmt::format("{} all PAIR_STATE {} {}", FIX_ID, nvalues + 1, within), 0));
    modify->fix_map->erase("PAIR_STATE");
    fix->pair = pair;
    fix->owner = this;
    if (afresh) fix->forget();
    afresh = 0;
  }
  check_fix();
  fix->keep_state_within(reach);
  check_neighbours();
  consolidate();
}

// what the state fix (FixNeighHistory's scheme) needs from the commands around it
void PairState::check_neighbours() const
{
  // the states are saved by neighbour-list index at pre_exchange: a fix that adds or deletes
  // atoms there must come after the state fix, which stands where pair_style was given
  const int me = modify->find_fix(FIX_ID);
  for (int k = 0; k < me; k++) {
    const Fix *f = modify->get_fix_by_index(k);
    for (const char *style : {"deposit", "evaporate", "pour", "gcmc"})
      if (strcmp(f->style, style) == 0)
        error->all(FLERR, "{}: fix {} ({}) adds or deletes atoms before the link state is saved: "
                   "define it after the pair_style command", name, f->id, f->style);
  }
}

void PairState::check_fix() const
{
  if (!fix || modify->get_fix_by_id(FIX_ID) != fix)
    error->all(FLERR, "{}: its link state (fix {}) was deleted by unfix: re-issue pair_style "
               "to link afresh", name, FIX_ID);
}

/* ---------------------------------------------------------------------- */

double *StatePass::claim(int i, int jj) const
{
  return slots[i][jj] ? slots[i][jj] : store->claim(i, jj);
}

StatePass PairState::begin()
{
  if (neighbor->ago == 0) check_single_images(lmp, name);    // the box may have changed
  trial_now = update->whichflag == 2 && !update->setupflag;
  if (trial_now && pending_step != update->ntimestep) accept();    // a new minimizer step
  pending_step = update->ntimestep;
  StatePass pass;
  pass.words = fix->firstflag;
  pass.slots = fix->state_slots();
  pass.store = fix;
  pass.fresh = update->setupflag ? fix->forward_saved_ids() : nullptr;
  pass.counts = fix->state_counts();
  pass.trial = trial_now;
  return pass;
}

void PairState::end(const StateTally &pass, double *tally_out)
{
  if (trial_now) pending = pass;
  else total.add(pass);
  if (update->setupflag) made_flag = 1;
  // a restart file written at the end of this step carries the global totals
  if (output->restart_flag && output->next_restart == update->ntimestep) consolidate();
  tally_out[0] = total.broken + pending.broken;
  tally_out[1] = total.formed + pending.formed;
  tally_out[2] = total.ejump + pending.ejump;
  for (int k = 0; k < nwork; k++) tally_out[3 + k] = total.work[k] + pending.work[k];
}

void PairState::accept()
{
  if (pending.any()) settle_words(true);
  total.add(pending);
  pending = StateTally();
}

void PairState::settle_before_save()
{
  if (update->whichflag == 2 && pending_step != update->ntimestep) accept();
  else {    // a line search's trial: it never happened
    if (pending.any()) settle_words(false);
    pending = StateTally();
  }
}

void PairState::settle_words(bool accept_trial)
{
  const NeighList *list = pair->list;
  int *const *words = fix->firstflag;
  const int *counts = fix->state_counts();
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < counts[i]; jj++)
      words[i][jj] = (words[i][jj] & WORD_KEPT) |
                     (accept_trial ? state_now(words[i][jj]) : words[i][jj] & 1);
  }
}

StateView PairState::view() const
{
  check_fix();
  return StateView{pair->list, fix->firstflag, fix->state_counts()};
}

/* ---------------------------------------------------------------------- */

// the tally as 3 + nwork numbers, and back
static void tally_to(const StateTally &t, double *v, int nwork)
{
  v[0] = t.broken;
  v[1] = t.formed;
  v[2] = t.ejump;
  for (int k = 0; k < nwork; k++) v[3 + k] = t.work[k];
}

static StateTally tally_from(const double *v, int nwork)
{
  StateTally t;
  t.broken = v[0];
  t.formed = v[1];
  t.ejump = v[2];
  for (int k = 0; k < nwork; k++) t.work[k] = v[3 + k];
  return t;
}

void PairState::consolidate()
{
  const int n = 3 + nwork;
  double mine[3 + StateTally::MAXWORK], all[3 + StateTally::MAXWORK];
  tally_to(total, mine, nwork);
  MPI_Allreduce(mine, all, n, MPI_DOUBLE, MPI_SUM, world);
  total = comm->me == 0 ? tally_from(all, nwork) : StateTally();
}

// processor 0, for the pair style's restart section
void PairState::write_restart(FILE *fp)
{
  // read_restart, then write_restart noinit: the states are still in the read file's atom
  // data, restored into the state fix at the next setup; this file would lose them
  if (made_flag && !fix)
    error->one(FLERR, "{}: write_restart noinit before the link state read from a restart file "
               "is restored (at a setup) would lose it: leave out noinit, or run 0 first", name);
  fwrite(&made_flag, sizeof(int), 1, fp);
  double sums[3 + StateTally::MAXWORK];
  tally_to(total, sums, nwork);
  fwrite(sums, sizeof(double), 3 + nwork, fp);
}

void PairState::read_restart(FILE *fp)
{
  double sums[3 + StateTally::MAXWORK] = {};
  if (comm->me == 0) {
    utils::sfread(FLERR, &made_flag, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, sums, sizeof(double), 3 + nwork, fp, nullptr, error);
  }
  MPI_Bcast(&made_flag, 1, MPI_INT, 0, world);
  // the totals stay on processor 0 (consolidate)
  total = comm->me == 0 ? tally_from(sums, nwork) : StateTally();
}
