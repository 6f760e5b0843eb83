/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix PAIR_STATE (fix_pair_state.h).
------------------------------------------------------------------------- */

#include "fix_pair_state.h"

#include "pair_state.h"
#include "pair_state_audit.h"
#include "pair_state_pages.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "my_page.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include <algorithm>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

// ID group PAIR_STATE row [within]: row, the doubles per pair (the owner's and the word's
// slot); within, a bit mask of the owner's doubles that live within a step (not saved)
FixPairState::FixPairState(LAMMPS *lmp, int narg, char **arg) :
    FixNeighHistory(lmp, 4, arg), owner(nullptr), saved_id(nullptr), nds_current(0),
    nstate(nullptr), maxstate(0), saved_entries(0), forward_mode(SAVED_IDS), forward_round(0)
{
  if (narg != 4 && narg != 5) error->all(FLERR, "Illegal fix PAIR_STATE command");
  layout.choose(dnum, narg == 5 ? utils::inumeric(FLERR, arg[4], false, lmp) : 0);
  slots.set_row(layout.row);
  dnum = layout.saved();    // FixNeighHistory's per-atom copies: the saved doubles
  dnumbytes = dnum * sizeof(double);
  comm_forward = 1 + PER_ROUND * (dnum + 1);    // the partner rounds; the saved IDs take 1
  memory->create(saved_id, atom->nmax, "pair_state:saved_id");
  for (int i = 0; i < atom->nmax; i++) saved_id[i] = 0;
}

FixPairState::~FixPairState()
{
  memory->destroy(saved_id);
  memory->destroy(nstate);
}

int FixPairState::setmask()
{
  return FixNeighHistory::setmask();    // setup(), min_setup() and post_run() need no mask
}

// FixNeighHistory's checks and pages; their sizes where it made them anew (the first init, or
// neigh_modify page or one changed), the saved pairs carried into them (pair_state_pages.h)
void FixPairState::init()
{
  const bool anew = !ipage_atom || pgsize != neighbor->pgsize || oneatom != neighbor->oneatom;
  PairStatePages::Carried carried;
  if (anew && ipage_atom)
    carried = PairStatePages::carry_out(atom->nlocal, npartner, partner, valuepartner, dnum);
  FixNeighHistory::init();
  if (!anew) return;
  size_pages();
  PairStatePages::carry_in(carried, npartner, partner, valuepartner, dnum, *ipage_atom,
                           *dpage_atom, error);
}

void FixPairState::size_pages()
{
  for (int t = 0; t < comm->nthreads; t++) {
    PairStatePages::size(ipage_atom[t], oneatom, error);
    PairStatePages::size(dpage_atom[t], dnum * oneatom, error);
    PairStatePages::size(ipage_neigh[t], oneatom, error);
    PairStatePages::size(dpage_neigh[t], layout.row * oneatom, error);
  }
  ghosts.size_ghosts(oneatom, dnum, error);
}

/* ----------------------------------------------------------------------
   copy the neighbour data to the atoms; my atoms remember their IDs
------------------------------------------------------------------------- */

void FixPairState::save()
{
  const NeighList *list = pair->list;
  if (list)
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      for (int jj = 0; jj < nstate[i]; jj++)
        if (firstflag[i][jj]) {
          double *v = slots.all()[i][jj] ? slots.all()[i][jj] : claim(i, jj);
          v[layout.row - 1] = firstflag[i][jj];
        }
    }
  save_one_copy();
  maxexchange += 1;    // saved_id
  const tagint *tag = atom->tag;
  for (int i = 0; i < nlocal_neigh; i++) saved_id[i] = tag[i];
}

// each pair's state once, at the atom its list puts first (an owned atom; with newton off a
// pair with a ghost is listed on both processors, and the one whose atom has the smaller ID
// keeps it); FixNeighHistory::pre_exchange() keeps it at both atoms.  The next list build finds
// it at either atom (restore())
void FixPairState::save_one_copy()
{
  ipage_atom->reset();
  dpage_atom->reset();
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < std::max(nall_neigh, nall); i++) npartner[i] = 0;
  const tagint *tag = atom->tag;
  const NeighList *list = pair->list;
  const auto keeps = [&](int i, int jj) {
    const int j = list->firstneigh[i][jj] & NEIGHMASK;
    return firstflag[i][jj] && (newton_pair || j < nlocal_neigh || tag[i] <= tag[j]);
  };
  saved_entries = 0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    int n = 0;
    for (int jj = 0; jj < nstate[i]; jj++) n += keeps(i, jj);
    partner[i] = ipage_atom->get(n);
    valuepartner[i] = dpage_atom->get(dnum * n);
    if (!partner[i] || !valuepartner[i])
      error->one(FLERR, "Neighbor history overflow, boost neigh_modify one");
    for (int jj = 0; jj < nstate[i]; jj++)
      if (keeps(i, jj)) {
        const int m = npartner[i]++;
        partner[i][m] = tag[list->firstneigh[i][jj] & NEIGHMASK];
        layout.to_saved(slots.all()[i][jj], valuepartner[i] + dnum * m);
      }
    saved_entries += n;
  }
  maxpartner = 0;
  for (int i = 0; i < nlocal_neigh; i++) maxpartner = std::max(maxpartner, npartner[i]);
  maxexchange = (dnum + 1) * maxpartner + 1;
  for (int i = nlocal_neigh; i < atom->nlocal; i++) npartner[i] = 0;
}

void FixPairState::min_pre_exchange()
{
  if (owner) owner->settle_before_save();
  save();
}

void FixPairState::post_run()
{
  if (owner) owner->run_ended();
  save();
  nds_current = 0;    // commands between runs may move, delete or renumber atoms
}

// during a run the neighbour data are current; between runs post_run() has saved them
void FixPairState::write_restart(FILE *fp)
{
  if (nds_current) {
    if (owner) owner->accept();
    save();
  }
  if (comm->me == 0) {
    int size = 0;
    fwrite(&size, sizeof(int), 1, fp);
  }
}

/* ----------------------------------------------------------------------
   after a list build: partners follow renumbered IDs, then the base class
   restores the flags, then every saved link must be in the list
------------------------------------------------------------------------- */

void FixPairState::post_neighbor()
{
  PairStateAudit audit(lmp, *this);
  if (update->setupflag) audit.relabel_partners();
  restore();
  nds_current = 1;
  audit.check_lost_links();
  drop_ghost_partners();
}

// FixNeighHistory::post_neighbor() (its pair style keeps every listed pair, beyond_contact),
// with each atom's list sorted: the pairs that keep doubles first, in their order, then the
// rest in theirs (a pass over the first ones sums as one over all did)
void FixPairState::restore()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  nlocal_neigh = nlocal;
  nall_neigh = nall;
  if (maxatom < nlocal) {
    memory->sfree(firstflag);
    maxatom = nall;
    firstflag = (int **) memory->smalloc(maxatom * sizeof(int *), "neighbor_history:firstflag");
  }
  if (maxstate < nlocal) {
    maxstate = nall;
    memory->destroy(nstate);
    memory->create(nstate, maxstate, "pair_state:nstate");
    slots.grow(maxstate);
  }
  ipage_neigh->reset();
  dpage_neigh->reset();
  slots.renew();

  const tagint *tag = atom->tag;
  const bool all = reach.empty();
  const int *type = atom->type;
  double *const *x = atom->x;
  const double skin = neighbor->skin;
  NeighList *list = pair->list;
  forward_partners();
  std::vector<int> kept, rest;    // the list's entries that keep doubles, and the others
  std::vector<const double *> found;    // the kept ones' saved states (null: none)
  std::vector<int> turned;              // found at the other atom: seen from it
  std::vector<double> seen(layout.row);    // such a state as its other atom saw it
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    kept.clear();
    found.clear();
    turned.clear();
    rest.clear();
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & HISTMASK;    // the history bit of a size list means nothing here
      const int jn = j & NEIGHMASK;
      int round = 0;
      const double *saved = saved_state(i, tag[jn]);
      if (!saved && (saved = saved_state(holder(jn), tag[i]))) round = 1;
      bool near = saved || all;
      if (!near) {
        const double dx = x[jn][0] - x[i][0], dy = x[jn][1] - x[i][1], dz = x[jn][2] - x[i][2];
        const double far = reach[type[i]] + reach[type[jn]] + skin;
        near = dx * dx + dy * dy + dz * dz < far * far;
      }
      if (near) {
        kept.push_back(j);
        found.push_back(saved);
        turned.push_back(round);
      } else rest.push_back(j);
    }
    const int nkept = kept.size();
    std::copy(kept.begin(), kept.end(), jlist);
    std::copy(rest.begin(), rest.end(), jlist + nkept);
    nstate[i] = nkept;
    int *flags = firstflag[i] = ipage_neigh->get(nkept);    // the rest's words are 0
    for (int jj = 0; jj < nkept; jj++) flags[jj] = 0;
    // doubles for the pairs with a saved state; the others claim theirs when they need them
    int nfound = 0;
    for (const double *saved : found) nfound += saved != nullptr;
    double *v = dpage_neigh->get(nfound * layout.row);
    if (!v) error->one(FLERR, "Neighbor history overflow, boost neigh_modify one");
    double **slot = slots.of(i, nkept);
    for (int jj = 0; jj < nkept; jj++) {
      slot[jj] = found[jj] ? v : nullptr;
      if (!found[jj]) continue;
      const int jn = kept[jj] & NEIGHMASK;
      if (!turned[jj]) layout.to_row(found[jj], v);
      else {
        layout.to_row(found[jj], seen.data());
        if (pair->nondefault_history_transfer)
          pair->transfer_history(seen.data(), v, type[jn], type[i]);
        else
          for (int k = 0; k < layout.row; k++) v[k] = -seen[k];
      }
      flags[jj] = PairStateLayout::word(v, layout.row);
      v += layout.row;
    }
  }
}

// the doubles of a pair that had none since the list was built, zeroed
double *FixPairState::claim(int i, int jj)
{
  double *v = slots.claim(i, jj);
  if (!v) error->one(FLERR, "Neighbor history overflow, boost neigh_modify one");
  return v;
}

// the ghosts' saved states from their owners (a pair the new list turned round is kept at its
// other atom, which may be a ghost now), PER_ROUND of each atom's per forward communication;
// a ghost that is an image of an owned atom (holder()) keeps none: on one processor no ghost
// needs them; they are dropped after the build (drop_ghost_partners())
void FixPairState::forward_partners()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  for (int i = nlocal; i < nall; i++) npartner[i] = 0;
  ghosts.reset();
  if (comm->nprocs == 1 && atom->map_style != Atom::MAP_NONE) return;
  int most = 0, most_all;
  for (int i = 0; i < nlocal; i++) most = std::max(most, npartner[i]);
  MPI_Allreduce(&most, &most_all, 1, MPI_INT, MPI_MAX, world);
  forward_mode = PARTNERS;
  for (forward_round = 0; forward_round * PER_ROUND < most_all; forward_round++)
    comm->forward_comm(this);
  forward_mode = SAVED_IDS;
}

void FixPairState::forget()
{
  for (int i = 0; i < atom->nlocal; i++) {
    npartner[i] = 0;
    saved_id[i] = 0;
  }
  saved_entries = 0;
}

const tagint *FixPairState::forward_saved_ids()
{
  comm->forward_comm(this);
  return saved_id;
}

bigint FixPairState::count_saved_links()
{
  return PairStateAudit(lmp, *this).count_saved_links();
}

/* ----------------------------------------------------------------------
   the saved ID travels with its atom
------------------------------------------------------------------------- */

void FixPairState::grow_arrays(int nmax)
{
  FixNeighHistory::grow_arrays(nmax);
  memory->grow(saved_id, nmax, "pair_state:saved_id");
}

void FixPairState::copy_arrays(int i, int j, int delflag)
{
  FixNeighHistory::copy_arrays(i, j, delflag);
  saved_id[j] = saved_id[i];
}

void FixPairState::set_arrays(int i)
{
  FixNeighHistory::set_arrays(i);
  saved_id[i] = 0;
}

int FixPairState::pack_exchange(int i, double *buf)
{
  int m = FixNeighHistory::pack_exchange(i, buf);
  buf[m++] = ubuf(saved_id[i]).d;
  return m;
}

int FixPairState::unpack_exchange(int nlocal, double *buf)
{
  int m = FixNeighHistory::unpack_exchange(nlocal, buf);
  saved_id[nlocal] = (tagint) ubuf(buf[m++]).i;
  return m;
}

// FixNeighHistory's record, the saved ID, and ONE_COPY: each pair is saved once (a record
// without it, from before, holds each pair at both atoms)
int FixPairState::pack_restart(int i, double *buf)
{
  int m = FixNeighHistory::pack_restart(i, buf);
  buf[m++] = ubuf(saved_id[i]).d;
  buf[m++] = PairStateLayout::ONE_COPY;
  buf[0] = m;
  return m;
}

void FixPairState::unpack_restart(int nlocal, int nth)
{
  if (ipage_atom == nullptr) first_pages();
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const double *record = extra[nlocal] + m;
  const int length = static_cast<int>(record[0]), n = static_cast<int>(record[1]);
  const PairStateLayout::Record kind = layout.record(length, n, record[length - 1]);
  if (kind == PairStateLayout::UNKNOWN)
    error->one(FLERR, "Fix {}: a restart record of {} values for {} pairs of {} doubles: the "
               "file was written by another pair style or plugin", id, length, n, layout.row - 1);
  saved_id[nlocal] = layout.owner_id(record + 2, n, kind);
  partner[nlocal] = ipage_atom->get(n);
  valuepartner[nlocal] = dpage_atom->get(dnum * n);
  if (!partner[nlocal] || !valuepartner[nlocal])
    error->one(FLERR, "Fix {}: an atom of the restart file keeps {} saved pairs, more than "
               "neigh_modify one allows: boost neigh_modify one", id, n);
  npartner[nlocal] =
      layout.read(record + 2, n, kind, saved_id[nlocal], partner[nlocal], valuepartner[nlocal]);
  maxpartner = std::max(maxpartner, npartner[nlocal]);
  saved_entries += npartner[nlocal];
}

int FixPairState::size_restart(int nlocal)
{
  return FixNeighHistory::size_restart(nlocal) + 2;
}

int FixPairState::maxsize_restart()
{
  return FixNeighHistory::maxsize_restart() + 2;
}

int FixPairState::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  if (forward_mode == SAVED_IDS) {
    for (int k = 0; k < n; k++) buf[k] = ubuf(saved_id[list[k]]).d;
    return n;
  }
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int i = holder(list[k]), first = forward_round * PER_ROUND;
    if (first == 0) buf[m++] = npartner[i];
    for (int e = first; e < std::min(npartner[i], first + PER_ROUND); e++) {
      buf[m++] = ubuf(partner[i][e]).d;
      memcpy(buf + m, valuepartner[i] + dnum * e, dnumbytes);
      m += dnum;
    }
  }
  return m;
}

void FixPairState::unpack_forward_comm(int n, int first, double *buf)
{
  if (forward_mode == SAVED_IDS) {
    for (int k = 0; k < n; k++) saved_id[first + k] = (tagint) ubuf(buf[k]).i;
    return;
  }
  int m = 0;
  for (int g = first; g < first + n; g++) {
    const int from = forward_round * PER_ROUND;
    const bool kept = holder(g) == g;    // an image of an owned atom keeps none
    if (from == 0) {
      npartner[g] = static_cast<int>(buf[m++]);
      partner[g] = kept ? ghosts.ghost_ids(npartner[g]) : nullptr;
      valuepartner[g] = kept ? ghosts.ghost_values(npartner[g]) : nullptr;
      if (kept && (!partner[g] || !valuepartner[g]))
        error->one(FLERR, "Neighbor history overflow, boost neigh_modify one");
    }
    for (int e = from; e < std::min(npartner[g], from + PER_ROUND); e++, m += 1 + dnum)
      if (kept) {
        partner[g][e] = (tagint) ubuf(buf[m]).i;
        memcpy(valuepartner[g] + dnum * e, buf + m + 1, dnumbytes);
      }
  }
}

double FixPairState::memory_usage()
{
  return FixNeighHistory::memory_usage() + (double) atom->nmax * sizeof(tagint) +
      (double) maxstate * (sizeof(int) + sizeof(double **)) +
      slots.bytes() + ghosts.bytes();
}
