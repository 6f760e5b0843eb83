/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the stiffnesses of the elements of
   pair_style mca (see mca_element_stiffness.h).
------------------------------------------------------------------------- */

#include "mca_element_stiffness.h"

#include "mca_contact.h"

#include "atom.h"
#include "memory.h"

using namespace LAMMPS_NS;
using namespace ClusterDyn;

McaElementStiffness::~McaElementStiffness()
{
  memory->destroy(a);
  memory->destroy(b);
}

void McaElementStiffness::grow(int nmax_atoms)
{
  if (nmax_atoms <= nmax) return;
  nmax = nmax_atoms;
  memory->destroy(a);
  memory->destroy(b);
  memory->create(a, nmax, "pair:stiffness");
  memory->create(b, nmax, 2, "pair:hourglass");
}

double McaElementStiffness::memory_usage() const
{
  return 3.0 * nmax * sizeof(double);
}

void McaElementStiffness::compute(const std::vector<McaMaterial> &scaled, bool springs)
{
  const int nall = atom->nlocal + atom->nghost;
  const int *type = atom->type;
  const double *radius = atom->radius;
  for (int i = 0; i < nall; i++) a[i] = McaContact::half_stiffness(scaled[type[i]].shear, radius[i]);
  if (springs)
    for (int i = 0; i < nall; i++) {
      const McaMaterial &m = scaled[type[i]];
      b[i][0] = 2.0 * m.hourglass * (m.bulk + 4.0 * m.shear / 3.0) / radius[i];
      b[i][1] = 4.0 * m.hourglass / radius[i];
    }
}
