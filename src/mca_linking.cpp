/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the links pair_style mca makes at a
   setup (see mca_linking.h).
------------------------------------------------------------------------- */

#include "mca_linking.h"

#include "mca_element.h"
#include "mca_pair_walk.h"

#include "atom.h"
#include "domain.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

using C = McaContact;

McaLinking::~McaLinking()
{
  memory->destroy(zcount);
}

void McaLinking::make(const NeighList *list, const StatePass &pass, const McaTypeTable &types,
                      double tolerance, double fraction)
{
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton = force->newton_pair;
  const double reach = 1.0 + tolerance;
  double deep = 0.0;    // pairs linked closer than half their contact distance
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(zcount);
    memory->create(zcount, nmax, 1, "pair:zcount");
  }
  for (int i = 0; i < nall; i++) zcount[i][0] = 0.0;

  walk_pairs(list, pass, [&](int i, int j, int jj) {
    int &word = pass.words[i][jj];
    if (!pass.fresh[i] || !pass.fresh[j]) {
      const McaPairFrame p(atom->x, i, j);
      const double r = sqrt(p.rsq);
      if (r == 0.0) coincident_elements(lmp, i, j);
      const double rsum = radius[i] + radius[j];
      word = r < reach * rsum && types.model(type[i], type[j]).links ? 1 : 0;
      if (word && r < 0.5 * rsum) deep += newton || j < nlocal ? 1.0 : 0.5;
      // a pair left unlinked keeps no doubles (a contact claims its own)
      double *v = word ? pass.claim(i, jj) : pass.pair_values(i, jj);
      if (v) {
        for (int k = 0; k < C::NVALUES; k++) v[k] = 0.0;
        v[C::REF] = r;
        for (int k = 0; k < 3; k++) v[C::DPREV + k] = p.d[k];
      }
    }
    if (state_now(word)) {
      zcount[i][0] += 1.0;
      if (newton || j < nlocal) zcount[j][0] += 1.0;
    }
  });
  double deep_all;
  MPI_Allreduce(&deep, &deep_all, 1, MPI_DOUBLE, MPI_SUM, world);
  if (deep_all > 0.0 && comm->me == 0)
    error->warning(FLERR, "Pair mca: {:.0f} pairs linked closer than half their contact distance "
                   "R_i + R_j (overlapping elements): they are linked stress free where they are",
                   deep_all);
  exchange.to_owners(zcount, 1);
  exchange.to_ghosts(zcount, 1);
  areas(list, pass, fraction);
  memory->destroy(zcount);    // needed again only at the next setup that links
  nmax = 0;
}

void McaLinking::areas(const NeighList *list, const StatePass &pass, double fraction)
{
  const double *radius = atom->radius;
  walk_pairs(list, pass, [&](int i, int j, int jj) {
    if (!state_now(pass.words[i][jj])) return;
    double *v = pass.pair_values(i, jj);
    if (v[C::AREA] != 0.0) return;
    const int dim = domain->dimension;
    const double si = McaElement::area_share(McaElement::volume(radius[i], fraction, dim),
                                             zcount[i][0], radius[i], dim);
    const double sj = McaElement::area_share(McaElement::volume(radius[j], fraction, dim),
                                             zcount[j][0], radius[j], dim);
    v[C::AREA] = 0.5 * (si + sj);
  });
}
