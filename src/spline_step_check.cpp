/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: time-step check of the spline pair
   styles (spline_step_check.h).
------------------------------------------------------------------------- */

#include "spline_step_check.h"

#include "spline_kernel.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "math_const.h"
#include "neigh_list.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace ClusterDyn;
using MathConst::MY_PI;

static constexpr double BIG = 1.0e300;

void SplineStepCheck::check(LAMMPS *lmp, const char *style, const NeighList *list,
                            const LawSource &law, const SplineCoeff *coeffs, double **stiffness,
                            int chain_n, const std::vector<double> &chain_scale)
{
  Update *update = lmp->update;
  Atom *atom = lmp->atom;
  // a run 0 (to read compute pair/params before choosing the step) takes no step
  if (warned || update->whichflag != 1 || update->nsteps == 0) return;
  if (!update->setupflag && update->ntimestep < next_check) return;
  next_check = update->ntimestep + EVERY;
  const int ntp1 = atom->ntypes + 1;
  std::vector<double> rminsq(ntp1 * ntp1, BIG);
  const double *const *const x = atom->x;
  const int *const type = atom->type;
  const tagint *const tag = atom->tag;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      double rsq = dx * dx + dy * dy + dz * dz;
      if (chain_n) {
        const tagint n = chain_distance(tag[i], tag[j]);
        if (n == 0 || n > chain_n) continue;
        rsq *= chain_scale[n];
      }
      double &rmin = rminsq[type[i] * ntp1 + type[j]];
      if (rsq < coeffs[type[i] * ntp1 + type[j]].cutsq && rsq < rmin) rmin = rsq;
    }
  }
  double mass_min = BIG;
  if (atom->rmass)
    for (int i = 0; i < atom->nlocal; i++) mass_min = MIN(mass_min, atom->rmass[i]);
  double mine[2] = {BIG, BIG}, all[2];    // suggested step, closest r/a
  for (int i = 1; i < ntp1; i++)
    for (int j = 1; j < ntp1; j++) {
      const double rsq = MIN(rminsq[i * ntp1 + j], rminsq[j * ntp1 + i]);
      if (rsq == BIG) continue;
      const double r = sqrt(rsq);
      double d[4];
      law.law_derivs(i, j, r, d, true);
      const double m = atom->rmass ? mass_min : MIN(atom->mass[i], atom->mass[j]);
      const double k = MAX(d[2], stiffness[i][j]);
      mine[0] = MIN(mine[0], MY_PI / (20.0 * sqrt(lmp->force->ftm2v * k / m)));
      mine[1] = MIN(mine[1], r / coeffs[i * ntp1 + j].a);
    }
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_MIN, lmp->world);
  if (update->dt > all[0]) {
    warned = 1;
    if (lmp->comm->me == 0)
      lmp->error->warning(FLERR, "Pair {}: time step {:.4g} exceeds {:.4g}, the step compute "
                          "pair/params suggests (T_min/20) for the compression present at step "
                          "{} (closest pair at {:.4g} a): the run may be inaccurate or unstable; "
                          "reduce the time step", style, update->dt, all[0], update->ntimestep,
                          all[1]);
  }
}
