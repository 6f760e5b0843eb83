/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative's tables per
   type pair (damping_types.h).
------------------------------------------------------------------------- */

#include "damping_types.h"

#include "atom.h"
#include "force.h"
#include "pair.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

DampingTypes::DampingTypes(LAMMPS *lmp, const ViscousSettings &settings) :
    Pointers(lmp), opt(settings), np1(atom->ntypes + 1)
{
  typepair = new TypePair[np1 * np1]();
  coeff = new DampingCoeff[np1 * np1]();
}

DampingTypes::~DampingTypes()
{
  delete[] typepair;
  delete[] coeff;
}

// the fix's init checked that the pair style gives C where style J needs it
void DampingTypes::fill()
{
  int dim = 0;
  double **stiffness = opt.by_j ? (double **) force->pair->extract("C", dim) : nullptr;
  for (int i = 1; i < np1; i++)
    for (int j = 1; j < np1; j++) {
      TypePair &tp = typepair[i * np1 + j];
      tp.cutsq = opt.cutoff > 0.0 ? opt.cutoff * opt.cutoff : force->pair->cutsq[i][j];
      tp.stiffness = opt.by_j ? stiffness[i][j] : 0.0;
      DampingCoeff &c = coeff[i * np1 + j];
      c.inv_cut = tp.cutsq > 0.0 ? 1.0 / sqrt(tp.cutsq) : 0.0;
      c.coef = atom->rmass ? 0.0 : friction(tp, atom->mass[i], atom->mass[j]);
    }
}

double DampingTypes::rate(const TypePair &tp, double mij) const
{
  return opt.rate(tp.stiffness, mij, force->ftm2v);
}

double DampingTypes::friction(const TypePair &tp, double mi, double mj) const
{
  const double mij = 2.0 * mi * mj / (mi + mj);
  return mij * rate(tp, mij) / force->ftm2v;
}

double DampingTypes::memory_usage() const
{
  return (double) np1 * np1 * (sizeof(TypePair) + sizeof(DampingCoeff));
}
