/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix PAIR_STATE (fix_pair_state.h).
------------------------------------------------------------------------- */

#include "fix_pair_state.h"

#include "mpi_collectives.h"
#include "pair_state.h"

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
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <unordered_set>
#include <vector>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

FixPairState::FixPairState(LAMMPS *lmp, int narg, char **arg) :
    FixNeighHistory(lmp, narg, arg), owner(nullptr), saved_id(nullptr), nds_current(0),
    nstate(nullptr), maxstate(0)
{
  comm_forward = 1;
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

/* ----------------------------------------------------------------------
   copy the neighbour data to the atoms; my atoms remember their IDs
------------------------------------------------------------------------- */

// a pair's word rides in the last of its doubles: the base class keeps only a flag
static int word_of(const double *values, int dnum)
{
  return static_cast<int>(fabs(values[dnum - 1]));
}

void FixPairState::save()
{
  const NeighList *list = pair->list;
  if (list)
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      for (int jj = 0; jj < list->numneigh[i]; jj++)
        if (firstflag[i][jj]) firstvalue[i][dnum * jj + dnum - 1] = firstflag[i][jj];
    }
  FixNeighHistory::pre_exchange();
  maxexchange += 1;    // saved_id
  const tagint *tag = atom->tag;
  for (int i = 0; i < nlocal_neigh; i++) saved_id[i] = tag[i];
}

void FixPairState::setup(int)
{
  nds_current = 1;
  save();
}

void FixPairState::min_setup(int)
{
  nds_current = 1;
  save();
}

void FixPairState::pre_exchange()
{
  save();
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
  if (update->setupflag) relabel_partners();
  restore();
  nds_current = 1;
  check_lost_links();
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
    memory->sfree(firstvalue);
    maxatom = nall;
    firstflag = (int **) memory->smalloc(maxatom * sizeof(int *), "neighbor_history:firstflag");
    firstvalue =
        (double **) memory->smalloc(maxatom * sizeof(double *), "neighbor_history:firstvalue");
  }
  if (maxstate < nlocal) {
    maxstate = nall;
    memory->destroy(nstate);
    memory->create(nstate, maxstate, "pair_state:nstate");
  }
  ipage_neigh->reset();
  dpage_neigh->reset();

  const tagint *tag = atom->tag;
  const bool all = reach.empty();
  const int *type = atom->type;
  double *const *x = atom->x;
  const double skin = neighbor->skin;
  NeighList *list = pair->list;
  std::vector<int> kept, found, rest;    // the list's entries that keep doubles, their partner
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    kept.clear();
    found.clear();
    rest.clear();
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & HISTMASK;    // the history bit of a size list means nothing here
      const int jn = j & NEIGHMASK;
      int m = 0;
      while (m < npartner[i] && partner[i][m] != tag[jn]) m++;
      bool near = m < npartner[i] || all;
      if (!near) {
        const double dx = x[jn][0] - x[i][0], dy = x[jn][1] - x[i][1], dz = x[jn][2] - x[i][2];
        const double far = reach[type[i]] + reach[type[jn]] + skin;
        near = dx * dx + dy * dy + dz * dz < far * far;
      }
      if (near) {
        kept.push_back(j);
        found.push_back(m);
      } else rest.push_back(j);
    }
    const int nkept = kept.size();
    std::copy(kept.begin(), kept.end(), jlist);
    std::copy(rest.begin(), rest.end(), jlist + nkept);
    nstate[i] = nkept;
    int *flags = firstflag[i] = ipage_neigh->get(jnum);
    double *values = firstvalue[i] = dpage_neigh->get(nkept * dnum);
    for (int jj = 0; jj < jnum; jj++) flags[jj] = 0;
    for (int jj = 0; jj < nkept; jj++) {
      double *v = values + dnum * jj;
      if (found[jj] < npartner[i]) {
        memcpy(v, valuepartner[i] + dnum * found[jj], dnumbytes);
        flags[jj] = word_of(v, dnum);
      } else memcpy(v, zeroes, dnumbytes);
    }
  }
}

void FixPairState::forget()
{
  for (int i = 0; i < atom->nlocal; i++) {
    npartner[i] = 0;
    saved_id[i] = 0;
  }
}

const tagint *FixPairState::forward_saved_ids()
{
  comm->forward_comm(this);
  return saved_id;
}

void FixPairState::relabel_partners()
{
  const int nlocal = atom->nlocal;
  const tagint *tag = atom->tag;
  // an atom renumbered since the save, or one created since (saved ID 0): it may hold the ID
  // of an atom deleted since, to which saved partners still point (delete_atoms, then
  // create_atoms, gives the freed highest IDs out again)
  int changed = 0, any;
  for (int i = 0; i < nlocal && !changed; i++)
    if ((npartner[i] && saved_id[i] != tag[i]) || !saved_id[i]) changed = 1;
  MPI_Allreduce(&changed, &any, 1, MPI_INT, MPI_MAX, world);
  if (!any) return;

  // old ID -> new ID: of my atoms and ghosts, then of the others' atoms for the rest
  forward_saved_ids();
  const int nall = nlocal + atom->nghost;
  std::unordered_map<tagint, tagint> renamed(2 * nall);
  for (int i = 0; i < nall; i++)
    if (saved_id[i]) renamed.emplace(saved_id[i], tag[i]);
  std::vector<tagint> unknown;
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < npartner[i]; m++)
      if (!renamed.count(partner[i][m])) unknown.push_back(partner[i][m]);
  std::sort(unknown.begin(), unknown.end());
  unknown.erase(std::unique(unknown.begin(), unknown.end()), unknown.end());
  const std::vector<tagint> asked = allgatherv(unknown, MPI_LMP_TAGINT, world);
  const int ntotal = asked.size();
  std::vector<tagint> mine(ntotal, 0), answer(ntotal);
  std::unordered_map<tagint, tagint> owned(2 * nlocal);
  for (int i = 0; i < nlocal; i++)
    if (saved_id[i]) owned.emplace(saved_id[i], tag[i]);
  for (int k = 0; k < ntotal; k++) {
    const auto it = owned.find(asked[k]);
    if (it != owned.end()) mine[k] = it->second;
  }
  MPI_Allreduce(mine.data(), answer.data(), ntotal, MPI_LMP_TAGINT, MPI_MAX, world);
  for (int k = 0; k < ntotal; k++) renamed.emplace(asked[k], answer[k]);    // 0: deleted
  for (int i = 0; i < nlocal; i++) {
    for (int m = 0; m < npartner[i]; m++) partner[i][m] = renamed[partner[i][m]];
    if (saved_id[i]) saved_id[i] = tag[i];
  }
}

void FixPairState::check_lost_links()
{
  const int nlocal = atom->nlocal;
  const NeighList *list = pair->list;
  double mine[2] = {0.0, 0.0}, all[2];    // partner entries of my atoms, links in my list
  for (int i = 0; i < nlocal; i++) mine[0] += npartner[i];
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < list->numneigh[i]; jj++)
      if (firstflag[i][jj])
        mine[1] += newton_pair || (list->firstneigh[i][jj] & NEIGHMASK) < nlocal ? 1.0 : 0.5;
  }
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_SUM, world);
  if (all[0] <= 2.0 * all[1] + 0.25) return;

  // partner entries whose atom no longer exists (0: deleted while IDs were renumbered)
  const tagint *tag = atom->tag;
  std::unordered_set<tagint> here(tag, tag + nlocal + atom->nghost), owned(tag, tag + nlocal);
  std::vector<tagint> away;
  double gone = 0.0;
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < npartner[i]; m++) {
      if (partner[i][m] == 0) gone += 1.0;
      else if (!here.count(partner[i][m])) away.push_back(partner[i][m]);
    }
  const std::vector<tagint> asked = allgatherv(away, MPI_LMP_TAGINT, world);
  const int ntotal = asked.size();
  std::vector<int> exists(ntotal, 0), found(ntotal);
  for (int k = 0; k < ntotal; k++) exists[k] = owned.count(asked[k]) ? 1 : 0;
  MPI_Allreduce(exists.data(), found.data(), ntotal, MPI_INT, MPI_MAX, world);
  std::unordered_set<tagint> deleted;
  for (int k = 0; k < ntotal; k++)
    if (!found[k]) deleted.insert(asked[k]);
  for (const tagint t : away)
    if (deleted.count(t)) gone += 1.0;
  double gone_all;
  MPI_Allreduce(&gone, &gone_all, 1, MPI_DOUBLE, MPI_SUM, world);

  const double lost = 0.5 * (all[0] - 2.0 * all[1] - gone_all);    // links, not ends
  if (lost > 0.25 && update->setupflag)
    error->all(FLERR, "{}: {:.0f} links left the neighbour list unbroken (fix {}): their atoms "
               "are farther apart than the list's cutoff before this run: atoms were moved since "
               "the last run (displace_atoms, set, change_box, read_dump ...) or linked pairs "
               "excluded (neigh_modify exclude); move them less, keep linked pairs in the list, "
               "or restart the links (pair_style anew)", owner ? owner->who() : "Pair state",
               lost, id);
  if (lost > 0.25) {
    const std::string why = owner ? owner->lost_links_explained() : std::string();
    error->all(FLERR, "{}: {:.0f} links left the neighbour list unbroken (fix {}): {}their atoms "
               "are farther apart than the list's cutoff; raise the neighbor skin or comm_modify "
               "cutoff{}, and do not exclude linked pairs (neigh_modify exclude)",
               owner ? owner->who() : "Pair state", lost, id, why.empty() ? "" : why + "; else ",
               update->whichflag == 2 ? " or reduce min_modify dmax (a line search's trial "
               "point moved them)" : "");
  }
  if (gone_all > 0.0 && comm->me == 0)
    utils::logmesg(lmp, "{}: {:.0f} links ended with their deleted atoms\n",
                   owner ? owner->who() : "Pair state", gone_all);
}

bigint FixPairState::count_saved_links()
{
  bigint mine = 0, all;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < npartner[i]; m++) mine += word_of(valuepartner[i] + dnum * m, dnum) & 1;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return all / 2;
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

int FixPairState::pack_restart(int i, double *buf)
{
  int m = FixNeighHistory::pack_restart(i, buf);
  buf[m++] = ubuf(saved_id[i]).d;
  buf[0] = m;
  return m;
}

void FixPairState::unpack_restart(int nlocal, int nth)
{
  FixNeighHistory::unpack_restart(nlocal, nth);
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m += static_cast<int>(extra[nlocal][m]) - 1;    // the last value of my record
  saved_id[nlocal] = (tagint) ubuf(extra[nlocal][m]).i;
}

int FixPairState::size_restart(int nlocal)
{
  return FixNeighHistory::size_restart(nlocal) + 1;
}

int FixPairState::maxsize_restart()
{
  return FixNeighHistory::maxsize_restart() + 1;
}

int FixPairState::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  for (int k = 0; k < n; k++) buf[k] = ubuf(saved_id[list[k]]).d;
  return n;
}

void FixPairState::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) saved_id[first + k] = (tagint) ubuf(buf[k]).i;
}

double FixPairState::memory_usage()
{
  return FixNeighHistory::memory_usage() + (double) atom->nmax * sizeof(tagint) +
      (double) maxstate * sizeof(int);
}
