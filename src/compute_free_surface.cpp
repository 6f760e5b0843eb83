/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute free/surface.

   The velocity of a body's free face: of the group's atoms that the named
   compute dust counts in its group and does not flag as dust, the
   outermost along the axis (largest coordinate for the rear face, smallest
   for the front) sets the face; the atoms within `depth` of it give the
   mass-weighted mean velocity along the axis.  After a spall the rear face
   is that of the spalled layer (its large fragment lies outermost), as a
   VISAR sees it.  With minsize N the body's pieces are the fragments of at
   least N atoms (the dust flags are not read).  A face that lies more than
   `depth` from where the last evaluation's face and velocity put it counts
   as a jump (a piece of the body counted as dust for a while, or one that
   came back): the fourth output, for tools/pull_back.py to refuse such a
   record.  Two reductions over the processors (the face, then the layer's
   momentum, mass and count).
------------------------------------------------------------------------- */

#include "compute_free_surface.h"

#include "arg_values.h"
#include "atom.h"
#include "error.h"
#include "keyword_set.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

static const char *WHO = "Compute free/surface";

ComputeFreeSurface::ComputeFreeSurface(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg)
{
  if (narg < 5)
    error->all(FLERR, "{}: expected compute ID group free/surface dust-ID depth "
               "[axis x|y|z] [face rear|front] [minsize N]", WHO);
  dust_id = arg[3];
  depth = positive_arg(WHO, "depth", arg[4], lmp);
  KeywordSet given(lmp, WHO, Keywords::FREE_SURFACE);
  for (int i = 5; i < narg; i += 2) {
    const std::string key = arg[i];
    given.add(key);
    if (i + 1 >= narg) error->all(FLERR, "{}: {} needs a value", WHO, key);
    const std::string val = arg[i + 1];
    if (key == "minsize") {
      minsize = integer_arg(WHO, "minsize", arg[i + 1], lmp);
      if (minsize < 1) error->all(FLERR, "{}: minsize must be >= 1 (got {})", WHO, val);
    } else if (key == "axis") {
      if (val != "x" && val != "y" && val != "z")
        error->all(FLERR, "{}: axis must be x, y or z (got '{}')", WHO, val);
      axis = val[0] - 'x';
    } else {
      if (val != "rear" && val != "front")
        error->all(FLERR, "{}: face must be rear or front (got '{}')", WHO, val);
      sign = val == "rear" ? 1 : -1;
    }
  }
  vector_flag = 1;
  size_vector = 4;
  extvector = 0;
  vector = new double[size_vector];
}

ComputeFreeSurface::~ComputeFreeSurface()
{
  delete[] vector;
}

void ComputeFreeSurface::init()
{
  dust = modify->get_compute_by_id(dust_id);
  if (!dust) error->all(FLERR, "{}: no compute with ID '{}'", WHO, dust_id);
  if (strcmp(dust->style, "dust") != 0)
    error->all(FLERR, "{}: compute '{}' is {}, not a compute dust", WHO, dust_id, dust->style);
}

void ComputeFreeSurface::compute_vector()
{
  // not invoked (-1) on another step than the last evaluation: reset_timestep, or a new run
  // whose last one did not end with an evaluation: the clock may not be the last's
  if (invoked_vector < 0 && update->ntimestep != last.step) last.found = false;
  invoked_vector = update->ntimestep;
  if (dust->invoked_peratom != update->ntimestep) dust->compute_peratom();
  double **fragment = dust->array_atom;    // fragment ID, size (0: outside its group), dust flag
  double **x = atom->x, **v = atom->v;
  const int *mask = atom->mask, *type = atom->type;
  const int nlocal = atom->nlocal;
  auto counted = [&](int i) {
    if (!(mask[i] & groupbit) || !(fragment[i][1] > 0.0)) return false;
    return minsize > 0 ? fragment[i][1] >= minsize : fragment[i][2] == 0.0;
  };

  double outer = -HUGE_VAL, outer_all;    // sign x of the outermost atom
  for (int i = 0; i < nlocal; i++)
    if (counted(i)) outer = std::max(outer, sign * x[i][axis]);
  MPI_Allreduce(&outer, &outer_all, 1, MPI_DOUBLE, MPI_MAX, world);

  double sums[3] = {0.0, 0.0, 0.0}, all[3];    // momentum, mass, atoms of the layer
  for (int i = 0; i < nlocal; i++)
    if (counted(i) && sign * x[i][axis] > outer_all - depth) {
      const double m = atom->rmass ? atom->rmass[i] : atom->mass[type[i]];
      sums[0] += m * v[i][axis];
      sums[1] += m;
      sums[2] += 1.0;
    }
  MPI_Allreduce(sums, all, 3, MPI_DOUBLE, MPI_SUM, world);
  vector[0] = all[1] > 0.0 ? all[0] / all[1] : 0.0;
  vector[1] = all[2] > 0.0 ? sign * outer_all : 0.0;
  vector[2] = all[2];
  count_jump(all[2] > 0.0, outer_all, vector[0]);
  vector[3] = jumps;
}

/* ----------------------------------------------------------------------
   the face (outermost sign x) against where the last evaluation's face and
   the mean of the two velocities put it: more than depth away, beyond what
   a change of velocity at any time in between can explain (half the change
   times the interval), or the face gone, is a jump.  A second evaluation
   on the same step compares nothing, nor the first after reset_timestep, a
   rerun's earlier snapshot, or a run whose last did not end with one.
------------------------------------------------------------------------- */

void ComputeFreeSurface::count_jump(bool found, double face, double velocity)
{
  if (update->ntimestep == last.step) return;
  const double now = update->atime + (update->ntimestep - update->atimestep) * update->dt;
  if (last.found && update->ntimestep > last.step) {
    const double interval = now - last.time;
    const double expected = last.face + sign * 0.5 * (last.velocity + velocity) * interval;
    const double slack = depth + 0.5 * fabs(velocity - last.velocity) * fabs(interval);
    if (!found || fabs(face - expected) > slack) jumps += 1.0;
  }
  last = {update->ntimestep, found, face, velocity, now};
}
