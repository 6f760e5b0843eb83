/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the element stresses of
   pair_style mca (see mca_element_stress.h).
------------------------------------------------------------------------- */

#include "mca_element_stress.h"

#include "atoms_fingerprint.h"

#include "atom.h"
#include "domain.h"
#include "force.h"
#include "memory.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

McaElementStress::~McaElementStress()
{
  memory->destroy(rows);
}

void McaElementStress::grow(int nmax_atoms)
{
  if (nmax_atoms <= nmax) return;
  nmax = nmax_atoms;
  memory->destroy(rows);
  memory->create(rows, nmax, COLUMNS, "pair:stress");
}

double McaElementStress::memory_usage() const
{
  return (double) nmax * COLUMNS * sizeof(double);
}

void McaElementStress::zero(int nall)
{
  if (nall > 0) memset(rows[0], 0, sizeof(double) * nall * COLUMNS);    // memory->create: one block
}

void McaElementStress::to_owners(bool to_pressure)
{
  exchange.to_owners(rows, COLUMNS);
  const double scale = to_pressure ? force->nktv2p : 1.0;
  for (int i = 0; i < atom->nlocal; i++) {
    const double to_stress = scale / McaElement::volume(atom->radius[i], fraction, domain->dimension);
    for (int k = 0; k < 6; k++) rows[i][k] *= to_stress;
  }
  if (to_pressure) {
    step = update->ntimestep;
    atoms = atoms_fingerprint(atom);
  }
}

double **McaElementStress::current() const
{
  return step == update->ntimestep && atoms == atoms_fingerprint(atom) ? rows : nullptr;
}
