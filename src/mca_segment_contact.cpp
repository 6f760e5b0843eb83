/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: contact segments of pair_style mca
   (see mca_segment_contact.h).
------------------------------------------------------------------------- */

#include "mca_segment_contact.h"

#include "arg_values.h"
#include "keyword_set.h"
#include "mca_contact.h"
#include "mca_element.h"
#include "mca_pair_tally.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "utils.h"

#include <cmath>
#include <cstring>
#include <string>
#include <utility>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

void McaSegmentContact::allocate(int n)
{
  ntypes = n;
  any = false;
  side.assign((n + 1) * (n + 1), 0);
  given.assign((n + 1) * (n + 1), Given());
  law.assign((n + 1) * (n + 1), McaSegmentLaw());
  rough.assign((n + 1) * (n + 1), McaRoughness());
}

void McaSegmentContact::refuse_link(char **arg) const
{
  const std::string who = "Pair mca pair_coeff";
  int ilo, ihi, jlo, jhi;
  type_range(who, "I", arg[0], ntypes, ilo, ihi, lmp);
  type_range(who, "J", arg[1], ntypes, jlo, jhi, lmp);
  for (int i = ilo; i <= ihi; i++)
    for (int j = jlo; j <= jhi; j++)
      if (i != j && between(i, j))
        error->all(FLERR, "{}: types {} and {} meet by contact segments (pair_coeff {} {} "
                   "segments): they never link, link does not apply", who, i, j, MIN(i, j),
                   MAX(i, j));
}

/* ----------------------------------------------------------------------
   pair_coeff I J segments mu0 [viscous eta0] [limit sigma0]
              [roughness A1 l1 d1 A2 l2 d2 seed]
------------------------------------------------------------------------- */

void McaSegmentContact::coeff(int narg, char **arg)
{
  const std::string who = "Pair mca pair_coeff segments";
  int ilo, ihi, jlo, jhi;
  type_range(who, "I", arg[0], ntypes, ilo, ihi, lmp);
  type_range(who, "J", arg[1], ntypes, jlo, jhi, lmp);
  if (narg < 4) error->all(FLERR, "{}: expected pair_coeff I J segments mu0 [...]", who);
  Given g;
  g.mu0 = number_arg(who, "mu0 (dry friction coefficient)", arg[3], lmp);
  if (g.mu0 < 0.0 || g.mu0 > 1.0e6)
    error->all(FLERR, "{}: mu0 (dry friction coefficient) must lie in 0 to 1e6 (got {})", who,
               arg[3]);
  KeywordSet seen(lmp, who, Keywords::MCA_SEGMENTS);
  for (int i = 4; i < narg;) {
    const std::string key = arg[i];
    const int count = seen.add(key).values;
    if (i + count >= narg)
      error->all(FLERR, "{}: {} needs {} value{}", who, key, count, count > 1 ? "s" : "");
    if (key == "viscous") {
      g.eta0 = number_arg(who, "viscous (eta0)", arg[i + 1], lmp);
      if (g.eta0 < 0.0)
        error->all(FLERR, "{}: viscous (eta0) must be >= 0 (got {})", who, arg[i + 1]);
    } else if (key == "limit") {
      g.sigma0 = positive_arg(who, "limit (sigma0, the junctions' elastic limit)", arg[i + 1], lmp);
    } else {
      const char *names[3] = {"amplitude", "half-period", "regularity"};
      for (int m = 0; m < 2; m++) {
        McaRoughness::Wave &w = g.waves[m];
        double *v[3] = {&w.amplitude, &w.half_period, &w.regularity};
        for (int k = 0; k < 3; k++) {
          const std::string name = fmt::format("roughness {} {}", names[k], m + 1);
          *v[k] = k == 0 ? number_arg(who, name.c_str(), arg[i + 1 + 3 * m + k], lmp)
                         : positive_arg(who, name.c_str(), arg[i + 1 + 3 * m + k], lmp);
        }
        if (w.amplitude < 0.0)
          error->all(FLERR, "{}: roughness amplitude {} must be >= 0 (got {})", who, m + 1,
                     arg[i + 1 + 3 * m]);
        if (w.regularity < 2.0 * w.half_period)
          error->all(FLERR, "{}: roughness regularity {} ({}) must be at least its period, twice "
                     "the half-period {}: a regular piece holds whole periods", who, m + 1,
                     arg[i + 3 + 3 * m], arg[i + 2 + 3 * m]);
      }
      if (1.5 * (g.waves[0].amplitude + g.waves[1].amplitude) >= 1.0)
        error->all(FLERR, "{}: roughness amplitudes A1 + A2 must stay below 2/3 (got {} + {}): "
                   "a piece's amplitude reaches 3/2 of A, and K_mu must stay above zero", who,
                   arg[i + 1], arg[i + 4]);
      const double seed = integer_arg(who, "roughness seed", arg[i + 7], lmp);
      if (seed < 1 || seed > 2147483646)
        error->all(FLERR, "{}: roughness seed must be an integer from 1 to 2147483646 (got {})",
                   who, arg[i + 7]);
      g.seed = static_cast<int>(seed);
    }
    i += 1 + count;
  }
  for (int i = ilo; i <= ihi; i++)
    for (int j = jlo; j <= jhi; j++) {
      if (i == j)
        error->all(FLERR, "{}: the surface (I) and the elements on it (J) are two types (got "
                   "type {} for both)", who, i);
      side[index(i, j)] = 1;
      given[index(i, j)] = g;
    }
  any = true;
}

double *McaSegmentContact::dvector(const char *name) const
{
  int flag, cols;
  const int index = atom->find_custom(name, flag, cols);
  return index < 0 || flag != 1 || cols != 0 ? nullptr : atom->dvector[index];
}

int *McaSegmentContact::set_flags() const
{
  int flag, cols;
  const int index = atom->find_custom("mca_x0_set", flag, cols);
  return index < 0 || flag != 0 || cols != 0 ? nullptr : atom->ivector[index];
}

double McaSegmentContact::reference_x(int i, int j, double t, const double *x0,
                                      const int *set) const
{
  double **x = atom->x;
  const double xi = set[i] ? x0[i] : x[i][0], xj = set[j] ? x0[j] : x[j][0];
  double d = xj - xi;
  if (domain->xperiodic) d -= domain->xprd * floor(d / domain->xprd + 0.5);
  return xi + t * d;
}

void McaSegmentContact::init()
{
  if (!any) return;
  if (domain->dimension != 2)
    error->all(FLERR, "Pair mca: contact segments (pair_coeff ... segments) are two-dimensional: "
               "in 3d the unlinked pairs' contact acts (doc: Contact segments)");
  if (!force->newton_pair)
    error->all(FLERR, "Pair mca: contact segments need newton on (a segment's forces on ghost "
               "elements are summed onto their owners)");
  if (!modify->get_fix_by_id(FIX_ID)) {
    Fix *fix = modify->add_fix(fmt::format("{} all property/atom d_mca_slip d_mca_x0 "
                                           "i_mca_x0_set ghost yes", FIX_ID));
    fix->wd_section = 0;    // as the pair states: out of data files
  }
  if (!dvector("mca_slip") || !dvector("mca_x0") || !set_flags())
    error->all(FLERR, "Pair mca: fix {} is not the elements' tangential springs and reference "
               "positions (fix property/atom d_mca_slip d_mca_x0 i_mca_x0_set) the style makes: "
               "its ID is reserved", FIX_ID);
  // the elements met for the first time: their reference x (ghosts take it at the setup)
  double *x0 = dvector("mca_x0");
  int *set = set_flags();
  for (int i = 0; i < atom->nlocal; i++)
    if (!set[i]) {
      double unwrapped[3];
      domain->unmap(atom->x[i], atom->image[i], unwrapped);
      x0[i] = unwrapped[0];
      set[i] = 1;
    }
  const double p2e = 1.0 / force->nktv2p;
  for (int i = 1; i <= ntypes; i++)
    for (int j = 1; j <= ntypes; j++) {
      if (!side[index(i, j)]) continue;
      const Given &g = given[index(i, j)];
      law[index(i, j)] = McaSegmentLaw{g.mu0, g.eta0 * p2e, g.sigma0 * p2e};
      rough[index(i, j)] = g.seed ? McaRoughness(g.waves, g.seed, domain->boxlo[0], domain->xprd)
                                  : McaRoughness();
    }
}

double McaSegmentContact::cutoff(int it, int jt, double ri, double rj, double tolerance) const
{
  // k of type jt reaches the far end of its nearest segment (two elements of type it)
  const auto reach = [&](double rs, double rk) {
    return 0.5 * sqrt(3.0) * (rk + rs) + 2.0 * (1.0 + tolerance) * rs;
  };
  double cut = 0.0;
  if (side[index(it, jt)]) cut = reach(ri, rj);
  if (side[index(jt, it)]) cut = fmax(cut, reach(rj, ri));
  return cut;
}

/* ----------------------------------------------------------------------
   every owned element k of a point type: its nearest point on the
   polyline of the surface elements in its list, the normal force and the
   friction there, shared by the segment's ends
------------------------------------------------------------------------- */

void McaSegmentContact::compute(const NeighList *full, const double *stiffness, double tolerance,
                                bool moving, double dt, StateTally &changes, Pair &pair,
                                McaElementStress *love)
{
  double **x = atom->x, **v = atom->v, **omega = atom->omega, **f = atom->f;
  double **torque = atom->torque;
  const double *radius = atom->radius;
  const int *type = atom->type;
  double *xi = dvector("mca_slip");
  const double *x0 = dvector("mca_x0");
  const int *x0_set = set_flags();
  std::vector<int> near;
  for (int ii = 0; ii < full->inum; ii++) {
    const int k = full->ilist[ii];
    const int kt = type[k];
    near.clear();
    const int *jlist = full->firstneigh[k];
    for (int jj = 0; jj < full->numneigh[k]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (side[index(type[j], kt)]) near.push_back(j);
    }
    if (near.empty()) {
      xi[k] = 0.0;
      continue;
    }
    // the nearest point of the polyline: a segment of two elements in contact, or a lone end
    int bi = -1, bj = -1;
    McaSegmentLaw::Foot best;
    best.h = INFINITY;
    const auto consider = [&](int a, int b) {
      const McaSegmentLaw::Foot foot = McaSegmentLaw::nearest(x[a], x[b], x[k]);
      if (foot.h < best.h) {
        best = foot;
        bi = a;
        bj = b;
      }
    };
    for (size_t m = 0; m < near.size(); m++) {
      const int a = near[m];
      consider(a, a);
      for (size_t l = m + 1; l < near.size(); l++) {
        const int b = near[l];
        const double dx = x[b][0] - x[a][0], dy = x[b][1] - x[a][1];
        const double touch = (1.0 + tolerance) * (radius[a] + radius[b]);
        if (dx * dx + dy * dy < touch * touch) consider(a, b);
      }
    }
    const double t = best.t, h = best.h, rk = radius[k];
    const double rs = (1.0 - t) * radius[bi] + t * radius[bj];
    const double h0 = McaSegmentLaw::rest_height(rk, radius[bi], radius[bj], t);
    if (h == 0.0)
      error->one(FLERR, "Pair mca: element {} of type {} lies on the polyline of the surface's "
                 "elements {} and {} (height 0): its contact has no normal; place it above the "
                 "surface", atom->tag[k], kt, atom->tag[bi], atom->tag[bj]);
    if (h >= h0) {
      xi[k] = 0.0;
      continue;
    }
    // a segment of two surface types: each law parameter and K_mu interpolated along it
    const int ai = index(type[bi], kt), aj = index(type[bj], kt);
    const McaSegmentLaw sl = McaSegmentLaw::between(law[ai], law[aj], t);
    const double s = McaElement::unlinked_area(rk, rs, 2);
    const double a =
        McaPairHalves(stiffness[k], (1.0 - t) * stiffness[bi] + t * stiffness[bj]).series();
    double enormal, espring = 0.0, work = 0.0;
    const double kn = 1.5 * s * a;
    const double fn = McaSegmentLaw::normal(kn, h0, h, enormal);
    const double *n = best.n, *e = best.e;
    double vrel[2];
    for (int c = 0; c < 2; c++) vrel[c] = v[k][c] - (1.0 - t) * v[bi][c] - t * v[bj][c];
    if (h < 0.5 * h0) refuse_passage(k, bi, bj, h, h0, kn, -(n[0] * vrel[0] + n[1] * vrel[1]));
    const double wseg = (1.0 - t) * omega[bi][2] + t * omega[bj][2];
    const double vt = e[0] * vrel[0] + e[1] * vrel[1] - rk * omega[k][2] - (h - rk) * wseg;
    const double xref = reference_x(bi, bj, t, x0, x0_set);
    const double kmu = ai == aj ? rough[ai].mean(xref, s)
                                : (1.0 - t) * rough[ai].mean(xref, s) + t * rough[aj].mean(xref, s);
    const double limit = sl.dry_limit(fn, kmu, s);
    double ft;
    if (moving) {
      ft = sl.friction(xi[k], vt, dt, s * a, limit, s, work, espring);
      changes.work[WORK_FRICTION] += work;
    } else {
      ft = -s * a * xi[k];
      espring = 0.5 * s * a * xi[k] * xi[k];
    }
    double fk[3] = {fn * n[0] + ft * e[0], fn * n[1] + ft * e[1], 0.0};
    double fj[3] = {-t * fk[0], -t * fk[1], 0.0};
    for (int c = 0; c < 2; c++) {
      f[k][c] += fk[c];
      f[bi][c] -= (1.0 - t) * fk[c];
      f[bj][c] += fj[c];
    }
    torque[k][2] -= rk * ft;
    torque[bi][2] -= (1.0 - t) * (h - rk) * ft;
    torque[bj][2] -= t * (h - rk) * ft;
    if (love) {
      const double c[3] = {x[k][0] - rk * n[0], x[k][1] - rk * n[1], x[k][2]};
      const double fi[3] = {-(1.0 - t) * fk[0], -(1.0 - t) * fk[1], 0.0};
      const int who[3] = {k, bi, bj};
      const double *force[3] = {fk, bi == bj ? fk : fi, fj};
      for (int m = 0; m < (bi == bj ? 2 : 3); m++) {
        const int e = who[m];
        double arm[3] = {c[0] - x[e][0], c[1] - x[e][1], 0.0}, f3[3], sym[6];
        for (int q = 0; q < 3; q++) f3[q] = (bi == bj && m == 1) ? -force[m][q] : force[m][q];
        McaElement::dyad(arm, f3, sym);
        love->add(e, 1.0, sym, 0);
      }
    }
    if (pair.evflag) {
      double dji[3] = {x[bj][0] - x[bi][0], x[bj][1] - x[bi][1], 0.0};
      double dki[3] = {x[k][0] - x[bi][0], x[k][1] - x[bi][1], 0.0};
      if (bi == bj) fj[0] = fj[1] = 0.0;    // a lone end: all on it
      pair.ev_tally3(bi, bj, k, enormal + espring, 0.0, fj, fk, dji, dki);
    }
  }
}

/* ----------------------------------------------------------------------
   k below half its rest height: the linear contact k_n (h0 - h) stores
   k_n h0^2 / 8 there, so it is going through the surface, whose far side
   would push it on (h is a distance, n turns over)
------------------------------------------------------------------------- */

void McaSegmentContact::refuse_passage(int k, int bi, int bj, double h, double h0, double kn,
                                       double closing) const
{
  const double stop = 0.5 * h0 * sqrt(kn / (atom->rmass[k] * force->mvv2e));
  error->one(FLERR, "Pair mca: element {} of type {} is {:.4g} from the polyline of the "
             "surface's elements {} and {}, below half its rest height {:.4g}, closing at {:.4g}: "
             "it is going through the surface.  The contact (normal stiffness 3/2 S a = {:.4g}) "
             "stops this element only below a closing speed of {:.4g} (velocity units); "
             "lower the impact speed, or the time step where one step carries it that far "
             "(doc: Contact segments and micro-roughness)", atom->tag[k], atom->type[k], h, atom->tag[bi],
             atom->tag[bj], h0, closing, kn, stop);
}

/* ---------------------------------------------------------------------- */

void McaSegmentContact::pack(const Given &g, double *v)
{
  const double out[NGIVEN] = {g.mu0,
                              g.eta0,
                              g.sigma0,
                              g.waves[0].amplitude,
                              g.waves[0].half_period,
                              g.waves[0].regularity,
                              g.waves[1].amplitude,
                              g.waves[1].half_period,
                              g.waves[1].regularity,
                              static_cast<double>(g.seed)};
  memcpy(v, out, sizeof(out));
}

void McaSegmentContact::unpack(const double *v, Given &g)
{
  g.mu0 = v[0];
  g.eta0 = v[1];
  g.sigma0 = v[2];
  for (int m = 0; m < 2; m++) {
    g.waves[m].amplitude = v[3 + 3 * m];
    g.waves[m].half_period = v[4 + 3 * m];
    g.waves[m].regularity = v[5 + 3 * m];
  }
  g.seed = static_cast<int>(v[9]);
}

void McaSegmentContact::write_restart(FILE *fp) const
{
  fwrite(side.data(), sizeof(int), side.size(), fp);
  for (const Given &g : given) {
    double v[NGIVEN];
    pack(g, v);
    fwrite(v, sizeof(double), NGIVEN, fp);
  }
}

void McaSegmentContact::read_restart(FILE *fp)
{
  if (comm->me == 0)
    utils::sfread(FLERR, side.data(), sizeof(int), side.size(), fp, nullptr, error);
  MPI_Bcast(side.data(), side.size(), MPI_INT, 0, world);
  for (Given &g : given) {
    double v[NGIVEN];
    if (comm->me == 0) utils::sfread(FLERR, v, sizeof(double), NGIVEN, fp, nullptr, error);
    MPI_Bcast(v, NGIVEN, MPI_DOUBLE, 0, world);
    unpack(v, g);
  }
  any = false;
  for (const int s : side)
    if (s) any = true;
}

bool McaSegmentContact::write_data_line(FILE *fp, int i, int j) const
{
  if (!side[index(i, j)]) {
    if (!side[index(j, i)]) return false;
    std::swap(i, j);
  }
  const Given &g = given[index(i, j)];
  fmt::print(fp, "{} {} segments {}", i, j, g.mu0);
  if (g.eta0 > 0.0) fmt::print(fp, " viscous {}", g.eta0);
  if (g.sigma0 > 0.0) fmt::print(fp, " limit {}", g.sigma0);
  if (g.seed)
    fmt::print(fp, " roughness {} {} {} {} {} {} {}", g.waves[0].amplitude, g.waves[0].half_period,
               g.waves[0].regularity, g.waves[1].amplitude, g.waves[1].half_period,
               g.waves[1].regularity, g.seed);
  fmt::print(fp, "\n");
  return true;
}
