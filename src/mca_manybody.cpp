/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the many-body (volumetric) part of
   pair_style mca (see mca_manybody.h).
------------------------------------------------------------------------- */

#include "mca_manybody.h"

#include "mca_element.h"

#include "atom.h"
#include "domain.h"
#include "memory.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

McaManybody::~McaManybody()
{
  memory->destroy(theta);
  memory->destroy(dtheta);
  memory->destroy(extra);
}

void McaManybody::grow(int nmax_atoms)
{
  if (nmax_atoms <= nmax) return;
  nmax = nmax_atoms;
  memory->destroy(theta);
  memory->destroy(dtheta);
  memory->destroy(extra);
  memory->create(extra, nmax, "pair:theta_modulus");
  memory->create(theta, nmax, 1, "pair:theta");
  memory->create(dtheta, nmax, NCHANGES, "pair:dtheta");
}

double McaManybody::memory_usage() const
{
  return (double) nmax * (2 + NCHANGES) * sizeof(double);
}

double McaManybody::volume(int i) const
{
  return McaElement::volume(atom->radius[i], fraction, domain->dimension);
}

void McaManybody::begin_strain(int nall)
{
  if (nall == 0) return;
  memset(theta[0], 0, sizeof(double) * nall);    // memory->create: one block
  memset(extra, 0, sizeof(double) * nall);
}

void McaManybody::finish_strain()
{
  exchange.to_owners(theta, 1);
  for (int i = 0; i < atom->nlocal; i++) theta[i][0] /= volume(i);
  exchange.to_ghosts(theta, 1);
}

void McaManybody::begin_changes(int nall)
{
  if (nall > 0) memset(dtheta[0], 0, sizeof(double) * nall * NCHANGES);    // one block
}

void McaManybody::tally_changes(StateTally &changes, int damage_work, int plastic_work,
                                McaElementShares heat)
{
  exchange.to_owners(dtheta, NCHANGES);
  const int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    const double omega = volume(i);
    const double half = 0.5 * ((*scaled)[type[i]].lambda + extra[i]) * omega;
    double now = theta[i][0], e_now = half * now * now;
    double released[MOTION];
    for (int c = 0; c < MOTION; c++) {
      now += dtheta[i][c] / omega;
      const double e = half * now * now;
      released[c] = e_now - e;
      e_now = e;
    }
    // the lag of the pair stress behind the plastic flow, over the step's motion
    released[CHANGE_PLASTIC] -= half * dtheta[i][CHANGE_PLASTIC] * dtheta[i][MOTION] / (omega * omega);
    changes.ejump += released[CHANGE_STATE];
    changes.work[damage_work] += released[CHANGE_DAMAGE];
    changes.work[plastic_work] += released[CHANGE_PLASTIC];
    if (heat) heat.add(0, i, i, released[CHANGE_PLASTIC], McaPairHalves(0.0, 1.0), false);    // all to i
  }
}

void McaManybody::tally_energy(double *total, double *per_atom) const
{
  for (int i = 0; i < atom->nlocal; i++) {
    const double e =
        0.5 * ((*scaled)[atom->type[i]].lambda + extra[i]) * volume(i) * theta[i][0] * theta[i][0];
    if (total) *total += e;
    if (per_atom) per_atom[i] += e;
  }
}
