/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair_style mca (see pair_mca.h).

   One force evaluation, as pair eam's: (a setup only) link the pairs of
   fresh elements and give them their contact areas; the volumetric strain
   of each element from its linked pairs, summed onto owners and sent to
   ghosts; then the pair forces and torques.  The per-pair state (distance
   at linking, contact area, tangential stress, last separation) lives in
   the PairState component, so that it survives list builds, migration,
   restarts and renumbering.
------------------------------------------------------------------------- */

#include "pair_mca.h"

#include "mca_contact.h"
#include "skin_check.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

using C = McaContact;

PairMCA::PairMCA(LAMMPS *lmp) :
    Pair(lmp), guard(lmp), state(lmp, this, "Pair mca", C::NVALUES), sums(nullptr),
    stress(nullptr), nmax(0), stress_wanted(0), stress_nlocal(-1), stress_step(-1),
    comm_what(COMM_SUMS)
{
  single_enable = 0;
  restartinfo = 1;
  writedata = 1;
  manybody_flag = 1;
  nondefault_history_transfer = 1;
  beyond_contact = 1;    // fix neigh/history keeps every listed pair's state, not only contacts
  comm_forward = 1;
  comm_reverse = STRESS_COLUMNS;
  nextra = 3;    // pvector: broken links, links formed, their energy (the state's tally)
  pvector = new double[nextra]();
}

PairMCA::~PairMCA()
{
  delete[] pvector;
  memory->destroy(sums);
  memory->destroy(stress);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairMCA::allocate()
{
  allocated = 1;
  const int np1 = atom->ntypes + 1;
  memory->create(setflag, np1, np1, "pair:setflag");
  memory->create(cutsq, np1, np1, "pair:cutsq");
  // a material belongs to a type: every pair is set once both types have one (init_style)
  for (int i = 1; i < np1; i++)
    for (int j = i; j < np1; j++) setflag[i][j] = 1;
  material.assign(np1, McaMaterial());
  material_set.assign(np1, 0);
}

void PairMCA::grow(int nall)
{
  if (nall <= nmax) return;
  nmax = atom->nmax;
  memory->destroy(sums);
  memory->destroy(stress);
  memory->create(sums, nmax, "pair:sums");
  memory->create(stress, nmax, STRESS_COLUMNS, "pair:stress");
}

double PairMCA::element_volume(int i) const
{
  const double r = atom->radius[i];
  return 4.0 * M_PI / 3.0 * r * r * r / setting.fraction;
}

/* ---------------------------------------------------------------------- */

void PairMCA::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const StatePass pass = state.begin();
  grow(atom->nlocal + atom->nghost);
  if (neighbor->ago == 0) guard.at_list_build();
  guard.each_step();
  if (pass.fresh) make_links(pass);
  if (update->setupflag && update->whichflag == 1) guard.at_setup(scaled, setting.fraction);
  if (setting.manybody) volumetric_strain(pass);
  StateTally changes;
  pair_forces(pass, changes);
  if (setting.manybody && eflag) manybody_energy();
  if (vflag_fdotr) virial_fdotr_compute();
  state.end(changes, pvector);
}

/* ----------------------------------------------------------------------
   a setup: the pairs of fresh elements closer than (1 + tolerance)(R_i + R_j)
   are linked, stress free at their present distance; their contact area is
   S_ij = (S_i + S_j)/2 with S_i = 3 Omega_i / (Z_i R_i), Z_i the linked
   pairs of element i (so that sum_j q_ij S_ij n n = Omega_i I on a regular
   packing: Love's formula gives the element's stress)
------------------------------------------------------------------------- */

void PairMCA::make_links(const StatePass &pass)
{
  double **x = atom->x;
  const double *radius = atom->radius;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton = force->newton_pair;
  double *zcount = sums;    // linked pairs per element
  const double reach = 1.0 + setting.tolerance;
  double deep = 0.0;    // pairs linked closer than half their contact distance
  for (int i = 0; i < nall; i++) zcount[i] = 0.0;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      int &word = pass.words[i][jj];
      if (!pass.fresh[i] || !pass.fresh[j]) {
        double *v = pass.values[i] + C::NVALUES * jj;
        double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
        const double r = sqrt(C::dot(d, d));
        if (r == 0.0) coincident(i, j);
        word = r < reach * (radius[i] + radius[j]) ? 1 : 0;
        if (r < 0.5 * (radius[i] + radius[j])) deep += newton || j < nlocal ? 1.0 : 0.5;
        for (int k = 0; k < C::NVALUES; k++) v[k] = 0.0;
        v[C::REF] = r;
        for (int k = 0; k < 3; k++) v[C::DPREV + k] = d[k];
      }
      if (word & 1) {
        zcount[i] += 1.0;
        if (newton || j < nlocal) zcount[j] += 1.0;
      }
    }
  }
  double deep_all;
  MPI_Allreduce(&deep, &deep_all, 1, MPI_DOUBLE, MPI_SUM, world);
  if (deep_all > 0.0 && comm->me == 0)
    error->warning(FLERR, "Pair mca: {:.0f} pairs linked closer than half their contact distance "
                   "R_i + R_j (overlapping elements): they are linked stress free where they are",
                   deep_all);
  comm_what = COMM_SUMS;
  if (newton) comm->reverse_comm(this);
  comm->forward_comm(this);

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      double *v = pass.values[i] + C::NVALUES * jj;
      if (!(pass.words[i][jj] & 1) || v[C::AREA] != 0.0) continue;
      const int j = jlist[jj] & NEIGHMASK;
      const double si = 3.0 * element_volume(i) / (zcount[i] * radius[i]);
      const double sj = 3.0 * element_volume(j) / (zcount[j] * radius[j]);
      v[C::AREA] = 0.5 * (si + sj);
    }
  }
}

/* ----------------------------------------------------------------------
   theta_i = (1/Omega_i) sum_j S_ij w_i (r_ij - r_ref): the volume change of
   element i from the elongations of its linked pairs (its share w_i of each)
------------------------------------------------------------------------- */

void PairMCA::volumetric_strain(const StatePass &pass)
{
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton = force->newton_pair;
  double *theta = sums;
  for (int i = 0; i < nall; i++) theta[i] = 0.0;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    const double ai = C::half_stiffness(scaled[type[i]].shear, radius[i]);
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      if (!(state_now(pass.words[i][jj]))) continue;
      const int j = jlist[jj] & NEIGHMASK;
      const double *v = pass.values[i] + C::NVALUES * jj;
      const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
      const double elong = v[C::AREA] * (sqrt(dx * dx + dy * dy + dz * dz) - v[C::REF]);
      const double aj = C::half_stiffness(scaled[type[j]].shear, radius[j]);
      theta[i] += elong * aj / (ai + aj);
      if (newton || j < nlocal) theta[j] += elong * ai / (ai + aj);
    }
  }
  comm_what = COMM_SUMS;
  if (newton) comm->reverse_comm(this);
  for (int i = 0; i < nlocal; i++) theta[i] /= element_volume(i);
  comm->forward_comm(this);
}

/* ----------------------------------------------------------------------
   linked pair: F_i = S (sigma n + tau), n from i to j, with
     sigma = a (r - r_ref) + (a_j lambda_i theta_i + a_i lambda_j theta_j)/(a_i + a_j)
     tau  += a du_t   (du_t: the tangential slide of j's contact point relative
                       to i's since the last evaluation: the separation less
                       the last one turned by the contact's spin; tau turned
                       with it first: mca_contact.h)
   torques q_ij n x S tau on i and q_ji n x S tau on j;
   energy S (a (r - r_ref)^2 / 2 + |tau|^2 / (2a)) per pair plus
   lambda_i Omega_i theta_i^2 / 2 per element (manybody_energy).
   unlinked pair: compression only, S_u a (r - R_i - R_j) for r < R_i + R_j
------------------------------------------------------------------------- */

void PairMCA::pair_forces(const StatePass &pass, StateTally &changes)
{
  double **x = atom->x, **f = atom->f, **torque = atom->torque, **omega = atom->omega;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton = force->newton_pair;
  const int manybody = setting.manybody;
  const double *theta = sums;    // volumetric strains (when manybody)
  // a setup re-evaluates the same positions; a minimizer does not turn the elements
  const int moving = !update->setupflag && update->whichflag == 1;
  const double dt = update->dt;
  if (stress_wanted)
    for (int i = 0; i < nall; i++)
      for (int k = 0; k < STRESS_COLUMNS; k++) stress[i][k] = 0.0;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    const McaMaterial &mi = scaled[type[i]];
    const double ri = radius[i];
    const double ai = C::half_stiffness(mi.shear, ri);
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double rj = radius[j];
      double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double rsq = C::dot(d, d);
      const int linked = state_now(pass.words[i][jj]);
      if (!linked && rsq >= (ri + rj) * (ri + rj)) continue;
      if (rsq == 0.0) coincident(i, j);
      const double r = sqrt(rsq);
      const double n[3] = {d[0] / r, d[1] / r, d[2] / r};
      const McaMaterial &mj = scaled[type[j]];
      const double aj = C::half_stiffness(mj.shear, rj);
      const double a = C::series(ai, aj);
      double fi[3], ft[3] = {0.0, 0.0, 0.0}, evdwl = 0.0;
      const double qi = r * ri / (ri + rj), qj = r - qi;

      if (linked) {
        double *v = pass.values[i] + C::NVALUES * jj;
        double *tau = v + C::TAU, *dprev = v + C::DPREV;
        const double area = v[C::AREA];
        const double elong = r - v[C::REF];
        double sigma = a * elong;
        if (manybody) sigma += (aj * mi.lambda * theta[i] + ai * mj.lambda * theta[j]) / (ai + aj);

        // the stored tangential stress and separation turn with the contact's spin; the
        // difference of the separations is then the slide of the contact points
        if (moving) {
          const double *oi = omega[i], *oj = omega[j];
          const double spin[3] = {dt * (qi * oi[0] + qj * oj[0]) / r,
                                  dt * (qi * oi[1] + qj * oj[1]) / r,
                                  dt * (qi * oi[2] + qj * oj[2]) / r};
          C::rotate(tau, spin);
          C::rotate(dprev, spin);
        }
        double du[3] = {d[0] - dprev[0], d[1] - dprev[1], d[2] - dprev[2]};
        // a stress left out of the new tangent plane (the pair turned otherwise than its
        // contact spins) is brought into it at its magnitude
        const double tau_old2 = C::dot(tau, tau), taun = C::dot(tau, n);
        if (taun != 0.0) {
          const double keep =
              tau_old2 > taun * taun ? sqrt(tau_old2 / (tau_old2 - taun * taun)) : 0.0;
          for (int k = 0; k < 3; k++) tau[k] = (tau[k] - taun * n[k]) * keep;
        }
        const double dun = C::dot(du, n);
        for (int k = 0; k < 3; k++) {
          tau[k] += a * (du[k] - dun * n[k]);
          dprev[k] = d[k];
        }
        const double tau2 = C::dot(tau, tau);
        const double strength = C::pair_strength(mi.strength, mj.strength);
        if (strength > 0.0 && sigma > 0.0 && sigma * sigma + 3.0 * tau2 >= strength * strength) {
          // the link breaks (type a): from now on an unlinked pair, apart in tension
          const double w = newton || j < nlocal ? 1.0 : 0.5;
          changes.broken += w;
          changes.ejump += w * area * (0.5 * a * elong * elong + 0.5 * tau2 / a);
          int &word = pass.words[i][jj];
          word = state_word(word, 0, pass.trial);
          continue;
        }
        for (int k = 0; k < 3; k++) {
          ft[k] = area * tau[k];
          fi[k] = area * sigma * n[k] + ft[k];
        }
        if (eflag_either) evdwl = area * (0.5 * a * elong * elong + 0.5 * tau2 / a);
      } else {
        const double area = C::unlinked_area(ri, rj);
        const double overlap = r - ri - rj;    // < 0
        for (int k = 0; k < 3; k++) fi[k] = area * a * overlap * n[k];
        if (eflag_either) evdwl = 0.5 * area * a * overlap * overlap;
      }

      const bool jown = newton || j < nlocal;
      double ti[3];
      C::cross(n, ft, ti);
      for (int k = 0; k < 3; k++) {
        f[i][k] += fi[k];
        torque[i][k] += qi * ti[k];
        if (jown) {
          f[j][k] -= fi[k];
          torque[j][k] += qj * ti[k];
        }
      }
      if (evflag) ev_tally_xyz(i, j, nlocal, newton, evdwl, 0.0, fi[0], fi[1], fi[2], -d[0],
                               -d[1], -d[2]);
      if (stress_wanted) {
        const double sym[6] = {n[0] * fi[0], n[1] * fi[1], n[2] * fi[2],
                               0.5 * (n[0] * fi[1] + n[1] * fi[0]),
                               0.5 * (n[0] * fi[2] + n[2] * fi[0]),
                               0.5 * (n[1] * fi[2] + n[2] * fi[1])};
        for (int k = 0; k < 6; k++) stress[i][k] += qi * sym[k];
        stress[i][6] += linked;
        if (jown) {
          for (int k = 0; k < 6; k++) stress[j][k] += qj * sym[k];
          stress[j][6] += linked;
        }
      }
    }
  }

  if (stress_wanted) {
    stress_step = update->ntimestep;
    stress_nlocal = nlocal;
    comm_what = COMM_STRESS;
    if (newton) comm->reverse_comm(this);
    for (int i = 0; i < nlocal; i++) {
      const double to_pressure = force->nktv2p / element_volume(i);
      for (int k = 0; k < 6; k++) stress[i][k] *= to_pressure;
    }
  }
}

void PairMCA::manybody_energy()
{
  const double *theta = sums;
  const int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    const double e = 0.5 * scaled[type[i]].lambda * element_volume(i) * theta[i] * theta[i];
    if (eflag_global) eng_vdwl += e;
    if (eflag_atom) eatom[i] += e;
  }
}

void PairMCA::coincident(int i, int j) const
{
  error->one(FLERR, "Pair mca: elements {} and {} are at the same place (coincident "
             "elements): remove one", atom->tag[i], atom->tag[j]);
  std::abort();    // not reached: error->one() throws
}

/* ----------------------------------------------------------------------
   pair_style mca fraction F [tolerance T] [manybody yes|no]; re-issued, the
   link state starts afresh (as pair_style spline ... link)
------------------------------------------------------------------------- */

void PairMCA::settings(int narg, char **arg)
{
  setting = McaSettings::parse(lmp, narg, arg);
  state.enable();
}

/* ----------------------------------------------------------------------
   pair_coeff I I bulk K shear G | young E poisson nu: the material of
   element type(s) I; a pair of two types takes each element's own
------------------------------------------------------------------------- */

void PairMCA::coeff(int narg, char **arg)
{
  const std::string who = "Pair mca pair_coeff";
  if (narg < 2) error->all(FLERR, "{}: expected pair_coeff I I bulk K shear G", who);
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  type_range(who, "I", arg[0], atom->ntypes, ilo, ihi, lmp);
  type_range(who, "J", arg[1], atom->ntypes, jlo, jhi, lmp);
  if (ilo != jlo || ihi != jhi)
    error->all(FLERR, "{}: a material belongs to an element type: give pair_coeff I I (got {} "
               "{}); a pair of two types takes each element's own", who, arg[0], arg[1]);
  const McaMaterial m = McaMaterial::read(who, narg - 2, arg + 2, lmp);
  for (int i = ilo; i <= ihi; i++) {
    material[i] = m;
    material_set[i] = 1;
  }
}

// the moduli in energy/volume (pressure units / nktv2p), as the kernel uses them
void PairMCA::scale_materials()
{
  const double p2e = 1.0 / force->nktv2p;
  scaled = material;
  for (McaMaterial &m : scaled) {
    m.bulk *= p2e;
    m.shear *= p2e;
    m.lambda *= p2e;
    m.strength *= p2e;
  }
}

/* ---------------------------------------------------------------------- */

void PairMCA::init_style()
{
  if (!atom->radius_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "Pair mca requires atom_style sphere (elements with radius, omega and "
               "torque)");
  if (domain->dimension != 3)
    error->all(FLERR, "Pair mca is three-dimensional (dimension 2 is not supported)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "Pair mca needs the velocities of ghost elements: comm_modify vel yes");
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Pair mca is not for run_style respa (use run_style verlet)");
  if (tail_flag) error->all(FLERR, "Pair mca: pair_modify tail yes does not apply");
  if (offset_flag) error->all(FLERR, "Pair mca: pair_modify shift yes does not apply");

  guard.init();
  scale_materials();
  neighbor->add_request(this, NeighConst::REQ_HISTORY);
  state.init();
}

// called for every type pair (for the type pairs pair_style hybrid gives this style)
double PairMCA::init_one(int i, int j)
{
  for (const int t : {i, j})
    if (!material_set[t])
      error->all(FLERR, "Pair mca: no material for atom type {}: give pair_coeff {} {} bulk K "
                 "shear G (or young E poisson nu)", t, t, t);
  const double cut = McaSettings::REACH * (1.0 + setting.tolerance) *
                     (guard.largest_radius(i) + guard.largest_radius(j));
  if (i == j && cut > 0.0)
    check_neighbor_skin(lmp, cut, "Pair mca");
  return cut;
}

/* ---------------------------------------------------------------------- */

void PairMCA::transfer_history(double *source, double *target, int, int)
{
  target[C::REF] = source[C::REF];
  target[C::AREA] = source[C::AREA];
  for (int k = 0; k < 3; k++) {
    target[C::TAU + k] = -source[C::TAU + k];
    target[C::DPREV + k] = -source[C::DPREV + k];
  }
}

void *PairMCA::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "pair_state") == 0) return (void *) &state;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

void PairMCA::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++) {
    fwrite(&material_set[i], sizeof(int), 1, fp);
    material[i].write_restart(fp);
  }
}

void PairMCA::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; i++) {
    if (comm->me == 0) utils::sfread(FLERR, &material_set[i], sizeof(int), 1, fp, nullptr, error);
    MPI_Bcast(&material_set[i], 1, MPI_INT, 0, world);
    material[i].read_restart(fp, lmp);
  }
}

void PairMCA::write_restart_settings(FILE *fp)
{
  setting.write_restart(fp);
  state.write_restart(fp);
}

void PairMCA::read_restart_settings(FILE *fp)
{
  setting.read_restart(fp, lmp);
  state.enable();
  state.read_restart(fp);
}

void PairMCA::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++) fmt::print(fp, "{} {}\n", i, material[i].words());
}

void PairMCA::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    fmt::print(fp, "{} {} {}\n", i, i, material[i].words());
}

/* ---------------------------------------------------------------------- */

int PairMCA::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  for (int i = 0; i < n; i++) buf[i] = sums[list[i]];
  return n;
}

void PairMCA::unpack_forward_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) sums[first + i] = buf[i];
}

int PairMCA::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  if (comm_what == COMM_STRESS) {
    for (int i = first; i < first + n; i++)
      for (int k = 0; k < STRESS_COLUMNS; k++) buf[m++] = stress[i][k];
  } else {
    for (int i = first; i < first + n; i++) buf[m++] = sums[i];
  }
  return m;
}

void PairMCA::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  if (comm_what == COMM_STRESS) {
    for (int i = 0; i < n; i++)
      for (int k = 0; k < STRESS_COLUMNS; k++) stress[list[i]][k] += buf[m++];
  } else {
    for (int i = 0; i < n; i++) sums[list[i]] += buf[m++];
  }
}

double PairMCA::memory_usage()
{
  return (double) nmax * (1 + STRESS_COLUMNS) * sizeof(double);
}
