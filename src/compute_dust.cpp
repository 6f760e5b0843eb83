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
#include <set>
#include <unordered_map>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

enum { FRAGMENT_ID = 0, FRAGMENT_SIZE = 1, DUST_FLAG = 2 };    // per-atom columns
static constexpr int NCOLS = 10;                                // local columns

ComputeDust::ComputeDust(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), opt(DustSettings::parse(lmp, narg, arg)), state(nullptr),
    list(nullptr), nmax(0), fragments(nullptr), nrows(0), maxrows(0), rows(nullptr), evaluated(-1)
{
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
  if (opt.links) {
    int dim;
    state = force->pair ? (PairState *) force->pair->extract("pair_state", dim) : nullptr;
    if (!state)
      error->all(FLERR, "Compute dust links needs a pair style with link L (and a run or "
                 "minimization that made the links: run 0 will do)");
    return;
  }
  if (opt.cutoff == 0.0 && (!force->pair || !force->pair->cutsq))
    error->all(FLERR, "Compute dust: without the cutoff keyword it needs a pair style, whose "
               "cutoffs are the bond distances");
  if (opt.cutoff == 0.0 && utils::strmatch(force->pair_style, "^hybrid") &&
      !modify->get_fix_by_style("^adapt").empty() && comm->me == 0)
    error->warning(FLERR, "Compute dust: under pair_style {} the bond distances are the "
                   "hybrid's cutoffs as the run starts; fix adapt changing a sub-style's cutoffs "
                   "does not move them (give the cutoff keyword)", force->pair_style);

  const double skin = neighbor->skin;
  const double cutghost = force->pair ? MAX(force->pair->cutforce + skin, comm->cutghostuser)
                                      : comm->cutghostuser;
  if (opt.cutoff > cutghost)
    error->all(FLERR, "Compute dust: cutoff {} exceeds the ghost atom range {}: raise it with "
               "comm_modify cutoff", opt.cutoff, cutghost);
  if (opt.cutoff > 0.0)
    check_neighbor_skin(lmp, force->pair ? MAX(opt.cutoff, force->pair->cutforce) : opt.cutoff,
                        "Compute dust");

  auto req = neighbor->add_request(this, NeighConst::REQ_OCCASIONAL);
  if (opt.cutoff > 0.0 && (!force->pair || opt.cutoff > force->pair->cutforce))
    req->set_cutoff(opt.cutoff);
}

// per type pair, squared: the cutoff keyword's, or the pair style's cutoffs as they are now
// (fix adapt may move them during a run: read again at each evaluation)
void ComputeDust::bond_distances()
{
  const int ntp1 = atom->ntypes + 1;
  cutsq.assign(ntp1 * ntp1, opt.cutoff * opt.cutoff);
  if (opt.cutoff == 0.0)
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
  if (!opt.links) {
    comm->forward_comm();    // current ghost positions
    neighbor->build_one(list);
    bond_distances();
  }

  join_bonded_atoms();    // 1.
  const std::vector<tagint> setmin = label_local_sets();
  comm->forward_comm(this);    // 2. the ghosts learn their owner's label
  const LabelUnion fragment = join_across_processors(setmin);    // 3.
  FragmentSums sums(world, opt.maxsize);                         // 4.
  sum_fragments(fragment, sums);
  sums.combine();
  write_vector(sums);
  write_rows(sums);
  write_atoms(sums);
}

/* ----------------------------------------------------------------------
   1. union-find over my atoms and ghosts; the images of one atom are one
   node; bonds: pairs closer than the bond distance, or (links) the pair
   style's intact links
------------------------------------------------------------------------- */

void ComputeDust::join_bonded_atoms()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  const int *mask = atom->mask, *type = atom->type;
  const double *const *x = atom->x;
  const int ntp1 = atom->ntypes + 1;

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
  if (opt.links && !state->made())
    error->all(FLERR, "Compute dust links: the links are not made yet (they are at the setup of "
               "the first run or minimization: run 0 will do)");
  const StateView view = opt.links ? state->view() : StateView{list, nullptr, nullptr};
  const NeighList *bonds = view.list;
  for (int ii = 0; ii < bonds->inum; ii++) {
    const int i = bonds->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const int jnum = opt.links ? view.counts[i] : bonds->numneigh[i];    // links: the first
    for (int jj = 0; jj < jnum; jj++) {
      const int j = bonds->firstneigh[i][jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      if (opt.links) {
        if (!state_now(view.words[i][jj])) continue;
      } else {
        const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
        if (dx * dx + dy * dy + dz * dz >= cutsq[type[i] * ntp1 + type[j]]) continue;
      }
      sets.join(i, j);
    }
  }
}

// the smallest atom ID of each local set (returned by set root), the label of its atoms
std::vector<tagint> ComputeDust::label_local_sets()
{
  const int nall = atom->nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  const int *mask = atom->mask;
  std::vector<tagint> setmin(nall, MAXTAGINT);
  for (int i = 0; i < nall; i++)
    if (mask[i] & groupbit) {
      const int r = sets.find(i);
      setmin[r] = std::min(setmin[r], tag[i]);
    }
  label.resize(nall);
  for (int i = 0; i < nall; i++)
    label[i] = (mask[i] & groupbit) ? (double) setmin[sets.find(i)] : 0.0;
  return setmin;
}

// 3. the pairs (my label of a ghost, its owner's label) from every processor: a global
// union-find on labels, each leading to its fragment's ID (the smallest label)
LabelUnion ComputeDust::join_across_processors(const std::vector<tagint> &setmin)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *mask = atom->mask;
  std::vector<tagint> pairs;
  std::set<std::pair<tagint, tagint>> seen;    // few distinct pairs: per fragment and neighbour
  for (int i = nlocal; i < nall; i++) {
    if (!(mask[i] & groupbit)) continue;
    const tagint a = setmin[sets.find(i)], b = (tagint) label[i];
    if (a != b && seen.emplace(std::min(a, b), std::max(a, b)).second) {    // new pair
      pairs.push_back(std::min(a, b));
      pairs.push_back(std::max(a, b));
    }
  }
  const std::vector<tagint> allpairs = allgatherv(pairs, MPI_LMP_TAGINT, world);
  LabelUnion fragment;
  for (size_t k = 0; k < allpairs.size(); k += 2) fragment.join(allpairs[k], allpairs[k + 1]);
  return fragment;
}

// 4. my atoms' fragment IDs and their sums
void ComputeDust::sum_fragments(const LabelUnion &fragment, FragmentSums &sums)
{
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    fragments[i][FRAGMENT_ID] = fragments[i][FRAGMENT_SIZE] = fragments[i][DUST_FLAG] = 0.0;
    if (!(mask[i] & groupbit)) continue;
    const tagint id = fragment.root((tagint) label[i]);
    fragments[i][FRAGMENT_ID] = id;
    const double m = atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]];
    double xu[3];
    domain->unmap(atom->x[i], atom->image[i], xu);
    sums.add(id, m, xu, atom->v[i]);
  }
}

// the global vector: dust atoms, fragments and mass, its fraction, the body, fragments
void ComputeDust::write_vector(const FragmentSums &sums)
{
  double mine[5] = {0.0, 0.0, 0.0, 0.0, 0.0};    // dust atoms, fragments, mass; mass; fragments
  for (const auto &kv : sums.owned()) {
    const double size = kv.second[FragmentSums::SIZE], mass = kv.second[FragmentSums::MASS];
    if (sums.is_dust(kv.first, size)) {
      mine[0] += size;
      mine[1] += 1.0;
      mine[2] += mass;
    }
    mine[3] += mass;
    mine[4] += 1.0;
  }
  double all[5];
  MPI_Allreduce(mine, all, 5, MPI_DOUBLE, MPI_SUM, world);
  vector[0] = all[0];
  vector[1] = all[1];
  vector[2] = all[2];
  vector[3] = all[3] > 0.0 ? all[2] / all[3] : 0.0;
  vector[4] = sums.body_size();
  vector[5] = all[4];
}

// local rows: one per fragment I own (dust only with rows dust), sorted by ID
void ComputeDust::write_rows(const FragmentSums &sums)
{
  using F = FragmentSums;
  nrows = 0;
  for (const auto &kv : sums.owned())
    if (!opt.dust_rows || sums.is_dust(kv.first, kv.second[F::SIZE])) nrows++;
  if (nrows > maxrows) {
    memory->destroy(rows);
    maxrows = nrows;
    memory->create(rows, maxrows, NCOLS, "dust:rows");
  }
  array_local = rows;
  size_local_rows = nrows;
  int r = 0;
  for (const auto &kv : sums.owned()) {
    const F::Sums &s = kv.second;
    const bool dust = sums.is_dust(kv.first, s[F::SIZE]);
    if (opt.dust_rows && !dust) continue;
    double *row = rows[r++];
    row[0] = kv.first;
    row[1] = s[F::SIZE];
    row[2] = s[F::MASS];
    for (int d = 0; d < 3; d++) {
      row[3 + d] = s[F::MX + d] / s[F::MASS];
      row[6 + d] = s[F::MV + d] / s[F::MASS];
    }
    row[9] = dust ? 1.0 : 0.0;
  }
}

// back to the atoms: their fragment's size and dust flag
void ComputeDust::write_atoms(const FragmentSums &sums)
{
  const std::unordered_map<tagint, FragmentSums::Answer> answers = sums.answers();
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const FragmentSums::Answer &answer = answers.at((tagint) fragments[i][FRAGMENT_ID]);
    fragments[i][FRAGMENT_SIZE] = answer.size;
    fragments[i][DUST_FLAG] = answer.dust;
  }
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
