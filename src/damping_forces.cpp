/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative's damping
   forces per atom (damping_forces.h).
------------------------------------------------------------------------- */

#include "damping_forces.h"

#include "atom.h"
#include "comm.h"
#include "force.h"
#include "memory.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

DampingForces::~DampingForces()
{
  memory->destroy(fd);
}

void DampingForces::clear()
{
  if (atom->nmax > maxfd) {
    maxfd = atom->nmax;
    memory->destroy(fd);
    memory->create(fd, maxfd, 3, "viscous/relative:fd");
  }
  const int nall = atom->nlocal + atom->nghost;
  if (nall) memset(&fd[0][0], 0, 3 * sizeof(double) * nall);
}

void DampingForces::sum_to_owners(Fix *fix)
{
  if (force->newton_pair) comm->reverse_comm(fix);
}

double DampingForces::add_to_forces(Fix *fix)
{
  sum_to_owners(fix);
  double **f = atom->f;
  for (int i = 0; i < atom->nlocal; i++) {
    f[i][0] += fd[i][0];
    f[i][1] += fd[i][1];
    f[i][2] += fd[i][2];
  }
  return power();
}

double DampingForces::power() const
{
  const double *const *const v = atom->v;
  double p = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    p += fd[i][0] * v[i][0] + fd[i][1] * v[i][1] + fd[i][2] * v[i][2];
  return p;
}

int DampingForces::pack(int n, int first, double *buf) const
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    buf[m++] = fd[i][0];
    buf[m++] = fd[i][1];
    buf[m++] = fd[i][2];
  }
  return m;
}

void DampingForces::unpack(int n, const int *list, const double *buf)
{
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    fd[j][0] += buf[m++];
    fd[j][1] += buf[m++];
    fd[j][2] += buf[m++];
  }
}

double DampingForces::memory_usage() const
{
  return (double) maxfd * 3 * sizeof(double);
}
