/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative's stability
   check (damping_stability.h).
------------------------------------------------------------------------- */

#include "damping_stability.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace ClusterDyn;

void ClusterDyn::check_damping_stability(LAMMPS *lmp, Fix *fix, const DampingBonds &bonds,
                                         const DampingTypes &types, const ViscousSettings &opt,
                                         DampingForces &counts)
{
  const Atom *atom = lmp->atom;
  const int nlocal = atom->nlocal;
  const int groupbit = fix->groupbit;
  counts.clear();
  xyz3 *const count = counts.data();    // .x: bonds of atom i
  const double *const *const x = atom->x;
  const int *type = atom->type;
  const int *mask = atom->mask;
  double rate_max = 0.0;
  const NeighList *const list = bonds.list;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const int jnum = bonds.words ? bonds.counts[i] : list->numneigh[i];    // the rest: unlinked
    for (int jj = 0; jj < jnum; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const DampingTypes::TypePair &tp = types.row(type[i])[type[j]];
      if (dx * dx + dy * dy + dz * dz >= tp.cutsq) continue;
      if (bonds.words && !state_now(bonds.words[i][jj])) continue;
      count[i].x += 1.0;
      if (lmp->force->newton_pair || j < nlocal) count[j].x += 1.0;
      const double mi = atom->rmass ? atom->rmass[i] : atom->mass[type[i]];
      const double mj = atom->rmass ? atom->rmass[j] : atom->mass[type[j]];
      rate_max = MAX(rate_max, types.rate(tp, 2.0 * mi * mj / (mi + mj)));
    }
  }
  counts.sum_to_owners(fix);
  double most = 0.0;    // bonds of one atom
  for (int i = 0; i < nlocal; i++) most = MAX(most, count[i].x);
  double mine[2] = {most, rate_max}, all[2];
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_MAX, lmp->world);
  const double dt = lmp->update->dt;
  const double product = all[1] * all[0] * dt;
  if (product > 1.0) {    // a run diverges (NaN, lost atoms); run 0 is only told
    const std::string text = fmt::format(
        "Fix viscous/relative: G x bonds x dt = {:.3g} x {} x {:.3g} = {:.3g} > 1: the damping is "
        "unstable with explicit integration; use a time step below {:.3g} (or a smaller {})",
        all[1], (int) all[0], dt, product, 1.0 / (all[1] * all[0]), opt.by_j ? "1/J" : "gamma");
    if (lmp->update->nsteps > 0) lmp->error->all(FLERR, text);
    if (lmp->comm->me == 0) lmp->error->warning(FLERR, text);
  }
}
