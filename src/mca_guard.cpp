/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the checks of pair_style mca (see
   mca_guard.h).
------------------------------------------------------------------------- */

#include "mca_guard.h"

#include "mca_element.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "modify.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

void McaGuard::check_style(int tail_flag, int offset_flag, int plane) const
{
  if (!atom->radius_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "Pair mca requires atom_style sphere (elements with radius, omega and "
               "torque)");
  if (domain->dimension == 2 && plane == McaSettings::NONE)
    error->all(FLERR, "Pair mca in dimension 2 needs 'plane strain' or 'plane stress' in "
               "pair_style mca (the elements are discs of unit thickness: which state they are in)");
  if (domain->dimension == 3 && plane != McaSettings::NONE)
    error->all(FLERR, "Pair mca: plane strain|stress is for dimension 2 (this box is 3d)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "Pair mca needs the velocities of ghost elements: comm_modify vel yes");
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Pair mca is not for run_style respa (use run_style verlet)");
  if (tail_flag) error->all(FLERR, "Pair mca: pair_modify tail yes does not apply");
  if (offset_flag) error->all(FLERR, "Pair mca: pair_modify shift yes does not apply");
}

void McaGuard::check_shock(const std::vector<McaMaterial> &given, bool manybody) const
{
  bool shock = false;
  for (const McaMaterial &m : given) shock = shock || m.shock();
  if (!shock) return;
  if (domain->dimension == 2)
    error->all(FLERR, "Pair mca: the shock equation of state (pair_coeff ... shock) is "
               "three-dimensional: in dimension 2 give bulk K shear G");
  if (!manybody)
    error->all(FLERR, "Pair mca: a shock equation of state (pair_coeff ... shock) needs the "
               "many-body term: remove 'manybody no'");
  if (update->whichflag == 2)
    error->all(FLERR, "Pair mca: the elements' shock equation of state follows their volume "
               "through a run; minimize cannot move it (use the linear law, bulk K)");
}

void McaGuard::init()
{
  const int ntypes = atom->ntypes;
  std::vector<double> mine(ntypes + 1, 0.0);
  double rmin = INFINITY;
  tagint bad = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    const double r = atom->radius[i];
    mine[atom->type[i]] = MAX(mine[atom->type[i]], r);
    if (!(r > 0.0) && (bad == 0 || r < rmin)) {
      rmin = r;
      bad = atom->tag[i];
    }
  }
  for (const char *style : {"^pour", "^deposit"})
    for (Fix *inserting : modify->get_fix_by_style(style))
      for (int t = 1; t <= ntypes; t++) {
        int itype = t;
        const double *r = (const double *) inserting->extract("radius", itype);
        if (r) mine[t] = MAX(mine[t], *r);
      }
  rmax.assign(ntypes + 1, 0.0);
  MPI_Allreduce(mine.data(), rmax.data(), ntypes + 1, MPI_DOUBLE, MPI_MAX, world);
  tagint anybad;
  MPI_Allreduce(&bad, &anybad, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (anybad)
    error->all(FLERR, "Pair mca: element {} has radius <= 0 (elements need a positive "
               "diameter: set diameter)", anybad);
}

void McaGuard::each_step() const
{
  const double *radius = atom->radius;
  const int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++)
    if (radius[i] > rmax[type[i]])
      error->one(FLERR, "Pair mca: element {} is larger than the elements of its type were when "
                 "the run started (the cutoffs are made from them, from fix pour and from fix "
                 "deposit): sizes are fixed during a run", atom->tag[i]);
}

// d sqrt(rho / (K + 4G/3)), rho = m / Omega, over the elements
void McaGuard::at_setup(const std::vector<McaMaterial> &scaled, double fraction) const
{
  const double *radius = atom->radius, *rmass = atom->rmass;
  if (!rmass) return;
  const int *type = atom->type;
  double shortest = INFINITY;
  for (int i = 0; i < atom->nlocal; i++) {
    const McaMaterial &m = scaled[type[i]];
    const double rho = rmass[i] / McaElement::volume(radius[i], fraction, domain->dimension);
    shortest = MIN(shortest, 2.0 * radius[i] * sqrt(rho / (m.bulk + 4.0 * m.shear / 3.0)));
  }
  double all;
  MPI_Allreduce(&shortest, &all, 1, MPI_DOUBLE, MPI_MIN, world);
  // velocity Verlet: forces in force units, masses in mass units (ftm2v)
  const double crossing = all / sqrt(force->ftm2v);
  if (std::isfinite(crossing) && update->dt > 0.2 * crossing && comm->me == 0)
    error->warning(FLERR, "Pair mca: timestep {:.6g} is more than 0.2 of the time {:.6g} a "
                   "longitudinal wave takes to cross the smallest element: expect energy "
                   "errors above 1e-2 or instability (doc: dt <= 0.1 of it)", update->dt,
                   crossing);
}

std::vector<double> McaGuard::state_reach(double tolerance) const
{
  std::vector<double> reach(rmax.size(), 0.0);
  for (std::size_t t = 1; t < rmax.size(); t++) reach[t] = (1.0 + tolerance) * rmax[t];
  return reach;
}
