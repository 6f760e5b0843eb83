/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute dust.

   Fragments are the connected components of the bond graph (pairs of group
   atoms closer than the bond distance), through periodic images and across
   processors; the largest is the body, the others (or those of at most
   maxsize atoms) are dust.  One evaluation, in a fixed number of
   communication rounds whatever the decomposition:
     1. union-find over my atoms and ghosts (the images of one atom are
        joined through atom->map, or a hash of the IDs when there is no
        map), local label = smallest atom ID in the set
     2. one forward communication of the labels of my atoms to their ghosts
     3. one MPI_Allgatherv of the label pairs (mine, owner's) that ghosts
        owned by other processors create; a global union-find over them
     4. one MPI_Allgatherv of the (label, size, mass) of my fragments
   The fragment ID is the smallest atom ID in the fragment, as compute
   cluster/atom gives it.  Cost: O(N) per processor plus the boundary.
------------------------------------------------------------------------- */

#include "compute_dust.h"

#include "skin_check.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <unordered_map>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

enum { FRAGMENT_ID = 0, FRAGMENT_SIZE = 1, DUST_FLAG = 2 };

// every processor's entries, concatenated in rank order, on every processor
template <class T>
static std::vector<T> allgatherv(const std::vector<T> &mine, MPI_Datatype type, MPI_Comm world)
{
  int nprocs, n = mine.size();
  MPI_Comm_size(world, &nprocs);
  std::vector<int> counts(nprocs), displs(nprocs);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int total = 0;
  for (int p = 0; p < nprocs; p++) {
    displs[p] = total;
    total += counts[p];
  }
  std::vector<T> all(total);
  MPI_Allgatherv(mine.data(), n, type, all.data(), counts.data(), displs.data(), type, world);
  return all;
}

ComputeDust::ComputeDust(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), cutoff_user(0.0), maxsize(0), links(0), link_history(nullptr),
    list(nullptr), nmax(0), fragments(nullptr), evaluated(-1)
{
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (key == "links") {    // a flag: the bonds are the pair style's links
      links = 1;
      iarg--;
      continue;
    }
    if (iarg + 1 >= narg) error->all(FLERR, "Compute dust: keyword {} needs a value", key);
    if (key == "cutoff") {
      cutoff_user = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(cutoff_user > 0.0))
        error->all(FLERR, "Compute dust: cutoff must be > 0 (got {})", arg[iarg + 1]);
    } else if (key == "maxsize") {
      maxsize = utils::bnumeric(FLERR, arg[iarg + 1], false, lmp);
      if (maxsize < 1) error->all(FLERR, "Compute dust: maxsize must be >= 1 (got {})", arg[iarg + 1]);
    } else
      error->all(FLERR, "Compute dust: unknown keyword '{}' (expected cutoff, maxsize or links)",
                 key);
  }
  if (links && cutoff_user > 0.0)
    error->all(FLERR, "Compute dust: keywords links and cutoff exclude each other (the links are "
               "the bonds)");

  vector_flag = 1;
  size_vector = 6;
  extvector = 0;
  vector = new double[size_vector];
  peratom_flag = 1;
  size_peratom_cols = 3;
  comm_forward = 1;
}

ComputeDust::~ComputeDust()
{
  delete[] vector;
  memory->destroy(fragments);
}

void ComputeDust::init()
{
  if (!atom->tag_enable) error->all(FLERR, "Compute dust requires atom IDs");
  if (links) {
    int dim;
    link_history = force->pair ? (FixNeighHistory *) force->pair->extract("link_history", dim)
                               : nullptr;
    if (!link_history)
      error->all(FLERR, "Compute dust links needs a pair style with link L (and a run or "
                 "minimization that made the links: run 0 will do)");
    return;
  }
  if (cutoff_user == 0.0 && (!force->pair || !force->pair->cutsq))
    error->all(FLERR, "Compute dust: without the cutoff keyword it needs a pair style, whose "
               "cutoffs are the bond distances");
  const int ntp1 = atom->ntypes + 1;
  cutsq.assign(ntp1 * ntp1, cutoff_user * cutoff_user);
  if (cutoff_user == 0.0)
    for (int i = 1; i < ntp1; i++)
      for (int j = 1; j < ntp1; j++) cutsq[i * ntp1 + j] = force->pair->cutsq[i][j];

  const double skin = neighbor->skin;
  const double cutghost = force->pair ? MAX(force->pair->cutforce + skin, comm->cutghostuser)
                                      : comm->cutghostuser;
  if (cutoff_user > cutghost)
    error->all(FLERR, "Compute dust: cutoff {} exceeds the ghost atom range {}: raise it with "
               "comm_modify cutoff", cutoff_user, cutghost);
  if (cutoff_user > 0.0)
    check_neighbor_skin(lmp, force->pair ? MAX(cutoff_user, force->pair->cutforce) : cutoff_user,
                        "Compute dust");

  auto req = neighbor->add_request(this, NeighConst::REQ_OCCASIONAL);
  if (cutoff_user > 0.0 && (!force->pair || cutoff_user > force->pair->cutforce))
    req->set_cutoff(cutoff_user);
}

void ComputeDust::init_list(int, NeighList *ptr)
{
  list = ptr;
}

void ComputeDust::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (evaluated != update->ntimestep) evaluate();
}

void ComputeDust::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (evaluated != update->ntimestep) evaluate();
}

int ComputeDust::find(int i)
{
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

/* ---------------------------------------------------------------------- */

void ComputeDust::evaluate()
{
  evaluated = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(fragments);
    nmax = atom->nmax;
    memory->create(fragments, nmax, 3, "dust:fragments");
    array_atom = fragments;
  }

  if (!links) {
    comm->forward_comm();    // current ghost positions
    neighbor->build_one(list);
  }

  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  const int *mask = atom->mask, *type = atom->type;
  const double *const *x = atom->x;
  const int ntp1 = atom->ntypes + 1;

  // 1. union-find over my atoms and ghosts; images of one atom are one node

  parent.resize(nall);
  for (int i = 0; i < nall; i++) parent[i] = i;
  if (atom->map_style != Atom::MAP_NONE) {
    for (int i = nlocal; i < nall; i++) {
      const int canonical = atom->map(tag[i]);
      if (canonical >= 0 && canonical != i) parent[find(i)] = find(canonical);
    }
  } else {    // no atom map: one of our own, my atoms first (as atom->map prefers them)
    std::unordered_map<tagint, int> first(2 * nall);
    for (int i = 0; i < nall; i++) {
      const auto seen = first.emplace(tag[i], i);
      if (!seen.second) parent[find(i)] = find(seen.first->second);
    }
  }
  // bonds: pairs closer than the bond distance, or (links) the pair style's intact links,
  // the flags fix neigh/history keeps for the pair style's neighbor list
  const NeighList *bonds = links ? link_history->pair->list : list;
  int *const *const linked = links ? link_history->firstflag : nullptr;
  if (links && !linked)
    error->all(FLERR, "Compute dust links: the links are not made yet (they are at the setup of "
               "the first run or minimization: run 0 will do)");
  for (int ii = 0; ii < bonds->inum; ii++) {
    const int i = bonds->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    for (int jj = 0; jj < bonds->numneigh[i]; jj++) {
      const int j = bonds->firstneigh[i][jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      if (links) {
        if (!linked[i][jj]) continue;
      } else {
        const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
        if (dx * dx + dy * dy + dz * dz >= cutsq[type[i] * ntp1 + type[j]]) continue;
      }
      const int ri = find(i), rj = find(j);
      if (ri != rj) parent[std::max(ri, rj)] = std::min(ri, rj);
    }
  }

  // smallest atom ID of each local set (sets of my atoms and ghosts)
  std::vector<tagint> setmin(nall, MAXTAGINT);
  for (int i = 0; i < nall; i++)
    if (mask[i] & groupbit) {
      const int r = find(i);
      setmin[r] = std::min(setmin[r], tag[i]);
    }
  label.resize(nall);
  for (int i = 0; i < nall; i++) label[i] = (mask[i] & groupbit) ? (double) setmin[find(i)] : 0.0;

  // 2. ghosts learn the label of their atom on its owner

  comm->forward_comm(this);    // changes only the ghosts' labels

  // 3. pairs (my label of a ghost, its owner's label) -> global union-find on labels

  std::vector<tagint> pairs;
  {
    std::set<std::pair<tagint, tagint>> seen;    // few distinct pairs: per fragment and neighbour
    for (int i = nlocal; i < nall; i++) {
      if (!(mask[i] & groupbit)) continue;
      const tagint a = setmin[find(i)], b = (tagint) label[i];
      if (a != b && seen.emplace(std::min(a, b), std::max(a, b)).second) {  // new pair
        pairs.push_back(std::min(a, b));
        pairs.push_back(std::max(a, b));
      }
    }
  }
  const std::vector<tagint> allpairs = allgatherv(pairs, MPI_LMP_TAGINT, world);
  std::unordered_map<tagint, tagint> up;    // label -> smaller label of the same fragment
  auto root = [&](tagint t) {
    for (auto it = up.find(t); it != up.end(); it = up.find(t)) t = it->second;
    return t;
  };
  for (size_t k = 0; k < allpairs.size(); k += 2) {
    const tagint ra = root(allpairs[k]), rb = root(allpairs[k + 1]);
    if (ra != rb) up[std::max(ra, rb)] = std::min(ra, rb);
  }

  // 4. fragment sizes and masses

  std::map<tagint, std::pair<double, double>> local;    // fragment ID -> (size, mass)
  for (int i = 0; i < nlocal; i++) {
    fragments[i][FRAGMENT_ID] = fragments[i][FRAGMENT_SIZE] = fragments[i][DUST_FLAG] = 0.0;
    if (!(mask[i] & groupbit)) continue;
    const tagint id = root((tagint) label[i]);
    fragments[i][FRAGMENT_ID] = id;
    auto &entry = local[id];
    entry.first += 1.0;
    entry.second += atom->rmass ? atom->rmass[i] : atom->mass[type[i]];
  }
  std::vector<double> packed;
  for (const auto &kv : local) packed.insert(packed.end(), {(double) kv.first, kv.second.first,
                                                            kv.second.second});
  const std::vector<double> allpacked = allgatherv(packed, MPI_DOUBLE, world);
  std::map<tagint, std::pair<double, double>> global;
  for (size_t k = 0; k < allpacked.size(); k += 3) {
    auto &entry = global[(tagint) allpacked[k]];
    entry.first += allpacked[k + 1];
    entry.second += allpacked[k + 2];
  }

  // the body: the largest fragment (the smallest ID among equals)
  tagint body = 0;
  double bodysize = 0.0, groupmass = 0.0;
  for (const auto &kv : global) {
    groupmass += kv.second.second;
    if (kv.second.first > bodysize) {
      bodysize = kv.second.first;
      body = kv.first;
    }
  }
  auto is_dust = [&](tagint id, double size) {
    return maxsize > 0 ? size <= (double) maxsize : id != body;
  };
  double ndust = 0.0, nfrag_dust = 0.0, dustmass = 0.0;
  for (const auto &kv : global)
    if (is_dust(kv.first, kv.second.first)) {
      ndust += kv.second.first;
      nfrag_dust += 1.0;
      dustmass += kv.second.second;
    }
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const tagint id = (tagint) fragments[i][FRAGMENT_ID];
    const double size = global[id].first;
    fragments[i][FRAGMENT_SIZE] = size;
    fragments[i][DUST_FLAG] = is_dust(id, size) ? 1.0 : 0.0;
  }

  vector[0] = ndust;
  vector[1] = nfrag_dust;
  vector[2] = dustmass;
  vector[3] = groupmass > 0.0 ? dustmass / groupmass : 0.0;
  vector[4] = bodysize;
  vector[5] = global.size();
}

/* ---------------------------------------------------------------------- */

int ComputeDust::pack_forward_comm(int n, int *list_, double *buf, int, int *)
{
  for (int k = 0; k < n; k++) buf[k] = label[list_[k]];
  return n;
}

void ComputeDust::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) label[first + k] = buf[k];
}

double ComputeDust::memory_usage()
{
  return (double) nmax * 3 * sizeof(double) + parent.capacity() * sizeof(int) +
      label.capacity() * sizeof(double);
}
