/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute links/atom.

   Per atom, the number of intact links under a pair style with link L: the
   pair states of the pair style's half neighbor list (PairState::view()),
   counted for both atoms of a link (a reverse communication adds the
   ghosts' counts to their owners with newton on), as compute coord/atom
   counts neighbours.
------------------------------------------------------------------------- */

#include "compute_links_atom.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "pair.h"
#include "pair_state.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace ClusterDyn;

ComputeLinksAtom::ComputeLinksAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), state(nullptr), nmax(0), count(nullptr)
{
  if (narg != 3) error->all(FLERR, "Compute links/atom takes no arguments (got {})", narg - 3);
  peratom_flag = 1;
  size_peratom_cols = 0;
  comm_reverse = 1;
}

ComputeLinksAtom::~ComputeLinksAtom()
{
  memory->destroy(count);
}

void ComputeLinksAtom::init()
{
  int dim;
  state = force->pair ? (PairState *) force->pair->extract("pair_state", dim) : nullptr;
  if (!state) error->all(FLERR, "Compute links/atom needs a pair style with link L");
}

void ComputeLinksAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (atom->nmax > nmax) {
    memory->destroy(count);
    nmax = atom->nmax;
    memory->create(count, nmax, "links/atom:count");
    vector_atom = count;
  }
  for (int i = 0; i < nall; i++) count[i] = 0.0;

  const int newton_pair = force->newton_pair;
  if (state->made()) {    // before the first run's setup no pair is linked
    const StateView links = state->view();
    const NeighList *list = links.list;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      for (int jj = 0; jj < links.counts[i]; jj++) {
        if (!state_now(links.words[i][jj])) continue;
        const int j = list->firstneigh[i][jj] & NEIGHMASK;
        count[i] += 1.0;
        if (newton_pair || j < nlocal) count[j] += 1.0;
      }
    }
  }
  if (newton_pair) comm->reverse_comm(this);
  const int *mask = atom->mask;
  for (int i = 0; i < nlocal; i++)
    if (!(mask[i] & groupbit)) count[i] = 0.0;
}

int ComputeLinksAtom::pack_reverse_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) buf[k] = count[first + k];
  return n;
}

void ComputeLinksAtom::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) count[list[k]] += buf[k];
}

double ComputeLinksAtom::memory_usage()
{
  return (double) nmax * sizeof(double);
}
