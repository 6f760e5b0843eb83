/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute mca/atom (see the header).
   The pair style sums the element stresses during its force evaluation
   once this compute has asked for them (at init), so the values are those
   of the last evaluation: the current step's at output.
------------------------------------------------------------------------- */

#include "compute_mca_atom.h"

#include "pair_mca.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

ComputeMcaAtom::ComputeMcaAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), pair(nullptr), values(nullptr), nmax(0)
{
  if (narg != 3) error->all(FLERR, "Compute mca/atom takes no arguments (got {})", narg - 3);
  peratom_flag = 1;
  size_peratom_cols = NCOLUMNS;
}

ComputeMcaAtom::~ComputeMcaAtom()
{
  memory->destroy(values);
}

void ComputeMcaAtom::init()
{
  pair = dynamic_cast<PairMCA *>(force->pair_match("^mca$", 0, 0));
  if (!pair) error->all(FLERR, "Compute mca/atom needs pair_style mca");
  pair->request_element_stress();
}

void ComputeMcaAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(values);
    nmax = atom->nmax;
    memory->create(values, nmax, NCOLUMNS, "mca/atom:values");
    array_atom = values;
  }
  pair = dynamic_cast<PairMCA *>(force->pair_match("^mca$", 0, 0));    // may have changed
  if (!pair) error->all(FLERR, "Compute mca/atom needs pair_style mca");
  double **s = pair->element_stress();
  int stale = !s, any = 0;    // on every processor: the same error everywhere
  MPI_Allreduce(&stale, &any, 1, MPI_INT, MPI_MAX, world);
  if (any)
    error->all(FLERR, "Compute mca/atom: the element stresses are not current (atoms added or "
               "removed, or no force evaluation since this compute was defined): run 0 first");
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    double *v = values[i];
    for (int k = 0; k < NCOLUMNS; k++) v[k] = 0.0;
    if (!(mask[i] & groupbit)) continue;
    for (int k = 0; k < 6; k++) v[k] = s[i][k];
    if (domain->dimension == 2) v[SZZ] = pair->out_of_plane_stress(i, v[SXX], v[SYY]);
    v[MEAN] = (v[SXX] + v[SYY] + v[SZZ]) / 3.0;
    const double dxx = v[SXX] - v[MEAN], dyy = v[SYY] - v[MEAN], dzz = v[SZZ] - v[MEAN];
    v[EQUIVALENT] = sqrt(1.5 * (dxx * dxx + dyy * dyy + dzz * dzz) +
                         3.0 * (v[SXY] * v[SXY] + v[SXZ] * v[SXZ] + v[SYZ] * v[SYZ]));
    v[LINKS] = s[i][McaElementStress::LINKS];
    v[VOLUME] = McaElement::volume(atom->radius[i], pair->packing_fraction(), domain->dimension);
    v[DAMAGE] = pair->element_damage(i);
  }
}

double ComputeMcaAtom::memory_usage()
{
  return (double) nmax * NCOLUMNS * sizeof(double);
}
