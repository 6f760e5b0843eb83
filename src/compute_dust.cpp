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
     4. one MPI_Alltoallv of my fragments' sums (size, mass, mass-weighted
        unwrapped position and velocity) to their owners (ID modulo the
        number of processors), the body from two MPI_Allreduce, one
        MPI_Alltoallv of each fragment's size and dust flag back
   The fragment ID is the smallest atom ID in the fragment, as compute
   cluster/atom gives it.  Each fragment's local row (ID, size, mass, centre
   of mass, its velocity, dust flag) is on its owner.  Cost: O(N) per
   processor plus the boundary.
------------------------------------------------------------------------- */

#include "compute_dust.h"

#include "mpi_collectives.h"
#include "arg_values.h"
#include "keyword_set.h"
#include "skin_check.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"
#include "pair_state.h"
#include "update.h"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

enum { FRAGMENT_ID = 0, FRAGMENT_SIZE = 1, DUST_FLAG = 2 };         // per-atom columns
enum { SIZE = 0, MASS = 1, MX = 2, MV = 5 };                         // ComputeDust::Sums
static constexpr int RECORD = 1 + ComputeDust::NSUMS;                // fragment ID, sums
static constexpr int NCOLS = 10;                                     // local columns

ComputeDust::ComputeDust(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), cutoff_user(0.0), maxsize(0), links(0), dust_rows(0),
    state(nullptr), list(nullptr), nmax(0), fragments(nullptr), nrows(0), maxrows(0),
    rows(nullptr), evaluated(-1)
{
  KeywordSet given(lmp, "Compute dust");
  for (int iarg = 3; iarg < narg; iarg++) {
    const std::string key = arg[iarg];
    given.add(key);
    if (key == "links") {    // a flag: the bonds are the pair style's links
      links = 1;
      continue;
    }
    if (key != "cutoff" && key != "maxsize" && key != "rows")
      error->all(FLERR, "Compute dust: unknown keyword '{}' (expected cutoff, maxsize, links "
                 "or rows)", key);
    if (++iarg >= narg) error->all(FLERR, "Compute dust: keyword {} needs a value", key);
    const std::string value = arg[iarg];
    if (key == "cutoff") {
      cutoff_user = positive_arg("Compute dust", "cutoff", value.c_str(), lmp);
    } else if (key == "maxsize") {
      const double m = integer_arg("Compute dust", "maxsize", value.c_str(), lmp);
      if (m < 1) error->all(FLERR, "Compute dust: maxsize must be >= 1 (got {})", value);
      maxsize = (bigint) m;
    } else {
      if (value != "all" && value != "dust")
        error->all(FLERR, "Compute dust: rows must be all or dust (got {})", value);
      dust_rows = value == "dust";
    }
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
  local_flag = 1;
  size_local_cols = NCOLS;
  comm_forward = 1;
}

ComputeDust::~ComputeDust()
{
  delete[] vector;
  memory->destroy(fragments);
  memory->destroy(rows);
}

void ComputeDust::init()
{
  if (!atom->tag_enable) error->all(FLERR, "Compute dust requires atom IDs");
  evaluated = -1;    // the atoms may have changed since (displace_atoms, delete_atoms, ...)
  if (links) {
    int dim;
    state = force->pair ? (PairState *) force->pair->extract("pair_state", dim) : nullptr;
    if (!state)
      error->all(FLERR, "Compute dust links needs a pair style with link L (and a run or "
                 "minimization that made the links: run 0 will do)");
    return;
  }
  if (cutoff_user == 0.0 && (!force->pair || !force->pair->cutsq))
    error->all(FLERR, "Compute dust: without the cutoff keyword it needs a pair style, whose "
               "cutoffs are the bond distances");
  if (cutoff_user == 0.0 && utils::strmatch(force->pair_style, "^hybrid") &&
      !modify->get_fix_by_style("^adapt").empty() && comm->me == 0)
    error->warning(FLERR, "Compute dust: under pair_style {} the bond distances are the "
                   "hybrid's cutoffs as the run starts; fix adapt changing a sub-style's cutoffs "
                   "does not move them (give the cutoff keyword)", force->pair_style);

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

// per type pair, squared: the cutoff keyword's, or the pair style's cutoffs as they are now
// (fix adapt may move them during a run: read again at each evaluation)
void ComputeDust::bond_distances()
{
  const int ntp1 = atom->ntypes + 1;
  cutsq.assign(ntp1 * ntp1, cutoff_user * cutoff_user);
  if (cutoff_user == 0.0)
    for (int i = 1; i < ntp1; i++)
      for (int j = 1; j < ntp1; j++) cutsq[i * ntp1 + j] = force->pair->cutsq[i][j];
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

void ComputeDust::compute_local()
{
  invoked_local = update->ntimestep;
  if (evaluated != update->ntimestep) evaluate();
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
    bond_distances();
  }

  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  const int *mask = atom->mask, *type = atom->type;
  const double *const *x = atom->x;
  const int ntp1 = atom->ntypes + 1;

  // 1. union-find over my atoms and ghosts; images of one atom are one node

  sets.reset(nall);
  if (atom->map_style != Atom::MAP_NONE) {
    for (int i = nlocal; i < nall; i++) {
      const int canonical = atom->map(tag[i]);
      if (canonical >= 0 && canonical != i) sets.join(i, canonical);
    }
  } else {    // no atom map: one of our own, my atoms first (as atom->map prefers them)
    std::unordered_map<tagint, int> first(2 * nall);
    for (int i = 0; i < nall; i++) {
      const auto seen = first.emplace(tag[i], i);
      if (!seen.second) sets.join(i, seen.first->second);
    }
  }
  // bonds: pairs closer than the bond distance, or (links) the pair style's intact links
  if (links && !state->made())
    error->all(FLERR, "Compute dust links: the links are not made yet (they are at the setup of "
               "the first run or minimization: run 0 will do)");
  const StateView view = links ? state->view() : StateView{list, nullptr, nullptr, 0, 1};
  const NeighList *bonds = view.list;
  for (int ii = 0; ii < bonds->inum; ii++) {
    const int i = bonds->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    for (int jj = 0; jj < bonds->numneigh[i]; jj++) {
      const int j = bonds->firstneigh[i][jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      if (links) {
        if (!state_now(view.words[i][jj])) continue;
      } else {
        const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
        if (dx * dx + dy * dy + dz * dz >= cutsq[type[i] * ntp1 + type[j]]) continue;
      }
      sets.join(i, j);
    }
  }

  // smallest atom ID of each local set (sets of my atoms and ghosts)
  std::vector<tagint> setmin(nall, MAXTAGINT);
  for (int i = 0; i < nall; i++)
    if (mask[i] & groupbit) {
      const int r = sets.find(i);
      setmin[r] = std::min(setmin[r], tag[i]);
    }
  label.resize(nall);
  for (int i = 0; i < nall; i++)
    label[i] = (mask[i] & groupbit) ? (double) setmin[sets.find(i)] : 0.0;

  // 2. ghosts learn the label of their atom on its owner

  comm->forward_comm(this);    // changes only the ghosts' labels

  // 3. pairs (my label of a ghost, its owner's label) -> global union-find on labels

  std::vector<tagint> pairs;
  {
    std::set<std::pair<tagint, tagint>> seen;    // few distinct pairs: per fragment and neighbour
    for (int i = nlocal; i < nall; i++) {
      if (!(mask[i] & groupbit)) continue;
      const tagint a = setmin[sets.find(i)], b = (tagint) label[i];
      if (a != b && seen.emplace(std::min(a, b), std::max(a, b)).second) {  // new pair
        pairs.push_back(std::min(a, b));
        pairs.push_back(std::max(a, b));
      }
    }
  }
  const std::vector<tagint> allpairs = allgatherv(pairs, MPI_LMP_TAGINT, world);
  LabelUnion fragment;    // label -> the fragment's ID (its smallest label)
  for (size_t k = 0; k < allpairs.size(); k += 2) fragment.join(allpairs[k], allpairs[k + 1]);

  // 4. per-fragment sums, each combined on the fragment's owner (ID modulo nprocs):
  //    one MPI_Alltoallv there, one back with the size and dust flag

  std::unordered_map<tagint, Sums> mine;    // fragment ID -> sums over my atoms
  for (int i = 0; i < nlocal; i++) {
    fragments[i][FRAGMENT_ID] = fragments[i][FRAGMENT_SIZE] = fragments[i][DUST_FLAG] = 0.0;
    if (!(mask[i] & groupbit)) continue;
    const tagint id = fragment.root((tagint) label[i]);
    fragments[i][FRAGMENT_ID] = id;
    const double m = atom->rmass ? atom->rmass[i] : atom->mass[type[i]];
    double xu[3];
    domain->unmap(x[i], atom->image[i], xu);
    Sums &sums = mine[id];
    sums[SIZE] += 1.0;
    sums[MASS] += m;
    for (int d = 0; d < 3; d++) {
      sums[MX + d] += m * xu[d];
      sums[MV + d] += m * atom->v[i][d];
    }
  }
  const int nprocs = comm->nprocs;
  std::vector<std::vector<double>> outbox(nprocs);    // (ID, sums) per owner
  for (const auto &kv : mine) {
    auto &box = outbox[kv.first % nprocs];
    box.push_back((double) kv.first);
    box.insert(box.end(), kv.second.begin(), kv.second.end());
  }
  std::vector<int> incounts;
  const std::vector<double> inbox = alltoallv(outbox, incounts, world);

  std::map<tagint, Sums> owned;    // the fragments I own, by ID
  for (size_t k = 0; k < inbox.size(); k += RECORD) {
    Sums &sums = owned[(tagint) inbox[k]];
    for (int c = 0; c < NSUMS; c++) sums[c] += inbox[k + 1 + c];
  }

  // the body: the largest fragment, the smallest ID among equals
  double mybody[2] = {0.0, 0.0};    // (size, -ID) of my largest, then everybody's
  for (const auto &kv : owned)
    if (kv.second[SIZE] > mybody[0]) {
      mybody[0] = kv.second[SIZE];
      mybody[1] = -(double) kv.first;
    }
  double body[2];
  MPI_Allreduce(&mybody[0], &body[0], 1, MPI_DOUBLE, MPI_MAX, world);
  if (mybody[0] < body[0]) mybody[1] = -(double) MAXTAGINT;
  MPI_Allreduce(&mybody[1], &body[1], 1, MPI_DOUBLE, MPI_MAX, world);
  const tagint bodyid = (tagint) -body[1];
  auto is_dust = [&](tagint id, double size) {
    return maxsize > 0 ? size <= (double) maxsize : id != bodyid;
  };

  double totals[5] = {0.0, 0.0, 0.0, 0.0, 0.0};    // dust atoms, fragments, mass; mass; fragments
  nrows = 0;
  for (const auto &kv : owned) {
    const bool dust = is_dust(kv.first, kv.second[SIZE]);
    if (dust) {
      totals[0] += kv.second[SIZE];
      totals[1] += 1.0;
      totals[2] += kv.second[MASS];
    }
    totals[3] += kv.second[MASS];
    totals[4] += 1.0;
    if (dust || !dust_rows) nrows++;
  }
  double sums[5];
  MPI_Allreduce(totals, sums, 5, MPI_DOUBLE, MPI_SUM, world);

  // local rows: one per fragment I own (dust only with rows dust), sorted by ID
  if (nrows > maxrows) {
    memory->destroy(rows);
    maxrows = nrows;
    memory->create(rows, maxrows, NCOLS, "dust:rows");
  }
  array_local = rows;
  size_local_rows = nrows;
  int r = 0;
  for (const auto &kv : owned) {
    const Sums &s = kv.second;
    const bool dust = is_dust(kv.first, s[SIZE]);
    if (dust_rows && !dust) continue;
    double *row = rows[r++];
    row[0] = kv.first;
    row[1] = s[SIZE];
    row[2] = s[MASS];
    for (int d = 0; d < 3; d++) {
      row[3 + d] = s[MX + d] / s[MASS];
      row[6 + d] = s[MV + d] / s[MASS];
    }
    row[9] = dust ? 1.0 : 0.0;
  }

  // back to the atoms: (size, dust flag) for each ID each processor sent, in its order
  std::vector<std::vector<double>> replies(nprocs);
  for (int p = 0, k = 0; p < nprocs; p++)
    for (int n = 0; n < incounts[p] / RECORD; n++, k += RECORD) {
      const tagint id = (tagint) inbox[k];
      const double size = owned[id][SIZE];
      replies[p].push_back(size);
      replies[p].push_back(is_dust(id, size) ? 1.0 : 0.0);
    }
  std::vector<int> replycounts;
  const std::vector<double> answers = alltoallv(replies, replycounts, world);
  std::unordered_map<tagint, std::pair<double, double>> mysizes;    // answers come grouped
  for (int p = 0, a = 0; p < nprocs; p++)                            // by owner, in my order
    for (size_t k = 0; k < outbox[p].size(); k += RECORD, a += 2)
      mysizes[(tagint) outbox[p][k]] = {answers[a], answers[a + 1]};
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const auto &answer = mysizes[(tagint) fragments[i][FRAGMENT_ID]];
    fragments[i][FRAGMENT_SIZE] = answer.first;
    fragments[i][DUST_FLAG] = answer.second;
  }

  vector[0] = sums[0];
  vector[1] = sums[1];
  vector[2] = sums[2];
  vector[3] = sums[3] > 0.0 ? sums[2] / sums[3] : 0.0;
  vector[4] = body[0];
  vector[5] = sums[4];
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
  return (double) nmax * 3 * sizeof(double) + (double) maxrows * NCOLS * sizeof(double) +
      sets.memory_usage() + label.capacity() * sizeof(double);
}
