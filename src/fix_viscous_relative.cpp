/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative.

   Each pair (i,j) of group atoms closer than the damping range gets
     F_i = -F_j = -m_ij G_ij w(r) dv / ftm2v,   dv = v_i - v_j  (mode full)
                                                 or (dv . e) e   (mode normal)
   with m_ij = 2 m_i m_j / (m_i + m_j), so the forces cancel in pairs and
   the total momentum is conserved; ftm2v (force->ftm2v) makes the force of
   mass x velocity / time a force in every unit style, so that the relative
   velocity of an isolated pair decays as exp(-2 G t).  Coincident atoms
   (r < 1e-10 of the damping range) have no normal: mode normal skips them,
   as pair dpd/tstat does.  post_force() sums them on a half
   neighbor list into fd (own and ghost atoms), adds the ghost parts to
   their owners (reverse communication), then adds fd to f.  Where its
   pairs are exactly a spline pair style's, that style's force pass sums
   them instead, on the steps without energy or virial tallies
   (damping_pass.h): the same fd, bit for bit, without a second walk over
   the neighbour list.

   Energy removed: velocity Verlet applies a force F computed at step k in
   two half kicks, v(k-1/2) -> v(k) -> v(k+1/2); the work of each half kick
   is exactly (dt/4) F . (v_before + v_after).  The fix sums it over its own
   forces, so the balance closes to the integrator's own accuracy.
------------------------------------------------------------------------- */

#include "fix_viscous_relative.h"

#include "damping_masses.h"
#include "pair_state.h"
#include "xyz3.h"
#include "skin_check.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <type_traits>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace ClusterDyn;

FixViscousRelative::FixViscousRelative(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), opt(ViscousSettings::parse(lmp, narg, arg)), types(lmp, opt), fused(0),
    fd(nullptr), maxfd(0),
    removed(0.0), power_full(0.0), fd_step(-1), kick_step(-1), list(nullptr), state(nullptr)
{
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 1;
  energy_global_flag = 1;
  virial_global_flag = 1;
  restart_global = 1;
  comm_reverse = 3;
  pass.normal = opt.normal;
  pass.dpd = opt.dpd;
  pass.coeff = types.coeffs();
}

FixViscousRelative::~FixViscousRelative()
{
  // unfix followed by run ... pre no: the pair style must not keep the pass
  if (fused && force && force->pair) {
    int dim = 0;
    auto slot = (DampingPass **) force->pair->extract("damping_pass", dim);
    if (slot && *slot == &pass) *slot = nullptr;
  }
  memory->destroy(fd);
}

int FixViscousRelative::setmask()
{
  return PRE_FORCE | POST_FORCE | POST_INTEGRATE | END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixViscousRelative::init()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix viscous/relative does not support run_style respa: its energy "
               "tally follows velocity Verlet's half kicks (use run_style verlet)");
  if (!force->pair && opt.cutoff == 0.0)
    error->all(FLERR, "Fix viscous/relative needs a pair style (its cutoffs are the damping "
               "range) or the cutoff keyword");
  // m_ij of a pair with a ghost atom needs the ghost's mass
  const std::string ghostless = atom->rmass ? ghostless_rmass_fix(lmp) : "";
  if (!ghostless.empty())
    error->all(FLERR, "Fix viscous/relative: fix {} property/atom rmass needs ghost yes (the "
               "damping of a pair with a ghost atom needs its mass)", ghostless);
  int dim = 0;
  state = force->pair ? (PairState *) force->pair->extract("pair_state", dim) : nullptr;
  if (state && opt.cutoff > 0.0)
    error->all(FLERR, "Fix viscous/relative: keyword cutoff does not apply under a pair style "
               "with link L (the linked pairs are the bonds it damps)");
  if (opt.by_j) {
    double **stiffness = force->pair ? (double **) force->pair->extract("C", dim) : nullptr;
    if (!stiffness || dim != 2)
      error->all(FLERR, "Fix viscous/relative J needs a pair style that provides the bond "
                 "stiffness C (this package's */spline styles); use gamma G with others");
  }
  // fix adapt may change the pair's cutoffs and C between two force evaluations: the tables
  // follow before each of the fix's own loops, and the pass (whose tables would be read
  // before the change) is not offered
  adapting = !modify->get_fix_by_style("^adapt").empty();
  if (adapting && opt.cutoff == 0.0 && utils::strmatch(force->pair_style, "^hybrid") &&
      comm->me == 0)
    error->warning(FLERR, "Fix viscous/relative: under pair_style {} the damping range is the "
                   "hybrid's cutoffs as the run starts; fix adapt changing a sub-style's cutoffs "
                   "does not move it (give the cutoff keyword)", force->pair_style);
  types.fill();
  fused = adapting ? 0 : claim_pass();
  pass.fd = nullptr;

  if (opt.cutoff > 0.0)
    check_neighbor_skin(lmp, force->pair ? MAX(opt.cutoff, force->pair->cutforce) : opt.cutoff,
                        "Fix viscous/relative");

  // relative velocities need ghost velocities
  comm->ghost_velocity = 1;

  // linked pairs: the pair style's list and states; else a list of our own, which the pair
  // style's covers unless the cutoff is longer
  if (state) return;
  auto req = neighbor->add_request(this);
  if (opt.cutoff > 0.0 && (!force->pair || opt.cutoff > force->pair->cutforce)) {
    const double skin = neighbor->skin;
    const double cutghost = force->pair ? MAX(force->pair->cutforce + skin, comm->cutghostuser)
                                        : comm->cutghostuser;
    if (opt.cutoff + skin > cutghost)
      error->all(FLERR, "Fix viscous/relative: cutoff {} plus skin {} exceeds the ghost atom "
                 "range {}: raise it with comm_modify cutoff", opt.cutoff, skin, cutghost);
    req->set_cutoff(opt.cutoff + skin);
  }
}

void FixViscousRelative::init_list(int, NeighList *ptr)
{
  list = ptr;
}

// the pair style's force pass damps the pairs this fix would: every pair of its list inside
// the pair's cutoffs, per-type masses, group all; the first such fix takes the slot
int FixViscousRelative::claim_pass()
{
  if (!force->pair || opt.cutoff > 0.0 || state || atom->rmass || groupbit != 1 ||
      utils::strmatch(force->pair_style, "^hybrid"))
    return 0;
  int dim = 0;
  auto slot = (DampingPass **) force->pair->extract("damping_pass", dim);
  if (!slot || *slot) return 0;
  *slot = &pass;
  if (comm->me == 0)
    utils::logmesg(lmp, "Fix viscous/relative {}: damping summed in pair {}'s force pass\n", id,
                   force->pair_style);
  return 1;
}

/* ---------------------------------------------------------------------- */

void FixViscousRelative::setup(int vflag)
{
  if (adapting) types.fill();    // fix adapt changed the pair at setup_pre_force
  check_stability();
  power_full = compute_forces(vflag);    // v(0): no kick before the first output
  fd_step = update->ntimestep;
}

// offer the pair style's force pass fd, unless this step tallies the fix's virial
void FixViscousRelative::pre_force(int vflag)
{
  pass.fd = nullptr;
  pass.filled = 0;
  if (!fused || (vflag && thermo_virial)) return;
  clear_fd();
  pass.fd = (xyz3 *) fd[0];
}

void FixViscousRelative::post_force(int vflag)
{
  double power_now;    // v(k-1/2) side of the first half kick
  if (pass.filled) {
    v_init(vflag);    // no virial: the pass is offered only without it
    power_now = add_forces();
  } else
    power_now = compute_forces(vflag);
  pass.fd = nullptr;
  pass.filled = 0;
  removed -= 0.25 * update->dt * power_now;
  fd_step = kick_step = update->ntimestep;
}

void FixViscousRelative::end_of_step()
{
  if (kick_step != update->ntimestep) return;    // rerun: end_of_step without a step
  power_full = power();
  removed -= 0.25 * update->dt * power_full;    // first half kick, v(k) side
}

void FixViscousRelative::post_integrate()
{
  // second half kick v(k) -> v(k+1/2) with the forces of step k; atoms have not moved
  // between processors since then, unless a run skipped its setup after a change
  if (fd_step != update->ntimestep - 1)
    error->all(FLERR, "Fix viscous/relative: no damping forces of step {} for its second half "
               "kick: run ... pre no after a minimization or another change between runs (use "
               "pre yes)", update->ntimestep - 1);
  removed -= 0.25 * update->dt * (power_full + power());
}

double FixViscousRelative::power() const
{
  const double *const *const v = atom->v;
  double p = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    p += fd[i][0] * v[i][0] + fd[i][1] * v[i][1] + fd[i][2] * v[i][2];
  return p;
}

// fd for my atoms and ghosts, zeroed
void FixViscousRelative::clear_fd()
{
  if (atom->nmax > maxfd) {
    maxfd = atom->nmax;
    memory->destroy(fd);
    memory->create(fd, maxfd, 3, "viscous/relative:fd");
  }
  const int nall = atom->nlocal + atom->nghost;
  if (nall) memset(&fd[0][0], 0, 3 * sizeof(double) * nall);
}

double FixViscousRelative::compute_forces(int vflag)
{
  if (adapting) types.fill();
  v_init(vflag);
  clear_fd();

  // compile-time options: a scene pays only for what it uses
  const Bonds bonds = current_bonds();
  const int general = atom->rmass != nullptr || groupbit != 1;    // group all: no mask lookups
  auto run = [&](auto normal, auto dpd) {
    using I = decltype(normal);
    using J = decltype(dpd);
    if (general) bonds.words ? damp<I::value, J::value, 1, 1>(bonds) : damp<I::value, J::value, 1, 0>(bonds);
    else bonds.words ? damp<I::value, J::value, 0, 1>(bonds) : damp<I::value, J::value, 0, 0>(bonds);
  };
  using I0 = std::integral_constant<int, 0>;
  using I1 = std::integral_constant<int, 1>;
  if (opt.normal) opt.dpd ? run(I1(), I1()) : run(I1(), I0());
  else opt.dpd ? run(I0(), I1()) : run(I0(), I0());
  return add_forces();
}

// fd's ghost parts to their owners, fd into the forces; the power sum fd . v of my atoms
double FixViscousRelative::add_forces()
{
  if (force->newton_pair) comm->reverse_comm(this);
  double **f = atom->f;
  const double *const *const v = atom->v;
  double p = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    f[i][0] += fd[i][0];
    f[i][1] += fd[i][1];
    f[i][2] += fd[i][2];
    p += fd[i][0] * v[i][0] + fd[i][1] * v[i][1] + fd[i][2] * v[i][2];
  }
  return p;
}

// the pairs damped: those of our list within the damping range, or the pair style's links
FixViscousRelative::Bonds FixViscousRelative::current_bonds() const
{
  if (!state) return {list, nullptr};
  const StateView view = state->view();    // made at the setup, before the fix's setup
  return {view.list, view.words};
}

// GENERAL: per-atom masses or a group other than all (else: per-type masses, group all);
// LINKED: only the pair style's linked pairs
template <int NORMAL, int DPD, int GENERAL, int LINKED>
void FixViscousRelative::damp(const Bonds &bonds)
{
  const auto *_noalias const x = (xyz3 *) atom->x[0];
  const auto *_noalias const v = (xyz3 *) atom->v[0];
  auto *_noalias const fdamp = (xyz3 *) fd[0];
  const int *_noalias const type = atom->type;
  const int *_noalias const mask = atom->mask;
  const double *_noalias const rmass = atom->rmass;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const NeighList *const list = bonds.list;
  const int inum = list->inum;

  for (int ii = 0; ii < inum; ii++) {
    const int i = list->ilist[ii];
    if (GENERAL && !(mask[i] & groupbit)) continue;
    const DampingTypes::TypePair *tpi = types.row(type[i]);
    const DampingCoeff *ci = types.coeff_row(type[i]);
    const double xtmp = x[i].x, ytmp = x[i].y, ztmp = x[i].z;
    const double vxtmp = v[i].x, vytmp = v[i].y, vztmp = v[i].z;
    double fxtmp = 0.0, fytmp = 0.0, fztmp = 0.0;
    const int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xtmp - x[j].x;
      const double dely = ytmp - x[j].y;
      const double delz = ztmp - x[j].z;
      const double rsq = delx * delx + dely * dely + delz * delz;
      const DampingTypes::TypePair &tp = tpi[type[j]];
      if (rsq >= tp.cutsq || (GENERAL && !(mask[j] & groupbit))) continue;
      if (LINKED && !state_now(bonds.words[i][jj])) continue;

      const DampingCoeff &c = ci[type[j]];
      const double coef = GENERAL && rmass ? types.friction(tp, rmass[i], rmass[j]) : c.coef;
      double fx, fy, fz;
      damping_force<NORMAL, DPD>(coef, c.inv_cut, rsq, tp.cutsq, vxtmp - v[j].x, vytmp - v[j].y,
                                 vztmp - v[j].z, delx, dely, delz, fx, fy, fz);
      fxtmp += fx;
      fytmp += fy;
      fztmp += fz;
      if (newton_pair || j < nlocal) {
        fdamp[j].x -= fx;
        fdamp[j].y -= fy;
        fdamp[j].z -= fz;
      }
      if (vflag_global) {
        int pair[2] = {i, j};
        double vir[6] = {delx * fx, dely * fy, delz * fz, delx * fy, delx * fz, dely * fz};
        v_tally((newton_pair || j < nlocal) ? 2 : 1, pair, 2.0, vir);
      }
    }
    fdamp[i].x += fxtmp;
    fdamp[i].y += fytmp;
    fdamp[i].z += fztmp;
  }
}

/* ----------------------------------------------------------------------
   warn when G x (bonds per atom) x dt exceeds 1: the explicit update of the
   relative velocities (eigenvalues up to 2 G x bonds) is then unstable
------------------------------------------------------------------------- */

void FixViscousRelative::check_stability()
{
  const int nlocal = atom->nlocal;
  clear_fd();    // fd[i][0]: bonds of atom i
  const double *const *const x = atom->x;
  const int *type = atom->type;
  const int *mask = atom->mask;
  double rate_max = 0.0;
  const Bonds bonds = current_bonds();
  const NeighList *const list = bonds.list;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const DampingTypes::TypePair &tp = types.row(type[i])[type[j]];
      if (dx * dx + dy * dy + dz * dz >= tp.cutsq) continue;
      if (bonds.words && !state_now(bonds.words[i][jj])) continue;
      fd[i][0] += 1.0;
      if (force->newton_pair || j < nlocal) fd[j][0] += 1.0;
      const double mi = atom->rmass ? atom->rmass[i] : atom->mass[type[i]];
      const double mj = atom->rmass ? atom->rmass[j] : atom->mass[type[j]];
      rate_max = MAX(rate_max, types.rate(tp, 2.0 * mi * mj / (mi + mj)));
    }
  }
  if (force->newton_pair) comm->reverse_comm(this);
  double most = 0.0;    // bonds of one atom
  for (int i = 0; i < nlocal; i++) most = MAX(most, fd[i][0]);
  double mine[2] = {most, rate_max}, all[2];
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_MAX, world);
  const double product = all[1] * all[0] * update->dt;
  if (product > 1.0) {    // a run diverges (NaN, lost atoms); run 0 is only told
    const std::string text = fmt::format(
        "Fix viscous/relative: G x bonds x dt = {:.3g} x {} x {:.3g} = {:.3g} > 1: the damping is "
        "unstable with explicit integration; use a time step below {:.3g} (or a smaller {})",
        all[1], (int) all[0], update->dt, product, 1.0 / (all[1] * all[0]),
        opt.by_j ? "1/J" : "gamma");
    if (update->nsteps > 0) error->all(FLERR, text);
    if (comm->me == 0) error->warning(FLERR, text);
  }
}

/* ---------------------------------------------------------------------- */

double FixViscousRelative::compute_scalar()
{
  double all = 0.0;
  MPI_Allreduce(&removed, &all, 1, MPI_DOUBLE, MPI_SUM, world);
  return all;
}

void FixViscousRelative::write_restart(FILE *fp)
{
  double all = compute_scalar();    // collective: every proc calls write_restart
  if (comm->me == 0) {
    int size = sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(&all, sizeof(double), 1, fp);
  }
}

void FixViscousRelative::restart(char *buf)
{
  double all;
  memcpy(&all, buf, sizeof(double));
  removed = comm->me == 0 ? all : 0.0;
}

int FixViscousRelative::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    buf[m++] = fd[i][0];
    buf[m++] = fd[i][1];
    buf[m++] = fd[i][2];
  }
  return m;
}

void FixViscousRelative::unpack_reverse_comm(int n, int *list_, double *buf)
{
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int j = list_[i];
    fd[j][0] += buf[m++];
    fd[j][1] += buf[m++];
    fd[j][2] += buf[m++];
  }
}

double FixViscousRelative::memory_usage()
{
  return (double) maxfd * 3 * sizeof(double) + types.memory_usage();
}
