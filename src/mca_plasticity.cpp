/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: von Mises plasticity of movable
   cellular automata (mca_plasticity.h).
------------------------------------------------------------------------- */

#include "mca_plasticity.h"

#include "mca_element_stress.h"

#include "atom.h"
#include "error.h"
#include "fix.h"
#include "memory.h"
#include "modify.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

void McaPlasticity::init(const std::vector<McaMaterial> &materials, bool in_plane_strain)
{
  on = false;
  plane_strain = in_plane_strain;
  for (const McaMaterial &m : materials)
    if (m.yield > 0.0) on = true;
  if (on && !modify->get_fix_by_id(FIX_ID)) {
    Fix *fix = modify->add_fix(
        fmt::format("{} all property/atom d_{} d_{} ghost yes", FIX_ID, NAME, NAME_ZZ));
    // as the pair states, the plastic strain stays out of data files (a plain read_data
    // could not read its section back): elements read from one are fresh
    fix->wd_section = 0;
  }
  if (on && (!strain_array() || !column(NAME_ZZ)))
    error->all(FLERR, "Pair mca: fix {} is not the per-element plastic strains (fix "
               "property/atom d_{} d_{}) the style makes: its ID is reserved", FIX_ID, NAME,
               NAME_ZZ);
}

double *McaPlasticity::column(const char *name) const
{
  int flag, cols;
  const int index = atom->find_custom(name, flag, cols);
  return index < 0 || flag != 1 || cols != 0 ? nullptr : atom->dvector[index];
}

McaPlasticity::~McaPlasticity()
{
  memory->destroy(returned);
}

void McaPlasticity::grow(int nmax_atoms)
{
  if (!on || nmax_atoms <= nmax) return;
  nmax = nmax_atoms;
  memory->destroy(returned);
  memory->create(returned, nmax, COLUMNS, "pair:returned");
}

void McaPlasticity::return_map(double *const *stress, const std::vector<McaMaterial> &scaled)
{
  double *const *out = returned;
  double *eps_p = strain_array(), *eps_zz = column(NAME_ZZ);
  const int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    const double *s = stress[i];
    const McaMaterial &m = scaled[type[i]];
    const double zz = plane_strain ? out_of_plane(i, m, s[0], s[1]) : s[2];
    const double mean = (s[0] + s[1] + zz) / 3.0;
    out[i][0] = 1.0;
    // the pairs return about their own weighted mean (mca_element_stress.h), not Love's,
    // which weighs them by their arms
    out[i][1] = s[McaElementStress::MEAN_WEIGHT] > 0.0
        ? s[McaElementStress::MEAN_SUM] / s[McaElementStress::MEAN_WEIGHT]
        : mean;
    if (m.yield == 0.0) continue;
    const double dxx = s[0] - mean, dyy = s[1] - mean, dzz = zz - mean;
    const double sint = sqrt(1.5 * (dxx * dxx + dyy * dyy + dzz * dzz +
                                    2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
    const double yield_now = m.yield + m.hardening * eps_p[i];
    if (sint <= yield_now) continue;
    const double deps = (sint - yield_now) / (3.0 * m.shear + m.hardening);
    eps_p[i] += deps;
    if (plane_strain) eps_zz[i] += 1.5 * deps * dzz / sint;
    out[i][0] = (yield_now + m.hardening * deps) / sint;
  }
  exchange.to_ghosts(returned, COLUMNS);
}
