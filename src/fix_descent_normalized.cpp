/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix descent/normalized.

   Chernyshev's quasi-static particle method (doc/fix_descent_normalized.rst):
   each timestep is one iteration that moves every atom of the group by a
   step of length h along its force,
     x_i <- x_i + h F_i / |F_i|          (atoms with F_i = 0 stay)
   and then h <- max(F h, Hmin).  The forces are those of the previous
   step after every fix has acted (fix setforce, walls), as a time
   integrator sees them.  With inertia M K, K times the mean of the atom's
   last M displacements is added to its step; the displacements are kept
   per atom (they migrate with the atom and are written to restart files).
   Velocities are zero, or with inertia the mean displacement / dt.
------------------------------------------------------------------------- */

#include "fix_descent_normalized.h"

#include "arg_values.h"
#include "keyword_set.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace ClusterDyn;

FixDescentNormalized::FixDescentNormalized(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), decay(1.0), hmin(0.0), nmemory(0), kinertia(0.0), nfilled(0), slot(0),
    nper(0), sum(nullptr), dmax_local(0.0), stats_step(-1), stats{0.0, 0.0, 0.0}
{
  if (narg < 5 || strcmp(arg[3], "h") != 0)
    error->all(FLERR, "Fix descent/normalized: expected fix ID group descent/normalized h H "
               "[decay F] [min Hmin] [inertia M K]");
  step = positive_arg("Fix descent/normalized", "h", arg[4], lmp);

  int iarg = 5;
  KeywordSet given(lmp, "Fix descent/normalized", Keywords::DESCENT_NORMALIZED);
  while (iarg < narg) {
    const std::string key = arg[iarg];
    const int nvalues = given.add(key).values;
    if (iarg + nvalues >= narg)
      error->all(FLERR, "Fix descent/normalized: keyword {} needs {} value{}", key, nvalues,
                 nvalues > 1 ? "s" : "");
    if (key == "decay") {
      decay = number_arg("Fix descent/normalized", "decay F", arg[iarg + 1], lmp);
      if (!(decay > 0.0 && decay <= 1.0))
        error->all(FLERR, "Fix descent/normalized: decay F must be in (0,1] (got {})",
                   arg[iarg + 1]);
    } else if (key == "min") {
      hmin = number_arg("Fix descent/normalized", "min Hmin", arg[iarg + 1], lmp);
      if (!(hmin >= 0.0 && hmin <= step))
        error->all(FLERR, "Fix descent/normalized: min Hmin must be in [0,h] (got {})",
                   arg[iarg + 1]);
    } else {
      const double m = number_arg("Fix descent/normalized", "inertia M", arg[iarg + 1], lmp);
      if (!(m >= 1.0))
        error->all(FLERR, "Fix descent/normalized: inertia M must be >= 1 (got {})",
                   arg[iarg + 1]);
      if (!(m <= MAX_MEMORY) || m != floor(m))
        error->all(FLERR, "Fix descent/normalized: inertia M must be an integer <= {} (got {}): "
                   "the memory holds 3 M values per atom", MAX_MEMORY, arg[iarg + 1]);
      nmemory = (int) m;
      kinertia = number_arg("Fix descent/normalized", "inertia K", arg[iarg + 2], lmp);
      if (!(kinertia >= 0.0 && kinertia < 1.0))
        error->all(FLERR, "Fix descent/normalized: inertia K must be in [0,1) (got {})",
                   arg[iarg + 2]);
    }
    iarg += nvalues + 1;
  }

  time_integrate = 1;
  scalar_flag = 1;
  extscalar = 0;
  vector_flag = 1;
  size_vector = 3;
  extvector = 0;
  global_freq = 1;
  restart_global = 1;

  if (nmemory) {
    restart_peratom = 1;
    nper = 3 * nmemory + 3;
    maxexchange = nper;
    rings.assign(nmemory, nullptr);
    grow_arrays(atom->nmax);
    atom->add_callback(Atom::GROW);
    atom->add_callback(Atom::RESTART);
    for (int i = 0; i < atom->nlocal; i++) clear_history(i);
  }
}

FixDescentNormalized::~FixDescentNormalized()
{
  if (nmemory) {
    atom->delete_callback(id, Atom::GROW);
    atom->delete_callback(id, Atom::RESTART);
  }
  for (auto &ring : rings) memory->destroy(ring);
  memory->destroy(sum);
}

int FixDescentNormalized::setmask()
{
  return INITIAL_INTEGRATE;
}

void FixDescentNormalized::init()
{
  if (!utils::strmatch(update->integrate_style, "^verlet"))
    error->all(FLERR, "Fix descent/normalized needs run_style verlet (got {})",
               update->integrate_style);
  check_integrators();
  const double box = domain->dimension == 2 ? MIN(domain->xprd, domain->yprd)
                                             : MIN(MIN(domain->xprd, domain->yprd), domain->zprd);
  if (!(step < box))
    error->all(FLERR, "Fix descent/normalized: h = {} must be smaller than the box ({})", step,
               box);
  if (nmemory && !(update->dt > 0.0))
    error->all(FLERR, "Fix descent/normalized: inertia needs a time step > 0 (got {}): the "
               "velocities are the mean displacement / dt", update->dt);
}

// no other time integrator may move the atoms this fix moves
void FixDescentNormalized::check_integrators()
{
  const int *mask = atom->mask;
  for (const auto &fix : modify->get_fix_list()) {
    if (fix == this || !fix->time_integrate) continue;
    bigint mine = 0, all = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((mask[i] & groupbit) && (mask[i] & fix->groupbit)) mine++;
    MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (all)
      error->all(FLERR, "Fix descent/normalized {} and time integrator fix {} ({}) move the same "
                 "{} atoms: each atom needs exactly one", id, fix->id, fix->style, all);
  }
}

void FixDescentNormalized::setup(int /*vflag*/)
{
  stats_step = -1;
  double **v = atom->v;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && !nmemory) v[i][0] = v[i][1] = v[i][2] = 0.0;
}

void FixDescentNormalized::initial_integrate(int /*vflag*/)
{
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int dim = domain->dimension;
  const int nfilled_next = nfilled < nmemory ? nfilled + 1 : nmemory;
  const double inv_dt = 1.0 / update->dt;

  dmax_local = 0.0;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double d[3] = {0.0, 0.0, 0.0};
    double fsq = 0.0;
    for (int k = 0; k < dim; k++) fsq += f[i][k] * f[i][k];
    if (fsq > 0.0) {
      const double scale = step / sqrt(fsq);
      for (int k = 0; k < dim; k++) d[k] = scale * f[i][k];
    }
    if (nmemory) {
      // ring of the last M displacements (slot: the oldest, overwritten now) and their sum
      double *ring = rings[slot][i];
      double *total = sum[i];
      for (int k = 0; k < 3; k++) {
        if (nfilled) d[k] += kinertia * total[k] / nfilled;
        if (nfilled == nmemory) total[k] -= ring[k];
        ring[k] = d[k];
        total[k] += d[k];
        v[i][k] = total[k] / nfilled_next * inv_dt;
      }
    } else {
      v[i][0] = v[i][1] = v[i][2] = 0.0;
    }
    for (int k = 0; k < 3; k++) x[i][k] += d[k];
    dmax_local = fmax(dmax_local, sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
  }
  nfilled = nfilled_next;
  if (nmemory) slot = (slot + 1) % nmemory;
  step = fmax(step * decay, hmin);
  stats_step = -1;
}

// max and mean |F_i| over the group at the current forces, largest last displacement
void FixDescentNormalized::compute_stats()
{
  if (stats_step == update->ntimestep) return;
  double **f = atom->f;
  const int *mask = atom->mask;
  double mine[2] = {0.0, dmax_local}, sum[2] = {0.0, 0.0}, all[2];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double fmag = sqrt(f[i][0] * f[i][0] + f[i][1] * f[i][1] + f[i][2] * f[i][2]);
    mine[0] = fmax(mine[0], fmag);
    sum[0] += fmag;
    sum[1] += 1.0;
  }
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_MAX, world);
  double total[2];
  MPI_Allreduce(sum, total, 2, MPI_DOUBLE, MPI_SUM, world);
  stats[0] = all[0];
  stats[1] = total[1] > 0.0 ? total[0] / total[1] : 0.0;
  stats[2] = all[1];
  stats_step = update->ntimestep;
}

double FixDescentNormalized::compute_scalar()
{
  return step;
}

double FixDescentNormalized::compute_vector(int n)
{
  compute_stats();
  return stats[n];
}

void FixDescentNormalized::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    const double list[3] = {step, (double) nfilled, (double) slot};
    const int size = sizeof(list);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), 3, fp);
  }
}

void FixDescentNormalized::restart(char *buf)
{
  double list[3];
  memcpy(list, buf, sizeof(list));
  step = list[0];
  nfilled = MIN((int) list[1], nmemory);
  slot = nmemory ? static_cast<int>(list[2]) % nmemory : 0;
}

void FixDescentNormalized::grow_arrays(int nmax)
{
  memory->grow(sum, nmax, 3, "descent/normalized:sum");
  for (auto &ring : rings) memory->grow(ring, nmax, 3, "descent/normalized:ring");
}

void FixDescentNormalized::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < 3; k++) sum[j][k] = sum[i][k];
  for (auto &ring : rings)
    for (int k = 0; k < 3; k++) ring[j][k] = ring[i][k];
}

int FixDescentNormalized::pack_exchange(int i, double *buf)
{
  return pack_history(i, buf);
}

int FixDescentNormalized::unpack_exchange(int nlocal, double *buf)
{
  return unpack_history(nlocal, buf, nper);
}

int FixDescentNormalized::pack_restart(int i, double *buf)
{
  buf[0] = nper + 1;    // the size first, as every fix's restart data
  return pack_history(i, buf + 1) + 1;
}

void FixDescentNormalized::unpack_restart(int nlocal, int nth)
{
  if (!nmemory) return;    // written with inertia, read without: nothing to keep
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const int stored = static_cast<int>(extra[nlocal][m]) - 1;
  if (stored == nper) unpack_history(nlocal, &extra[nlocal][m + 1], nper);
  else clear_history(nlocal);    // written with another M: start the memory afresh
}

int FixDescentNormalized::size_restart(int /*nlocal*/)
{
  return nper + 1;
}

int FixDescentNormalized::maxsize_restart()
{
  return nper + 1;
}

// atom i's running sum, then its ring slots in order: nper values
int FixDescentNormalized::pack_history(int i, double *buf)
{
  int n = 0;
  for (int k = 0; k < 3; k++) buf[n++] = sum[i][k];
  for (auto &ring : rings)
    for (int k = 0; k < 3; k++) buf[n++] = ring[i][k];
  return n;
}

int FixDescentNormalized::unpack_history(int i, const double *buf, int n)
{
  int m = 0;
  for (int k = 0; k < 3; k++) sum[i][k] = buf[m++];
  for (auto &ring : rings)
    for (int k = 0; k < 3; k++) ring[i][k] = buf[m++];
  return n;
}

void FixDescentNormalized::clear_history(int i)
{
  for (int k = 0; k < 3; k++) sum[i][k] = 0.0;
  for (auto &ring : rings)
    for (int k = 0; k < 3; k++) ring[i][k] = 0.0;
}

double FixDescentNormalized::memory_usage()
{
  return (double) atom->nmax * nper * sizeof(double);
}
