/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair styles morse/spline, lj/spline,
   mie/spline, harmonic/spline.  See pair_spline.h and doc/pair_spline.rst.
------------------------------------------------------------------------- */

#include "pair_spline.h"

#include "skin_check.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

template <class Law>
PairSpline<Law>::PairSpline(LAMMPS *lmp) :
    Pair(lmp), table(lmp), state(lmp, this, std::string("Pair style ") + Law::style, 0),
    kappa_any(0), damping(nullptr), listed(0)
{
  writedata = 1;
  born_matrix_enable = 1;
  beyond_contact = 1;    // fix neigh/history keeps every listed pair's flag, not only contacts
}

template <class Law> PairSpline<Law>::~PairSpline()
{
  if (copymode) return;
  delete[] pvector;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

template <class Law> void PairSpline<Law>::allocate()
{
  allocated = 1;
  const int np1 = atom->ntypes + 1;
  memory->create(setflag, np1, np1, "pair:setflag");
  for (int i = 1; i < np1; i++)
    for (int j = i; j < np1; j++) setflag[i][j] = 0;
  memory->create(cutsq, np1, np1, "pair:cutsq");
  table.allocate(atom->ntypes);
}

/* ---------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const StatePass pass = start_compute();
  StateTally changes;
  DampingPass *const fused = damping_this_step();    // fix viscous/relative's
  run_spline_kernel<Law>(
      variant(eflag, fused), kernel_data(fused), list, atom, force->special_lj, 0, list->inum,
      (xyz3 *) atom->f[0], pass, changes,
      [this](int i, int j, int nlocal, int newton, double evdwl, double fpair, double dx, double dy,
             double dz) { ev_tally(i, j, nlocal, newton, evdwl, 0.0, fpair, dx, dy, dz); },
      [this](int i, int j, double rsq) { singular_error(i, j, rsq); });
  if (fused) fused->filled = 1;
  if (vflag_fdotr) virial_fdotr_compute();
  finish_compute(changes);
}

// before and after the kernel, serial and /omp: the link state and tally, the time-step check
template <class Law> void PairSpline<Law>::finish_compute(const StateTally &changes)
{
  if (links.on()) state.end(changes, pvector);
  if (neighbor->ago == 0)
    step_check.check(lmp, Law::style, list, *this, table.coeffs, table.stiffness,
                     setting.chain_n, chain_scale);
}

template <class Law> void PairSpline<Law>::singular_error(int i, int j, double rsq) const
{
  const SplineCoeff &c = table.at(atom->type[i], atom->type[j]);
  error->one(FLERR,
             "Pair {}: atoms {} and {} are {:.8g} apart, at or inside the distance {:.8g} where "
             "their law (types {} {}) is singular (a (1 - 1/kappa) for kappa > 1, else 0): "
             "reduce the time step or kappa",
             Law::style, atom->tag[i], atom->tag[j], sqrt(rsq), sqrt(c.hardsq), atom->type[i],
             atom->type[j]);
  std::abort();    // not reached: error->one() throws
}

/* ----------------------------------------------------------------------
   pair_style: parsed whole, then applied.  link L: a re-issued pair_style
   starts the state afresh (doc: link); switching it off is refused (the
   links would be lost silently)
------------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::settings(int narg, char **arg)
{
  apply(SplineSettings::parse(lmp, Law::style, Law::has_inflection, narg, arg));
  if (allocated) table.reset_cutoffs();
}

template <class Law> void PairSpline<Law>::apply(const SplineSettings &s)
{
  if (links.on() && s.link_l == 0.0)
    error->all(FLERR, "Pair style {}: link cannot be switched off once set (the link state "
               "would be lost); use pair_style none first", Law::style);
  if (s.link_l > 0.0) {
    state.enable();
    if (!pvector) {
      nextra = 3;
      pvector = new double[nextra]();
    }
  }
  setting = s;
  links.l = s.link_l;
  links.relink = s.relink;
  single_enable = born_matrix_enable = links.on() ? 0 : 1;    // they cannot see the state
  chain_scale.assign(s.chain_n + 1, 0.0);
  for (int n = 1; n <= s.chain_n; n++) chain_scale[n] = 1.0 / ((double) n * n);
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
  const std::string who = std::string("Pair ") + Law::style + " pair_coeff";
  type_range(who, "I", arg[0], atom->ntypes, ilo, ihi, lmp);
  type_range(who, "J", arg[1], atom->ntypes, jlo, jhi, lmp);

  SplineCoeff in{};
  Law::read(arg + 2, in, lmp);
  const SplineSettings::PairKeywords k =
      setting.parse_pair_keywords(lmp, Law::style, narg - 2 - Law::nargs, arg + 2 + Law::nargs);
  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      table.set(i, j, in, k.kappa, k.rc, k.rs);
      setflag[i][j] = 1;
      table.derive(i, j, setting, offset_flag, links);    // reject a bad law now, pair named
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* ---------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::init_style()
{
  check_run();
  if (links.on()) {
    neighbor->add_request(this, NeighConst::REQ_HISTORY);
    state.init();
  } else
    neighbor->add_request(this);
  derive_table();
}

// init_style's checks of the run, before the lists are requested
template <class Law> void PairSpline<Law>::check_run()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Pair {} is not for run_style respa (use run_style verlet)", Law::style);
  if (tail_flag)
    error->all(FLERR, "Pair {}: pair_modify tail yes does not apply (the interaction ends at "
               "the tail's end)", Law::style);
  damping = nullptr;    // claimed by fix viscous/relative's init, after this
  listed = 0;           // the init_one() calls that follow are the run's own
}

// init_style's kernel constants of every type pair set, and the skin's check against them
template <class Law> void PairSpline<Law>::derive_table()
{
  kappa_any = 0;    // set by init_one()
  double cutmax = 0.0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j]) {
        table.derive(i, j, setting, offset_flag, links);
        cutmax = MAX(cutmax, table.at(i, j).rc * (setting.chain_n ? setting.chain_n : 1));
      }
  // LAMMPS's default skin is a fixed length per unit style (units si: 1 mm); at cluster
  // scale it is 100 particle sizes, and binning then fails
  check_neighbor_skin(lmp, cutmax, fmt::format("Pair {}", Law::style));
}

template <class Law> double PairSpline<Law>::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "Pair {}: coefficients for atom types {} {} are not set (this style does "
               "not mix: give pair_coeff {} {} ...)", Law::style, i, j, i, j);
  table.derive(i, j, setting, offset_flag, links);
  table.mirror(i, j);
  if (table.kappa[i][j] != 1.0) kappa_any = 1;    // the kappa kernel, also after fix adapt
  const double reach = table.at(i, j).rc * (setting.chain_n ? setting.chain_n : 1);
  // fix adapt (reinit(), also through a hybrid style) may move Rc a during a run
  if (listed) {
    const double made = sqrt(neighbor->cutneighsq[i][j]) - neighbor->skin;
    if (reach > made * (1.0 + 1e-12))
      error->all(FLERR, "Pair {}: fix adapt moved the cutoff of types {} {} to {:.6g} beyond "
                 "{:.6g}, its value when the run's neighbour lists were made: before the run, "
                 "give pair_coeff the largest a (and rc) it reaches, or use fix adapt reset yes",
                 Law::style, i, j, reach, made);
  }
  cutsq[i][j] = cutsq[j][i] = reach * reach;    // as Pair::init does; its reinit() does not
  return reach;
}

// the run's neighbour lists are made (every run and minimization with setup, also when the
// lists are kept from the run before): from now on (fix adapt's reinit()) a type pair's
// cutoff must stay inside the one they were made for
template <class Law> void PairSpline<Law>::setup()
{
  listed = 1;
}

/* ---------------------------------------------------------------------- */

template <class Law> void PairSpline<Law>::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  table.write_restart(fp, setflag);
}

template <class Law> void PairSpline<Law>::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  table.read_restart(fp, setflag);
}

template <class Law> void PairSpline<Law>::write_restart_settings(FILE *fp)
{
  setting.write_restart(fp, offset_flag, mix_flag);
  state.write_restart(fp);
}

template <class Law> void PairSpline<Law>::read_restart_settings(FILE *fp)
{
  SplineSettings s;
  s.read_restart(fp, offset_flag, mix_flag, lmp);
  apply(s);
  state.read_restart(fp);
}

template <class Law> void PairSpline<Law>::write_data(FILE *fp)
{
  table.write_data(fp, false);
}

template <class Law> void PairSpline<Law>::write_data_all(FILE *fp)
{
  table.write_data(fp, true);
}

/* ---------------------------------------------------------------------- */

template <class Law>
double PairSpline<Law>::single(int, int, int itype, int jtype, double rsq, double,
                               double factor_lj, double &fforce)
{
  double fpair;
  const double e = pair_law_energy<Law>(table.at(itype, jtype), setting.tail, rsq, fpair);
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

template <class Law> void *PairSpline<Law>::extract(const char *str, int &dim)
{
  dim = -1;    // objects, not parameters: fix adapt refuses dimensions other than 0 and 2
  if (strcmp(str, "pair_state") == 0) return links.on() ? (void *) &state : nullptr;
  if (strcmp(str, "damping_pass") == 0)    // the kernel's DAMP modes: every pair to the end
    return !links.on() && !setting.chain_n ? (void *) &damping : nullptr;
  dim = 2;
  return table.extract(str);
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
