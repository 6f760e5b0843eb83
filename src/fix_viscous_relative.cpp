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
   neighbor list (damping_pairs.h) into fd (own and ghost atoms,
   damping_forces.h), adds the ghost parts to their owners (reverse
   communication), then adds fd to f.  Where its
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
#include "damping_stability.h"
#include "pair_state.h"
#include "skin_check.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace ClusterDyn;

FixViscousRelative::FixViscousRelative(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), opt(ViscousSettings::parse(lmp, narg, arg)), types(lmp, opt),
    forces(lmp), fused(0), removed(0.0), power_full(0.0), fd_step(-1), kick_step(-1),
    list(nullptr), state(nullptr)
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
  check_damping_stability(lmp, this, current_bonds(), types, opt, forces);
  power_full = compute_forces(vflag);    // v(0): no kick before the first output
  fd_step = update->ntimestep;
}

// offer the pair style's force pass fd, unless this step tallies the fix's virial
void FixViscousRelative::pre_force(int vflag)
{
  pass.fd = nullptr;
  pass.filled = 0;
  if (!fused || (vflag && thermo_virial)) return;
  forces.clear();
  pass.fd = forces.data();
}

void FixViscousRelative::post_force(int vflag)
{
  double power_now;    // v(k-1/2) side of the first half kick
  if (pass.filled) {
    v_init(vflag);    // no virial: the pass is offered only without it
    power_now = forces.add_to_forces(this);
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
  power_full = forces.power();
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
  removed -= 0.25 * update->dt * (power_full + forces.power());
}

double FixViscousRelative::compute_forces(int vflag)
{
  if (adapting) types.fill();
  v_init(vflag);
  forces.clear();
  const DampingPairs pairs{atom, types, current_bonds(), groupbit, force->newton_pair,
                           vflag_global};
  pairs.run(opt, forces.data(),
            [this](int n, int *pair, double *vir) { v_tally(n, pair, 2.0, vir); });
  return forces.add_to_forces(this);
}

// the pairs damped: those of our list within the damping range, or the pair style's links
DampingBonds FixViscousRelative::current_bonds() const
{
  if (!state) return {list, nullptr, nullptr};
  const StateView view = state->view();    // made at the setup, before the fix's setup
  return {view.list, view.words, view.counts};
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
  return forces.pack(n, first, buf);
}

void FixViscousRelative::unpack_reverse_comm(int n, int *list_, double *buf)
{
  forces.unpack(n, list_, buf);
}

double FixViscousRelative::memory_usage()
{
  return forces.memory_usage() + types.memory_usage();
}
