/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute pair/params.

   The characteristic parameters of the law of one type pair (Krivtsov):
   a, b, sigma, D, f*, C, eps*, k*, kv, k2, Gamma, and with the particle
   mass omega0, T0, v0 = c0, vd, B*, the dusting criteria and the lattice
   sound speed; a table of the shock-stiffened sound speed c(u).
   Definitions: doc/compute_pair_params.rst.  Evaluated once per run.
------------------------------------------------------------------------- */

#include "compute_pair_params.h"

#include "arg_values.h"
#include "keyword_set.h"

#include "law_probe.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "pair.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

static constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
static constexpr int NCOLS = 6;

// the whole of str is a number as strtod reads it (nan and inf included)
static bool is_number(const char *str)
{
  char *end;
  strtod(str, &end);
  return end != str && *end == '\0';
}

ComputePairParams::ComputePairParams(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), mass_user(0.0), rc_user(0.0), lambda(0.0), fresh(0)
{
  if (narg < 5)
    error->all(FLERR, "Compute pair/params: expected compute ID group pair/params I J "
               "[mass m] [rc Rc] [lattice chain|tri|fcc] [u u1 u2 ...]");
  if (!domain->box_exist)
    error->all(FLERR, "Compute pair/params: the box must exist (its atom types are I and J)");
  itype = (int) integer_arg("Compute pair/params", "type I", arg[3], lmp);
  jtype = (int) integer_arg("Compute pair/params", "type J", arg[4], lmp);
  for (int t : {itype, jtype})
    if (t < 1 || t > atom->ntypes)
      error->all(FLERR, "Compute pair/params: atom type {} is out of range 1-{}", t, atom->ntypes);

  KeywordSet given(lmp, "Compute pair/params", Keywords::PAIR_PARAMS);

  for (int iarg = 5; iarg < narg;) {
    const std::string key = arg[iarg];
    given.add(key);
    if (key != "u" && iarg + 1 >= narg)
      error->all(FLERR, "Compute pair/params: keyword {} needs a value", key);
    if (key == "mass") {
      mass_user = positive_arg("Compute pair/params", "mass", arg[iarg + 1], lmp);
      iarg += 2;
    } else if (key == "rc") {
      rc_user = positive_arg("Compute pair/params", "rc", arg[iarg + 1], lmp);
      if (!(rc_user > 1.0))
        error->all(FLERR, "Compute pair/params: rc must be > 1 in units of a (got {}): the bond "
                   "would never hold", arg[iarg + 1]);
      iarg += 2;
    } else if (key == "lattice") {
      const std::string name = arg[iarg + 1];
      if (name == "chain") lambda = 1.0;
      else if (name == "tri") lambda = 1.06;
      else if (name == "fcc") lambda = 1.10;
      else
        error->all(FLERR, "Compute pair/params: unknown lattice '{}' (expected chain, tri or fcc)",
                   name);
      iarg += 2;
    } else {    // u: the numbers up to the next keyword; nan and inf are numbers, refused
      for (iarg++; iarg < narg && is_number(arg[iarg]); iarg++) {
        const double u = strtod(arg[iarg], nullptr);
        if (!(u > 0.0) || !std::isfinite(u))
          error->all(FLERR, "Compute pair/params: loading speed u must be a finite number > 0 "
                     "(got {})", arg[iarg]);
        speeds.push_back(u);
      }
      if (speeds.empty())
        error->all(FLERR, "Compute pair/params: keyword u needs at least one speed (got {})",
                   iarg < narg ? fmt::format("'{}'", arg[iarg]) : std::string("nothing"));
    }
  }

  vector_flag = 1;
  size_vector = NVALUES;
  extvector = 0;
  vector = new double[NVALUES];
  if (!speeds.empty()) {
    array_flag = 1;
    size_array_rows = speeds.size();
    size_array_cols = NCOLS;
    extarray = 0;
    memory->create(array, size_array_rows, NCOLS, "pair/params:array");
  }
}

ComputePairParams::~ComputePairParams()
{
  delete[] vector;
  memory->destroy(array);
}

void ComputePairParams::init()
{
  if (!force->pair) error->all(FLERR, "Compute pair/params needs a pair style");
  if (!force->pair->single_enable && !dynamic_cast<LawSource *>(force->pair))
    error->all(FLERR, "Compute pair/params: pair style {} has no single() to evaluate its law",
               force->pair_style);
  if (!(force->pair->cutsq[itype][jtype] > 0.0))
    error->all(FLERR, "Compute pair/params: pair style {} has no interaction for types {} {}",
               force->pair_style, itype, jtype);
  if (mass_user == 0.0 && !atom->mass)
    error->all(FLERR, "Compute pair/params: atoms have per-atom masses: give the mass keyword");
  fresh = 0;    // the law may have changed since the last run
}

void ComputePairParams::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (!fresh) evaluate();
}

void ComputePairParams::compute_array()
{
  invoked_array = update->ntimestep;
  if (!fresh) evaluate();
}

/* ---------------------------------------------------------------------- */

void ComputePairParams::evaluate()
{
  fresh = 1;
  Pair *pair = force->pair;
  const double cut = sqrt(pair->cutsq[itype][jtype]);
  auto *source = dynamic_cast<LawSource *>(pair);

  // the law as the pair style computes it; the base (no tail) beyond the cutoff
  // where this package's styles can give it
  std::unique_ptr<LawProbe> probe, base;
  if (source) {
    probe.reset(new AnalyticProbe(source, itype, jtype, true));
    base.reset(new AnalyticProbe(source, itype, jtype, false));
  }

  // equilibrium distance a: the first change of sign of f from repulsion to attraction

  double a;
  const int ngrid = 500;    // scan to bracket a, b and sigma; then bisection or golden section
  const double rlo = 0.05 * cut;    // where the law is probed from
  if (source) a = source->law_a(itype, jtype);
  else {
    SingleProbe coarse(pair, itype, jtype, 0.0);
    a = 0.0;
    for (int k = 1; k < ngrid && a == 0.0; k++) {
      const double r0 = rlo + (cut - rlo) * (k - 1) / ngrid, r1 = rlo + (cut - rlo) * k / ngrid;
      if (coarse.force(r0) > 0.0 && coarse.force(r1) <= 0.0)
        a = bisect([&](double r) { return coarse.force(r); }, r0, r1);
    }
    if (a == 0.0)
      error->all(FLERR, "Compute pair/params: no minimum of the law for types {} {} inside the "
                 "cutoff {} (purely repulsive or attractive?)", itype, jtype, cut);
    probe.reset(new SingleProbe(pair, itype, jtype, 1e-4 * a));
  }

  // inflection point b: where the attraction is strongest

  double b = NaN;
  if (source) {
    b = source->law_b(itype, jtype);
    if (b == 0.0) b = NaN;
  } else {
    int kmin = -1;
    double fmin = 0.0;
    for (int k = 0; k <= ngrid; k++) {
      const double r = a + (cut - a) * k / ngrid * (1.0 - 1e-12);
      const double f = probe->force(r);
      if (f < fmin) {
        fmin = f;
        kmin = k;
      }
    }
    if (kmin > 0 && kmin < ngrid)
      b = golden_min([&](double r) { return probe->force(r); },
                     a + (cut - a) * (kmin - 1) / ngrid, a + (cut - a) * (kmin + 1) / ngrid);
    else
      error->warning(FLERR, "Compute pair/params: the attraction of types {} {} is strongest at "
                     "the cutoff: no inflection point b inside it (b, f*, eps*, k* are NaN)",
                     itype, jtype);
  }

  // sigma: Pi(sigma) = 0 below a

  double sigma = NaN;
  for (int k = 1; k < ngrid; k++) {
    const double r1 = a - (a - rlo) * (k - 1) / ngrid, r0 = a - (a - rlo) * k / ngrid;
    if (probe->energy(r0) > 0.0 && probe->energy(r1) <= 0.0) {
      sigma = bisect([&](double r) { return probe->energy(r); }, r0, r1);
      break;
    }
  }

  LawProbe &at_b = (source && b >= cut) ? *base : *probe;
  const double d = -probe->energy(a);
  const double fstar = std::isnan(b) ? NaN : fabs(at_b.force(b));
  const double c = probe->d2(a);
  // a pair style computes nothing at or beyond its cutoff: Pi(2a) = 0 there
  const double e2a = 2.0 * a < cut ? probe->energy(2.0 * a) : 0.0;
  // with LAMMPS's unit conversions: acceleration = ftm2v force/mass, kinetic energy =
  // mvv2e m v^2 / 2, a damping force B v of fix viscous is in force units
  const double m = mass_user > 0.0 ? mass_user : atom->mass[itype];
  const double rc = rc_user > 0.0 ? rc_user : cut / a;
  const double omega0 = sqrt(force->ftm2v * c / m);
  const double v0 = a * omega0;

  double *v = vector;
  v[0] = a;
  v[1] = b;
  v[2] = sigma;
  v[3] = d;
  v[4] = fstar;
  v[5] = c;
  v[6] = b / a - 1.0;
  v[7] = c * (b - a) / fstar;
  v[8] = a * sqrt(c / (2.0 * d));
  v[9] = e2a == 0.0 ? std::numeric_limits<double>::infinity() : -d / e2a;
  v[10] = -a * probe->d3(a) / (2.0 * c);
  v[11] = omega0;
  v[12] = 2.0 * M_PI / omega0;
  v[13] = v0;
  v[14] = sqrt(2.0 * d / (m * force->mvv2e));
  v[15] = 2.0 * sqrt(m * c / force->ftm2v);
  v[16] = rc;
  v[17] = 1.35 * (rc - 1.0) * v0;
  v[18] = (rc - 1.0) * v0 / (2.0 * M_SQRT2);
  v[19] = lambda * v0;
  // vd of the base law's depth, before a tail or shift (the papers' vd); a stock style's law
  // is known only as it computes it
  const double d0 = source ? -base->energy(a) : d;
  v[20] = sqrt(2.0 * d0 / (m * force->mvv2e));

  if (!speeds.empty()) shock_table(*probe, a, c);
}

/* ----------------------------------------------------------------------
   compression y behind a shock of particle speed u: y + (u/c0) / sqrt(Pi''(ya)/C) = 1,
   the first root below y = 1 (scan in steps of 0.005, then bisection)
------------------------------------------------------------------------- */

void ComputePairParams::shock_table(LawProbe &probe, double a, double c)
{
  const double c0 = vector[13];
  for (size_t k = 0; k < speeds.size(); k++) {
    const double u = speeds[k];
    auto g = [&](double y) {
      const double s = probe.d2(y * a);
      return s > 0.0 ? y + (u / c0) / sqrt(s / c) - 1.0 : -1.0;
    };
    double y = NaN;
    for (double hi = 1.0; hi > 0.01; hi -= 0.005) {
      const double lo = hi - 0.005;
      const double glo = g(lo);
      if (std::isfinite(glo) && glo <= 0.0) {
        y = bisect(g, lo, hi);
        break;
      }
    }
    array[k][0] = u;
    if (std::isnan(y)) {
      error->warning(FLERR, "Compute pair/params: no steady compression for u = {} (the law does "
                     "not stiffen enough): row {} is NaN after u", u, k + 1);
      for (int col = 1; col < NCOLS; col++) array[k][col] = NaN;
      continue;
    }
    const double cu = c0 * sqrt(probe.d2(y * a) / c);
    array[k][1] = y;
    array[k][2] = cu / c0;
    array[k][3] = cu;
    array[k][4] = M_PI * a / cu;
    array[k][5] = array[k][4] / 20.0;
  }
}
