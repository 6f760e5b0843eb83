/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the audit of fix PAIR_STATE's saved
   pairs at a list build (pair_state_audit.h).
------------------------------------------------------------------------- */

#include "pair_state_audit.h"

#include "fix_pair_state.h"
#include "mpi_collectives.h"
#include "pair_state.h"
#include "pair_state_layout.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "neigh_list.h"
#include "pair.h"
#include "update.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

void PairStateAudit::relabel_partners()
{
  const int nlocal = atom->nlocal;
  const tagint *tag = atom->tag;
  // an atom renumbered since the save, or one created since (saved ID 0): it may hold the ID
  // of an atom deleted since, to which saved partners still point (delete_atoms, then
  // create_atoms, gives the freed highest IDs out again)
  int changed = 0, any;
  for (int i = 0; i < nlocal && !changed; i++)
    if ((fix.npartner[i] && fix.saved_id[i] != tag[i]) || !fix.saved_id[i]) changed = 1;
  MPI_Allreduce(&changed, &any, 1, MPI_INT, MPI_MAX, world);
  if (!any) return;

  // old ID -> new ID: of my atoms and ghosts, then of the others' atoms for the rest
  fix.forward_saved_ids();
  const int nall = nlocal + atom->nghost;
  std::unordered_map<tagint, tagint> renamed(2 * nall);
  for (int i = 0; i < nall; i++)
    if (fix.saved_id[i]) renamed.emplace(fix.saved_id[i], tag[i]);
  std::vector<tagint> unknown;
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < fix.npartner[i]; m++)
      if (!renamed.count(fix.partner[i][m])) unknown.push_back(fix.partner[i][m]);
  std::sort(unknown.begin(), unknown.end());
  unknown.erase(std::unique(unknown.begin(), unknown.end()), unknown.end());
  const std::vector<tagint> asked = allgatherv(unknown, MPI_LMP_TAGINT, world);
  const int ntotal = asked.size();
  std::vector<tagint> mine(ntotal, 0), answer(ntotal);
  std::unordered_map<tagint, tagint> owned(2 * nlocal);
  for (int i = 0; i < nlocal; i++)
    if (fix.saved_id[i]) owned.emplace(fix.saved_id[i], tag[i]);
  for (int k = 0; k < ntotal; k++) {
    const auto it = owned.find(asked[k]);
    if (it != owned.end()) mine[k] = it->second;
  }
  MPI_Allreduce(mine.data(), answer.data(), ntotal, MPI_LMP_TAGINT, MPI_MAX, world);
  for (int k = 0; k < ntotal; k++) renamed.emplace(asked[k], answer[k]);    // 0: deleted
  for (int i = 0; i < nlocal; i++) {
    for (int m = 0; m < fix.npartner[i]; m++) fix.partner[i][m] = renamed[fix.partner[i][m]];
    if (fix.saved_id[i]) fix.saved_id[i] = tag[i];
  }
}

void PairStateAudit::check_lost_links()
{
  const int nlocal = atom->nlocal;
  const NeighList *list = fix.pair->list;
  // the saved pairs (one entry each) my atoms hold, the pairs in my list, the entries saved
  double mine[3] = {0.0, 0.0, (double) fix.saved_entries}, all[3];
  for (int i = 0; i < nlocal; i++) mine[0] += fix.npartner[i];
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < fix.nstate[i]; jj++)
      if (fix.firstflag[i][jj])
        mine[1] += fix.newton_pair || (list->firstneigh[i][jj] & NEIGHMASK) < nlocal ? 1.0 : 0.5;
  }
  MPI_Allreduce(mine, all, 3, MPI_DOUBLE, MPI_SUM, world);
  // pairs whose keeping atom was deleted since the save took their entries with it
  const double kept_by_deleted = std::max(0.0, all[2] - all[0]);
  if (all[0] <= all[1] + 0.25 && kept_by_deleted < 0.25) return;

  // partner entries whose atom no longer exists (0: deleted while IDs were renumbered)
  const tagint *tag = atom->tag;
  std::unordered_set<tagint> here(tag, tag + nlocal + atom->nghost), owned(tag, tag + nlocal);
  std::vector<tagint> away;
  double gone = 0.0;
  for (int i = 0; i < nlocal; i++)
    for (int m = 0; m < fix.npartner[i]; m++) {
      if (fix.partner[i][m] == 0) gone += 1.0;
      else if (!here.count(fix.partner[i][m])) away.push_back(fix.partner[i][m]);
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

  const double lost = all[0] - all[1] - gone_all;
  gone_all += kept_by_deleted;
  const char *who = fix.owner ? fix.owner->who() : "Pair state";
  if (lost > 0.25 && update->setupflag)
    error->all(FLERR, "{}: {:.0f} links left the neighbour list unbroken (fix {}): their atoms "
               "are farther apart than the list's cutoff before this run: atoms were moved since "
               "the last run (displace_atoms, set, change_box, read_dump ...) or linked pairs "
               "excluded (neigh_modify exclude); move them less, keep linked pairs in the list, "
               "or restart the links (pair_style anew)", who, lost, fix.id);
  if (lost > 0.25) {
    const std::string why = fix.owner ? fix.owner->lost_links_explained() : std::string();
    error->all(FLERR, "{}: {:.0f} links left the neighbour list unbroken (fix {}): {}their atoms "
               "are farther apart than the list's cutoff; raise the neighbor skin or comm_modify "
               "cutoff{}, and do not exclude linked pairs (neigh_modify exclude)", who, lost,
               fix.id, why.empty() ? "" : why + "; else ",
               update->whichflag == 2 ? " or reduce min_modify dmax (a line search's trial "
               "point moved them)" : "");
  }
  if (gone_all > 0.0 && comm->me == 0)
    utils::logmesg(lmp, "{}: {:.0f} links ended with their deleted atoms\n", who, gone_all);
}

bigint PairStateAudit::count_saved_links()
{
  bigint mine = 0, all;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < fix.npartner[i]; m++)
      mine += PairStateLayout::word(fix.valuepartner[i] + fix.dnum * m, fix.dnum) & 1;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return all;
}
