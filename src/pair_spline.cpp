/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair styles morse/spline, lj/spline,
   mie/spline, harmonic/spline.  See pair_spline.h and doc/pair_spline.rst.
------------------------------------------------------------------------- */

#include "pair_spline.h"

#include "pair_spline_kernel.h"
#include "skin_check.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;
using MathConst::MY_PI;

static constexpr double BIG = 1.0e300;

template <class Law>
PairSpline<Law>::PairSpline(LAMMPS *lmp) :
    Pair(lmp), state(lmp, this, std::string("Pair style ") + Law::style, 0)
{
  writedata = 1;
  born_matrix_enable = 1;
  tail = CUT;
  rc_global = rs_global = 0.0;
  d0 = a0 = p0 = q0 = kappa = rc_pair = rs_pair = cut = stiffness = nullptr;
  coeffs = nullptr;
  kappa_any = 0;
  chain_n = 0;
  step_warned = 0;
  step_next_check = 0;
  beyond_contact = 1;    // fix neigh/history keeps every listed pair's flag, not only contacts
}

template <class Law> PairSpline<Law>::~PairSpline()
{
  if (copymode) return;
  delete[] pvector;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(cut);
    memory->destroy(d0);
    memory->destroy(a0);
    memory->destroy(p0);
    memory->destroy(q0);
    memory->destroy(kappa);
    memory->destroy(rc_pair);
    memory->destroy(rs_pair);
    memory->destroy(stiffness);
    delete[] coeffs;
  }
}

/* ---------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const StatePass pass = links.on() ? state.begin() : StatePass();
  StateTally changes;
  dispatch(eflag, [&](auto t, auto mode, auto ev, auto e, auto n) {
    eval<decltype(t), decltype(mode)::value, decltype(ev)::value, decltype(e)::value,
         decltype(n)::value>(0, list->inum, (xyz3 *) atom->f[0], pass, changes,
                             [this](int i, int j, int nlocal, int newton, double evdwl,
                                    double fpair, double dx, double dy, double dz) {
                               ev_tally(i, j, nlocal, newton, evdwl, 0.0, fpair, dx, dy, dz);
                             });
  });
  if (vflag_fdotr) virial_fdotr_compute();
  finish_compute(changes);
}

// after the kernel, serial and /omp: the link tally, the time-step check
template <class Law> void PairSpline<Law>::finish_compute(const StateTally &changes)
{
  if (links.on()) state.end(changes, pvector);
  if (neighbor->ago == 0) check_time_step();
}

template <class Law> void PairSpline<Law>::singular_error(int i, int j, double rsq) const
{
  const SplineCoeff &c = pair_coeff(atom->type[i], atom->type[j]);
  error->one(FLERR,
             "Pair {}: atoms {} and {} are {:.8g} apart, at or inside the distance {:.8g} where "
             "their law (types {} {}) is singular (a (1 - 1/kappa) for kappa > 1, else 0): "
             "reduce the time step or kappa",
             Law::style, atom->tag[i], atom->tag[j], sqrt(rsq), sqrt(c.hardsq), atom->type[i],
             atom->type[j]);
  std::abort();    // not reached: error->one() throws
}

/* ----------------------------------------------------------------------
   warn once when the time step exceeds what compute pair/params suggests for
   the deepest compression present: T_min/20 with T_min = pi / sqrt(ftm2v Pi''(r)/m)
   at the closest pair of each type pair (the law's argument r/n in a chain),
   Pi'' at least C, m the smaller mass.  Called on steps that rebuilt the list,
   at every run's setup and then at most every STEP_CHECK_EVERY steps.
------------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::check_time_step()
{
  if (step_warned || update->whichflag != 1) return;
  if (!update->setupflag && update->ntimestep < step_next_check) return;
  step_next_check = update->ntimestep + STEP_CHECK_EVERY;
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
      if (rsq < pair_coeff(type[i], type[j]).cutsq && rsq < rmin) rmin = rsq;
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
      law_derivs(i, j, r, d, true);
      const double m = atom->rmass ? mass_min : MIN(atom->mass[i], atom->mass[j]);
      const double k = MAX(d[2], stiffness[i][j]);
      mine[0] = MIN(mine[0], MY_PI / (20.0 * sqrt(force->ftm2v * k / m)));
      mine[1] = MIN(mine[1], r / pair_coeff(i, j).a);
    }
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_MIN, world);
  if (update->dt > all[0]) {
    step_warned = 1;
    if (comm->me == 0)
      error->warning(FLERR, "Pair {}: time step {:.4g} exceeds {:.4g}, the step compute "
                     "pair/params suggests (T_min/20) for the compression present at step {} "
                     "(closest pair at {:.4g} a): the run may be inaccurate or unstable; reduce "
                     "the time step", Law::style, update->dt, all[0], update->ntimestep, all[1]);
  }
}

/* ----------------------------------------------------------------------
   LAMMPS's default skin is a fixed length per unit style (units si: 1 mm);
   at cluster scale it is 100 particle sizes, and binning then fails
------------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::check_skin() const
{
  double cutmax = 0.0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j]) cutmax = MAX(cutmax, pair_coeff(i, j).rc * (chain_n ? chain_n : 1));
  check_neighbor_skin(lmp, cutmax, fmt::format("Pair {}", Law::style));
}

/* ---------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::allocate()
{
  allocated = 1;
  const int np1 = atom->ntypes + 1;
  memory->create(setflag, np1, np1, "pair:setflag");
  for (int i = 1; i < np1; i++)
    for (int j = i; j < np1; j++) setflag[i][j] = 0;
  memory->create(cutsq, np1, np1, "pair:cutsq");
  memory->create(cut, np1, np1, "pair:cut");
  memory->create(d0, np1, np1, "pair:d0");
  memory->create(a0, np1, np1, "pair:a0");
  memory->create(p0, np1, np1, "pair:p0");
  memory->create(q0, np1, np1, "pair:q0");
  memory->create(kappa, np1, np1, "pair:kappa");
  memory->create(rc_pair, np1, np1, "pair:rc_pair");
  memory->create(rs_pair, np1, np1, "pair:rs_pair");
  memory->create(stiffness, np1, np1, "pair:stiffness");
  coeffs = new SplineCoeff[np1 * np1]();
}

/* ----------------------------------------------------------------------
   pair_style STYLE cut Rc | wagner | lagunov Rc [start Rs]  [chain N]
------------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::settings(int narg, char **arg)
{
  if (narg < 1)
    error->all(FLERR, "Pair style {}: missing tail (cut Rc | wagner | lagunov Rc [start Rs])",
               Law::style);
  const std::string name = arg[0];
  int iarg = 1;
  rs_global = 0.0;
  auto tail_number = [&](const char *what) {
    if (iarg >= narg || !utils::is_double(arg[iarg]))
      error->all(FLERR, "Pair style {} {}: expected a number {} (got {})", Law::style, name, what,
                 iarg < narg ? fmt::format("'{}'", arg[iarg]) : std::string("nothing"));
    return arg[iarg++];
  };
  if (name == "cut") {
    tail = CUT;
    const char *rc = tail_number("Rc");
    rc_global = utils::numeric(FLERR, rc, false, lmp);
    if (!(rc_global > 1.0))
      error->all(FLERR, "Pair style {} cut: Rc must be > 1 in units of a (got {}): the bond would "
                 "never hold", Law::style, rc);
  } else if (name == "wagner") {
    if (!Law::has_inflection)
      error->all(FLERR, "Pair style {}: tail wagner needs an inflection point; the harmonic well "
                 "has none (use cut or lagunov Rc start Rs)", Law::style);
    if (iarg < narg && utils::is_double(arg[iarg]))
      error->all(FLERR, "Pair style {} wagner: takes no arguments (got {})", Law::style, arg[iarg]);
    tail = WAGNER;
    rc_global = 0.0;
  } else if (name == "lagunov") {
    tail = LAGUNOV;
    const char *rc = tail_number("Rc");
    rc_global = positive_arg(Law::style, "lagunov Rc", rc, lmp);
    if (!(rc_global > 1.0))
      error->all(FLERR, "Pair style {} lagunov: Rc must be > 1 in units of a (got {}): the bond "
                 "would never hold", Law::style, rc);
    if (iarg < narg && strcmp(arg[iarg], "start") == 0) {
      iarg++;
      const char *rs = tail_number("Rs after start");
      rs_global = positive_arg(Law::style, "lagunov start Rs", rs, lmp);
      if (!(rc_global > rs_global))
        error->all(FLERR, "Pair style {} lagunov: Rc = {} must be > start Rs = {}", Law::style, rc,
                   rs);
    } else if (!Law::has_inflection)
      error->all(FLERR, "Pair style {}: tail lagunov needs 'start Rs'; the harmonic well has no "
                 "inflection point to start at", Law::style);
  } else
    error->all(FLERR, "Pair style {}: unknown tail '{}' (expected cut, wagner or lagunov)",
               Law::style, name);

  // keywords after the tail
  chain_n = 0;
  double new_l = 0.0;
  int relink_set = -1;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key != "chain" && key != "link" && key != "relink")
      error->all(FLERR, "Pair style {}: unknown keyword '{}' after tail {} (expected chain, link "
                 "or relink{})", Law::style, key, name, name == "lagunov" ? " or start" : "");
    if (iarg + 1 >= narg)
      error->all(FLERR, "Pair style {}: keyword {} needs a value", Law::style, key);
    if (key == "chain") {
      chain_n = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (chain_n < 1 || chain_n > MAX_CHAIN)
        error->all(FLERR, "Pair style {}: chain N must be between 1 and {} (got {})", Law::style,
                   MAX_CHAIN, arg[iarg + 1]);
    } else if (key == "link") {
      new_l = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(new_l >= 1.0))
        error->all(FLERR, "Pair style {}: link L must be >= 1 in units of a (got {}): pairs "
                   "closer than L a are linked", Law::style, arg[iarg + 1]);
    } else
      relink_set = utils::logical(FLERR, arg[iarg + 1], false, lmp);
    iarg += 2;
  }
  if (relink_set >= 0 && new_l == 0.0)
    error->all(FLERR, "Pair style {}: relink needs link L", Law::style);
  if (chain_n && new_l > 0.0)
    error->all(FLERR, "Pair style {}: link and chain N do not combine (chain N fixes the "
               "neighbours by atom ID already)", Law::style);
  set_chain_scale();
  set_links(new_l, relink_set > 0);

  // as pair lj/cut resets explicitly set cutoffs, a new pair_style command resets every
  // per-pair rc and rs to the new global values (those of one tail mean nothing to another)
  if (allocated)
    for (int i = 1; i <= atom->ntypes; i++)
      for (int j = i; j <= atom->ntypes; j++) rc_pair[i][j] = rs_pair[i][j] = 0.0;
}

template <class Law> void PairSpline<Law>::set_chain_scale()
{
  chain_scale.assign(chain_n + 1, 0.0);
  for (int n = 1; n <= chain_n; n++) chain_scale[n] = 1.0 / ((double) n * n);
}

/* ----------------------------------------------------------------------
   link L: the state is kept by a PairState; a re-issued pair_style starts
   it afresh (doc: link); switching it off is refused (the links would be
   lost silently)
------------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::set_links(double l, int relink)
{
  if (links.on() && l == 0.0)
    error->all(FLERR, "Pair style {}: link cannot be switched off once set (the link state "
               "would be lost); use pair_style none first", Law::style);
  if (l > 0.0) {
    state.enable();
    if (!pvector) {
      nextra = 3;
      pvector = new double[nextra]();
    }
  }
  links.l = l;
  links.relink = relink;
  single_enable = born_matrix_enable = links.on() ? 0 : 1;    // they cannot see the state
}

/* ----------------------------------------------------------------------
   pair_coeff I J <law args> [kappa K] [rc Rc] [rs Rs]
------------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::coeff(int narg, char **arg)
{
  if (narg < 2 + Law::nargs)
    error->all(FLERR, "Pair {}: expected pair_coeff I J {} [kappa K] [rc Rc] [rs Rs]", Law::style,
               Law::usage);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  SplineCoeff in{};
  Law::read(arg + 2, in, lmp);
  double kappa_one = 1.0, rc_one = 0.0, rs_one = 0.0;
  for (int iarg = 2 + Law::nargs; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (key != "kappa" && key != "rc" && key != "rs")
      error->all(FLERR, "Pair {}: unknown pair_coeff keyword '{}' (expected kappa, rc or rs)",
                 Law::style, key);
    if (iarg + 1 >= narg) error->all(FLERR, "Pair {}: pair_coeff keyword {} needs a value",
                                     Law::style, key);
    const double value = positive_arg(Law::style, key.c_str(), arg[iarg + 1], lmp);
    if (key == "kappa") kappa_one = value;
    else if (key == "rc") {
      if (tail == WAGNER)
        error->all(FLERR, "Pair {}: keyword rc does not apply to tail wagner (its cutoff follows "
                   "from the law)", Law::style);
      if (!(value > 1.0))
        error->all(FLERR, "Pair {}: rc must be > 1 in units of a (got {})", Law::style,
                   arg[iarg + 1]);
      rc_one = value;
    } else {
      if (tail != LAGUNOV)
        error->all(FLERR, "Pair {}: keyword rs applies only to tail lagunov", Law::style);
      rs_one = value;
    }
  }

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      d0[i][j] = in.d;
      a0[i][j] = in.a;
      p0[i][j] = in.p;
      q0[i][j] = in.q;
      kappa[i][j] = kappa_one;
      rc_pair[i][j] = rc_one;
      rs_pair[i][j] = rs_one;
      setflag[i][j] = 1;
      derive(i, j);    // reject a bad law now, with the pair named
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* ----------------------------------------------------------------------
   kernel data of one type pair from its input and the tail settings
------------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::derive(int i, int j)
{
  const int np1 = atom->ntypes + 1;
  SplineCoeff &c = coeffs[i * np1 + j];
  c = SplineCoeff();
  c.d = d0[i][j];
  c.a = a0[i][j];
  c.p = p0[i][j];
  c.q = q0[i][j];
  c.kappa = kappa[i][j];
  Law::setup(c);

  // the law must stay finite under deep compression, down to half the equilibrium
  // distance (exponents such as Mie n = 1e6 overflow double precision right below a)
  {
    double d[4];
    Law::derivs(c, 0.5 * c.a, d);
    for (int k = 0; k < 4; k++)
      if (!std::isfinite(d[k]))
        error->all(FLERR, "Pair {}: law of types {} {} overflows at r = a/2 ({}): '{}' gives "
                   "derivative {} = {} there", Law::style, i, j, Law::overflow_hint,
                   Law::args(c), k, d[k]);
  }

  // inflection point b and bond strength f* of the kappa-modified base

  double b = 0.0, pib = 0.0, fstar = 0.0;
  if (Law::has_inflection) {
    const double b0 = Law::inflection(c);
    double d[4];
    Law::derivs(c, b0, d);
    b = c.a + (b0 - c.a) / c.kappa;
    pib = d[0];
    fstar = c.kappa * fabs(d[1]);
  }
  TailShape shape{b, pib, fstar, rc_pair[i][j] > 0.0 ? rc_pair[i][j] : rc_global,
                  rs_pair[i][j] > 0.0 ? rs_pair[i][j] : rs_global, i, j};
  with_tail(tail, [&](auto t) { decltype(t)::template derive<Law>(c, shape, lmp); });
  c.cutsq = c.rc * c.rc;

  if (tail == CUT && offset_flag) {
    double d[4];
    Law::derivs(c, c.kappa * (c.rc - c.a) + c.a, d);
    c.offset = d[0];
  }
  if (links.on()) links.derive<Law>(c, tail, i, j, np1, lmp);
  if (Law::singular && c.kappa > 1.0) {    // in the chain: r/n at or inside that distance
    const double rh = c.a * (1.0 - 1.0 / c.kappa);
    c.hardsq = rh * rh;
  }
  coeffs[j * np1 + i] = c;
}

/* ---------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::init_style()
{
  if (links.on()) {
    neighbor->add_request(this, NeighConst::REQ_HISTORY);
    state.init();
  } else
    neighbor->add_request(this);
  kappa_any = 0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j]) {
        if (kappa[i][j] != 1.0) kappa_any = 1;
        derive(i, j);
      }
  check_skin();
}

template <class Law> double PairSpline<Law>::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "Pair {}: coefficients for atom types {} {} are not set (this style does "
               "not mix: give pair_coeff {} {} ...)", Law::style, i, j, i, j);
  derive(i, j);
  for (auto *v : {d0, a0, p0, q0, kappa, rc_pair, rs_pair}) v[j][i] = v[i][j];
  const SplineCoeff &c = pair_coeff(i, j);
  double d[4];
  law_derivs(i, j, c.a, d, false);
  stiffness[i][j] = stiffness[j][i] = d[2];
  cut[i][j] = cut[j][i] = c.rc * (chain_n ? chain_n : 1);
  return cut[i][j];
}

/* ---------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++) {
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j])
        for (auto *v : {d0, a0, p0, q0, kappa, rc_pair, rs_pair})
          fwrite(&v[i][j], sizeof(double), 1, fp);
    }
  }
}

template <class Law> void PairSpline<Law>::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++) {
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) {
        for (auto *v : {d0, a0, p0, q0, kappa, rc_pair, rs_pair}) {
          if (me == 0) utils::sfread(FLERR, &v[i][j], sizeof(double), 1, fp, nullptr, error);
          MPI_Bcast(&v[i][j], 1, MPI_DOUBLE, 0, world);
        }
      }
    }
  }
}

template <class Law> void PairSpline<Law>::write_restart_settings(FILE *fp)
{
  fwrite(&tail, sizeof(int), 1, fp);
  fwrite(&rc_global, sizeof(double), 1, fp);
  fwrite(&rs_global, sizeof(double), 1, fp);
  fwrite(&offset_flag, sizeof(int), 1, fp);
  fwrite(&mix_flag, sizeof(int), 1, fp);
  fwrite(&chain_n, sizeof(int), 1, fp);
  fwrite(&links.l, sizeof(double), 1, fp);
  fwrite(&links.relink, sizeof(int), 1, fp);
  state.write_restart(fp);
}

template <class Law> void PairSpline<Law>::read_restart_settings(FILE *fp)
{
  double new_l = 0.0;
  int new_relink = 0;
  if (comm->me == 0) {
    utils::sfread(FLERR, &tail, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &rc_global, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &rs_global, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &offset_flag, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &mix_flag, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &chain_n, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &new_l, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &new_relink, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&new_l, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&new_relink, 1, MPI_INT, 0, world);
  set_links(new_l, new_relink);
  state.read_restart(fp);
  MPI_Bcast(&tail, 1, MPI_INT, 0, world);
  MPI_Bcast(&chain_n, 1, MPI_INT, 0, world);
  set_chain_scale();
  MPI_Bcast(&rc_global, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&rs_global, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&offset_flag, 1, MPI_INT, 0, world);
  MPI_Bcast(&mix_flag, 1, MPI_INT, 0, world);
}

/* ----------------------------------------------------------------------
   data files: the law's arguments, then every keyword explicitly
------------------------------------------------------------------------- */

template <class Law> std::string PairSpline<Law>::data_args(int i, int j) const
{
  SplineCoeff c{};
  c.d = d0[i][j];
  c.a = a0[i][j];
  c.p = p0[i][j];
  c.q = q0[i][j];
  std::string text = Law::args(c) + fmt::format(" kappa {}", kappa[i][j]);
  if (rc_pair[i][j] > 0.0) text += fmt::format(" rc {}", rc_pair[i][j]);
  if (rs_pair[i][j] > 0.0) text += fmt::format(" rs {}", rs_pair[i][j]);
  return text;
}

template <class Law> void PairSpline<Law>::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++) utils::print(fp, "{} {}\n", i, data_args(i, i));
}

template <class Law> void PairSpline<Law>::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) utils::print(fp, "{} {} {}\n", i, j, data_args(i, j));
}

/* ----------------------------------------------------------------------
   Pi, Pi', Pi'', Pi''' at r: the full law (kappa, tail, shift) or the base
------------------------------------------------------------------------- */

template <class Law>
void PairSpline<Law>::law_derivs(int itype, int jtype, double r, double *d, bool tailed) const
{
  const SplineCoeff &c = pair_coeff(itype, jtype);
  if (!tailed) return kappa_derivs<Law>(c, r, d);
  if (r >= c.rc) {
    d[0] = d[1] = d[2] = d[3] = 0.0;
    return;
  }
  with_tail(tail, [&](auto t) { decltype(t)::template derivs<Law>(c, r, d); });
  d[0] -= c.offset;
}

template <class Law> double PairSpline<Law>::law_b(int itype, int jtype) const
{
  if (!Law::has_inflection && tail != LAGUNOV) return 0.0;
  const SplineCoeff &c = pair_coeff(itype, jtype);
  const double b = Law::has_inflection ? c.a + (Law::inflection(c) - c.a) / c.kappa : 0.0;
  if (tail != LAGUNOV || (b > 0.0 && c.rs >= b)) return b;

  // the smoothing starts before b: the first zero of Pi'' of the smoothed law in (Rs, Rc)
  double lo = MAX(c.a, c.rs), hi = c.rc, d[4];
  law_derivs(itype, jtype, lo, d, true);
  if (d[2] <= 0.0) return lo;
  law_derivs(itype, jtype, hi * (1.0 - 1e-12), d, true);
  if (d[2] > 0.0) return 0.0;
  while (hi - lo > 1e-15 * hi) {
    const double mid = 0.5 * (lo + hi);
    law_derivs(itype, jtype, mid, d, true);
    if (d[2] > 0.0) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

template <class Law>
double PairSpline<Law>::single(int, int, int itype, int jtype, double rsq, double,
                               double factor_lj, double &fforce)
{
  const SplineCoeff &c = pair_coeff(itype, jtype);
  double fpair = 0.0, e = 0.0;
  if (rsq < c.cutsq)
    e = with_tail(tail, [&](auto t) { return decltype(t)::template eval<true, Law>(c, rsq, fpair); })
        - c.offset;
  fforce = factor_lj * fpair;
  return factor_lj * e;
}

template <class Law>
void PairSpline<Law>::born_matrix(int, int, int itype, int jtype, double rsq, double,
                                  double factor_lj, double &dupair, double &du2pair)
{
  double d[4];
  law_derivs(itype, jtype, sqrt(rsq), d, true);
  dupair = factor_lj * d[1];
  du2pair = factor_lj * d[2];
}

/* ---------------------------------------------------------------------- */

template <class Law> void *PairSpline<Law>::extract(const char *str, int &dim)
{
  dim = 0;
  if (strcmp(str, "pair_state") == 0) return links.on() ? (void *) &state : nullptr;
  dim = 2;
  if (strcmp(str, "D") == 0) return (void *) d0;
  if (strcmp(str, "a") == 0) return (void *) a0;
  if (strcmp(str, "kappa") == 0) return (void *) kappa;
  if (strcmp(str, "C") == 0) return (void *) stiffness;
  if constexpr (Law::p_name != nullptr)
    if (strcmp(str, Law::p_name) == 0) return (void *) p0;
  if constexpr (Law::q_name != nullptr)
    if (strcmp(str, Law::q_name) == 0) return (void *) q0;
  return nullptr;
}

template <class Law> double PairSpline<Law>::memory_usage()
{
  const double np1 = atom->ntypes + 1;
  return np1 * np1 * (2.0 * sizeof(int) + 10.0 * sizeof(double) + sizeof(SplineCoeff));
}

namespace LAMMPS_NS {
namespace ClusterDyn {
  template class PairSpline<MorseLaw>;
  template class PairSpline<LJLaw>;
  template class PairSpline<MieLaw>;
  template class PairSpline<HarmonicLaw>;
}    // namespace ClusterDyn
}    // namespace LAMMPS_NS
