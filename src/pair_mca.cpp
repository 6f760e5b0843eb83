/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair_style mca (see pair_mca.h).

   One force evaluation, as pair eam's: (a setup only) link the pairs of
   fresh elements and give them their contact areas; the volumetric strain
   of each element from its linked pairs, summed onto owners and sent to
   ghosts; (plasticity) the trial pair stresses, the elements' stresses
   from them and their radial return; then the pair forces and torques,
   with damage, breaking, friction and welding; last the energy that the
   changes of state took from the many-body term.  The per-pair state
   (mca_contact.h) lives in the PairState component, so that it survives
   list builds, migration, restarts and renumbering.
------------------------------------------------------------------------- */

#include "pair_mca.h"

#include "mca_contact.h"
#include "mca_friction.h"
#include "mca_response.h"
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
#include <algorithm>
#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

using C = McaContact;

PairMCA::PairMCA(LAMMPS *lmp) :
    Pair(lmp), guard(lmp), plasticity(lmp), state(lmp, this, "Pair mca", C::NVALUES, NWORK),
    responds(0), sums(nullptr), stress(nullptr), returned(nullptr), dtheta(nullptr), nmax(0),
    stress_wanted(0), stress_step(-1), stress_atoms(0), comm_what(COMM_SUMS)
{
  single_enable = 0;
  restartinfo = 1;
  writedata = 1;
  manybody_flag = 1;
  nondefault_history_transfer = 1;
  beyond_contact = 1;    // fix neigh/history keeps every listed pair's state, not only contacts
  comm_forward = 2;
  comm_reverse = STRESS_COLUMNS;
  nextra = 3 + NWORK;    // pvector: the state's tally, then the dissipated energies
  pvector = new double[nextra]();
}

PairMCA::~PairMCA()
{
  delete[] pvector;
  memory->destroy(sums);
  memory->destroy(stress);
  memory->destroy(returned);
  memory->destroy(dtheta);
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
  unlinkable.assign(np1 * np1, 0);
}

bool PairMCA::linkable(int itype, int jtype) const
{
  return !unlinkable[itype * (atom->ntypes + 1) + jtype];
}

void PairMCA::grow(int nall)
{
  if (nall <= nmax) return;
  nmax = atom->nmax;
  memory->destroy(sums);
  memory->destroy(stress);
  memory->destroy(returned);
  memory->destroy(dtheta);
  memory->create(sums, nmax, "pair:sums");
  memory->create(stress, nmax, STRESS_COLUMNS, "pair:stress");
  memory->create(returned, nmax, 2, "pair:returned");
  memory->create(dtheta, nmax, 3, "pair:dtheta");
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
  guard.each_step();
  if (pass.fresh) make_links(pass);
  if (update->setupflag && update->whichflag == 1) guard.at_setup(scaled, setting.fraction);
  if (setting.manybody) volumetric_strain(pass);
  if (plasticity.active()) plastic_trial(pass);
  StateTally changes;
  pair_forces(pass, changes);
  if (setting.manybody && responds) manybody_changes(changes);
  if (setting.manybody && eflag) manybody_energy();
  if (vflag_fdotr) virial_fdotr_compute();
  state.end(changes, pvector);
}

/* ----------------------------------------------------------------------
   a setup: the pairs of fresh elements closer than (1 + tolerance)(R_i + R_j)
   are linked (unless their types never link), stress free at their present
   distance; their contact area is S_ij = (S_i + S_j)/2 with
   S_i = 3 Omega_i / (Z_i R_i), Z_i the linked pairs of element i (so that
   sum_j q_ij S_ij n n = Omega_i I on a regular packing: Love's formula
   gives the element's stress)
------------------------------------------------------------------------- */

void PairMCA::make_links(const StatePass &pass)
{
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *type = atom->type;
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
        double *v = pass.pair_values(i, jj);
        double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
        const double r = sqrt(C::dot(d, d));
        if (r == 0.0) coincident(i, j);
        const double rsum = radius[i] + radius[j];
        word = r < reach * rsum && linkable(type[i], type[j]) ? 1 : 0;
        if (word && r < 0.5 * rsum) deep += newton || j < nlocal ? 1.0 : 0.5;
        for (int k = 0; k < C::NVALUES; k++) v[k] = 0.0;
        v[C::REF] = r;
        for (int k = 0; k < 3; k++) v[C::DPREV + k] = d[k];
      }
      if (state_now(word)) {
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
  if (newton) comm->reverse_comm(this, 1);
  comm->forward_comm(this, 1);

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      double *v = pass.pair_values(i, jj);
      if (!state_now(pass.words[i][jj]) || v[C::AREA] != 0.0) continue;
      const int j = jlist[jj] & NEIGHMASK;
      const double si = 3.0 * element_volume(i) / (zcount[i] * radius[i]);
      const double sj = 3.0 * element_volume(j) / (zcount[j] * radius[j]);
      v[C::AREA] = 0.5 * (si + sj);
    }
  }
}

/* ----------------------------------------------------------------------
   theta_i = (1/Omega_i) sum_j (1 - D_ij) S_ij w_i (r_ij - r_ref - e_p): the
   volume change of element i from the elastic elongations of its linked
   pairs (its share w_i of each)
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
    const McaMaterial &mi = scaled[type[i]];
    const double ai = C::half_stiffness(mi.shear, radius[i]);
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      if (!state_now(pass.words[i][jj])) continue;
      const int j = jlist[jj] & NEIGHMASK;
      const McaMaterial &mj = scaled[type[j]];
      const double *v = pass.pair_values(i, jj);
      const McaResponse resp =
          McaResponse::of_pair(mi.strength, mi.damage, mj.strength, mj.damage);
      const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
      const double elong = resp.intact(v[C::KAPPA]) * v[C::AREA] *
                           (sqrt(dx * dx + dy * dy + dz * dz) - v[C::REF] - v[C::EPL]);
      const double aj = C::half_stiffness(mj.shear, radius[j]);
      theta[i] += elong * aj / (ai + aj);
      if (newton || j < nlocal) theta[j] += elong * ai / (ai + aj);
    }
  }
  comm_what = COMM_SUMS;
  if (newton) comm->reverse_comm(this, 1);
  for (int i = 0; i < nlocal; i++) theta[i] /= element_volume(i);
  comm->forward_comm(this, 1);
}

/* ----------------------------------------------------------------------
   a linked pair's effective normal stress at this step (before any return)
     sigma~ = a (r - r_ref - e_p) + (a_j lambda_i theta_i + a_i lambda_j theta_j)/(a_i + a_j)
   and its tangential stress tau~ after this step's slide (stored in v)
------------------------------------------------------------------------- */

double PairMCA::linked_trial(int i, int j, double *v, const double *d, const double *n,
                             double r, const C::Turn *turn) const
{
  const double *radius = atom->radius;
  const int *type = atom->type;
  const McaMaterial &mi = scaled[type[i]], &mj = scaled[type[j]];
  const double ai = C::half_stiffness(mi.shear, radius[i]);
  const double aj = C::half_stiffness(mj.shear, radius[j]);
  const double a = C::series(ai, aj);
  double sigma = a * (r - v[C::REF] - v[C::EPL]);
  if (setting.manybody)
    sigma += (aj * mi.lambda * sums[i] + ai * mj.lambda * sums[j]) / (ai + aj);
  C::slide(v + C::TAU, v + C::DPREV, d, n, turn, a);
  return sigma;
}

/* ----------------------------------------------------------------------
   plasticity: every linked pair's trial stresses (tau stored, sigma in
   SIG), the elements' stresses from them (Love's formula), then each
   element's radial return factor and mean stress, sent to ghosts
------------------------------------------------------------------------- */

void PairMCA::plastic_trial(const StatePass &pass)
{
  double **x = atom->x, **omega = atom->omega;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton = force->newton_pair;
  const int moving = !update->setupflag && update->whichflag == 1;
  const double dt = update->dt;
  for (int i = 0; i < nall; i++)
    for (int k = 0; k < STRESS_COLUMNS; k++) stress[i][k] = 0.0;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      if (!state_now(pass.words[i][jj])) continue;
      const int j = jlist[jj] & NEIGHMASK;
      double *v = pass.pair_values(i, jj);
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double r = sqrt(C::dot(d, d));
      if (r == 0.0) coincident(i, j);
      const double n[3] = {d[0] / r, d[1] / r, d[2] / r};
      const double qi = r * radius[i] / (radius[i] + radius[j]), qj = r - qi;
      double spin[3];
      for (int k = 0; k < 3; k++) spin[k] = dt * (qi * omega[i][k] + qj * omega[j][k]) / r;
      const C::Turn turn(spin);
      v[C::SIG] = linked_trial(i, j, v, d, n, r, moving ? &turn : nullptr);
      const McaMaterial &mi = scaled[type[i]], &mj = scaled[type[j]];
      const double s = McaResponse::of_pair(mi.strength, mi.damage, mj.strength, mj.damage)
                           .intact(v[C::KAPPA]) * v[C::AREA];
      const double *tau = v + C::TAU;
      double fi[3];
      for (int k = 0; k < 3; k++) fi[k] = s * (v[C::SIG] * n[k] + tau[k]);
      const double sym[6] = {n[0] * fi[0], n[1] * fi[1], n[2] * fi[2],
                             0.5 * (n[0] * fi[1] + n[1] * fi[0]),
                             0.5 * (n[0] * fi[2] + n[2] * fi[0]),
                             0.5 * (n[1] * fi[2] + n[2] * fi[1])};
      for (int k = 0; k < 6; k++) stress[i][k] += qi * sym[k];
      if (newton || j < nlocal)
        for (int k = 0; k < 6; k++) stress[j][k] += qj * sym[k];
    }
  }
  stress_to_owners(false);
  plasticity.return_map(stress, scaled, returned);
  comm_what = COMM_RETURNED;
  comm->forward_comm(this, 2);
}

// the element stresses summed onto their owners, divided by the volume (energy/volume) and
// converted to pressure units if asked
void PairMCA::stress_to_owners(bool to_pressure)
{
  comm_what = COMM_STRESS;
  if (force->newton_pair) comm->reverse_comm(this);
  const double scale = to_pressure ? force->nktv2p : 1.0;
  for (int i = 0; i < atom->nlocal; i++) {
    const double to_stress = scale / element_volume(i);
    for (int k = 0; k < 6; k++) stress[i][k] *= to_stress;
  }
}

/* ----------------------------------------------------------------------
   linked pair: F_i = (1 - D) S (sigma~ n + tau~), n from i to j, with
   sigma~ and tau~ from linked_trial() (tau~ += a du_t: the tangential slide
   of j's contact point relative to i's since the last evaluation, the
   stored stress turned with the contact's spin first: mca_contact.h);
   plasticity scales the deviatoric parts by phi = min(phi_i, phi_j) about
   the mean stress of the two elements and stores the plastic elongation;
   torques q_ij n x F_t on i and q_ji n x F_t on j, and the moment of the
   elements' relative rotation, (1 - D) K_ij on i and its opposite on j
   (mca_contact.h); energy (1 - D) (S (a e^2 / 2 + |tau~|^2 / (2a)) + the
   moment's) per pair plus
   lambda_i Omega_i theta_i^2 / 2 per element (manybody_energy).  From the
   stresses of this step (mca_response.h) a link that breaks transmits
   nothing from this step on; damage grows for the next one.
   unlinked pair: contact() below.
------------------------------------------------------------------------- */

void PairMCA::pair_forces(const StatePass &pass, StateTally &changes)
{
  double **x = atom->x, **f = atom->f, **torque = atom->torque, **omega = atom->omega;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton = force->newton_pair;
  const int plastic = plasticity.active();
  // a setup re-evaluates the same positions; a minimizer does not turn the elements
  const int moving = !update->setupflag && update->whichflag == 1;
  const double dt = update->dt;
  if (stress_wanted)
    for (int i = 0; i < nall; i++)
      for (int k = 0; k < STRESS_COLUMNS; k++) stress[i][k] = 0.0;
  if (responds)
    for (int i = 0; i < nall; i++) dtheta[i][0] = dtheta[i][1] = dtheta[i][2] = 0.0;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    const McaMaterial &mi = scaled[type[i]];
    const double ri = radius[i];
    const double ai = C::half_stiffness(mi.shear, ri);
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double rj = radius[j];
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double rsq = C::dot(d, d);
      int &word = pass.words[i][jj];
      const int linked = state_now(word);
      if (!linked && rsq >= (ri + rj) * (ri + rj)) {
        word = kept_word(word, false);    // an open contact keeps nothing
        continue;
      }
      if (rsq == 0.0) coincident(i, j);
      const double r = sqrt(rsq);
      const double n[3] = {d[0] / r, d[1] / r, d[2] / r};
      const McaMaterial &mj = scaled[type[j]];
      const double aj = C::half_stiffness(mj.shear, rj);
      const double a = C::series(ai, aj);
      const double qi = r * ri / (ri + rj), qj = r - qi;
      const double w = newton || j < nlocal ? 1.0 : 0.5;
      double spin[3];
      for (int k = 0; k < 3; k++) spin[k] = dt * (qi * omega[i][k] + qj * omega[j][k]) / r;
      const C::Turn turn(spin);    // of the pair's stored vectors (when the elements move)
      double *v = pass.pair_values(i, jj);
      double fi[3], ft[3], mom[3] = {0.0, 0.0, 0.0}, evdwl = 0.0;

      if (linked) {
        const McaResponse resp =
            McaResponse::of_pair(mi.strength, mi.damage, mj.strength, mj.damage);
        const double intact = resp.intact(v[C::KAPPA]);
        const double area = v[C::AREA];
        double *tau = v + C::TAU;
        double sigma = plastic ? v[C::SIG] : linked_trial(i, j, v, d, n, r, moving ? &turn : nullptr);
        const double phi = plastic ? std::min(returned[i][0], returned[j][0]) : 1.0;
        if (phi < 1.0) {
          // radial return of the transmitted stresses about the elements' mean stress
          const double mean = 0.5 * (returned[i][1] + returned[j][1]);
          const double back = (intact * sigma - mean) * (1.0 - phi) / intact;
          const double e_old = r - v[C::REF] - v[C::EPL], tau2_old = C::dot(tau, tau);
          v[C::EPL] += back / a;
          sigma -= back;
          for (int k = 0; k < 3; k++) tau[k] *= phi;
          const double e_new = e_old - back / a;
          changes.work[TALLY_PLASTIC] += w * intact * area *
              (0.5 * a * (e_old * e_old - e_new * e_new) + 0.5 * (tau2_old - C::dot(tau, tau)) / a);
          if (responds) {
            const double dv = -intact * area * back / a;
            dtheta[i][2] += dv * aj / (ai + aj);
            if (newton || j < nlocal) dtheta[j][2] += dv * ai / (ai + aj);
          }
        }
        double *rot = v + C::ROT;
        if (moving) {
          turn.apply(rot);
          for (int k = 0; k < 3; k++) rot[k] += dt * (omega[j][k] - omega[i][k]);
        }
        double moment[3];
        const double erot = C::moment(rot, n, a, area, moment);
        const double elong = r - v[C::REF] - v[C::EPL];
        const double tau2 = C::dot(tau, tau);
        const double epair = area * (0.5 * a * elong * elong + 0.5 * tau2 / a) + erot;

        // breaking (now) and damage (from the next step) at this step's stresses
        const double s = resp.active() ? McaResponse::equivalent(sigma, tau2) : 0.0;
        if (s > v[C::KAPPA]) {
          const int breaks = s >= resp.peak();
          const double lost = breaks ? intact : intact - resp.intact(s);
          if (responds) {
            const double dv = -lost * area * elong;
            const int col = breaks ? 0 : 1;
            dtheta[i][col] += dv * aj / (ai + aj);
            if (newton || j < nlocal) dtheta[j][col] += dv * ai / (ai + aj);
          }
          if (breaks) {    // from now on an unlinked pair, apart in tension
            changes.broken += w;
            changes.ejump += w * intact * epair;
            word = state_word(word, 0, pass.trial);
            continue;
          }
          changes.work[TALLY_DAMAGE] += w * lost * epair;
          v[C::KAPPA] = s;
        }
        for (int k = 0; k < 3; k++) {
          ft[k] = intact * area * tau[k];
          fi[k] = intact * area * sigma * n[k] + ft[k];
          mom[k] = intact * moment[k];
        }
        if (eflag_either) evdwl = intact * epair;
      } else {
        contact(i, j, word, v, d, n, r, moving ? &turn : nullptr, pass.trial, w, changes, fi, ft,
                evdwl);
      }

      const bool jown = newton || j < nlocal;
      double ti[3];
      C::cross(n, ft, ti);
      for (int k = 0; k < 3; k++) {
        f[i][k] += fi[k];
        torque[i][k] += qi * ti[k] + mom[k];
        if (jown) {
          f[j][k] -= fi[k];
          torque[j][k] += qj * ti[k] - mom[k];
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
    stress_atoms = atoms_fingerprint(atom);
    stress_to_owners(true);
  }
}

/* ----------------------------------------------------------------------
   unlinked pair closer than R_i + R_j: compression S_u a (r - R_i - R_j)
   on the face S_u of the harmonic mean radius, dry friction (the elastic
   tangential stress capped at mu |sigma_n|, kept while the contact lasts)
   and viscous friction eta v_t (mca_friction.h); pressed at the weld
   stress, the pair links at R_i + R_j (its force unchanged) from the next
   step, if its types may link
------------------------------------------------------------------------- */

void PairMCA::contact(int i, int j, int &word, double *v, const double *d, const double *n,
                      double r, const C::Turn *turn, int trial, double w, StateTally &changes,
                      double *fi, double *ft, double &evdwl)
{
  const double *radius = atom->radius;
  const int *type = atom->type;
  const McaMaterial &mi = scaled[type[i]], &mj = scaled[type[j]];
  const double ri = radius[i], rj = radius[j];
  const double ai = C::half_stiffness(mi.shear, ri), aj = C::half_stiffness(mj.shear, rj);
  const double a = C::series(ai, aj);
  const double area = C::unlinked_area(ri, rj);
  const double overlap = r - ri - rj;    // < 0
  const double sigma = a * overlap;
  const McaFriction fr =
      McaFriction::of_pair(mi.friction, mi.viscous, mi.weld, mj.friction, mj.viscous, mj.weld);
  double tau[3] = {0.0, 0.0, 0.0};
  if (fr.keeps_state()) {
    if (!(word & WORD_KEPT)) {    // a new contact
      for (int k = 0; k < C::NVALUES; k++) v[k] = 0.0;
      for (int k = 0; k < 3; k++) v[C::DPREV + k] = d[k];
      word = kept_word(word, true);
    }
    C::slide(v + C::TAU, v + C::DPREV, d, n, turn, a);
    changes.work[TALLY_FRICTION] += w * area * fr.cap(v + C::TAU, sigma, a);
    for (int k = 0; k < 3; k++) tau[k] = v[C::TAU + k];
  }
  const double tau2 = C::dot(tau, tau);
  double visc[3] = {0.0, 0.0, 0.0};
  if (fr.eta > 0.0 && update->whichflag == 1) {    // velocities mean nothing to a minimizer
    // the velocity of j's contact point relative to i's, tangential part
    double **vel = atom->v, **omega = atom->omega;
    const double qi = r * ri / (ri + rj), qj = r - qi;
    double wi[3], wj[3];
    C::cross(omega[i], n, wi);
    C::cross(omega[j], n, wj);
    double vr[3];
    for (int k = 0; k < 3; k++) vr[k] = vel[j][k] - vel[i][k] - qj * wj[k] - qi * wi[k];
    const double vn = C::dot(vr, n);
    for (int k = 0; k < 3; k++) visc[k] = fr.eta * (vr[k] - vn * n[k]);
    if (turn) changes.work[TALLY_FRICTION] += w * area * C::dot(visc, visc) / fr.eta * update->dt;
  }
  for (int k = 0; k < 3; k++) {
    ft[k] = area * (tau[k] + visc[k]);
    fi[k] = area * sigma * n[k] + ft[k];
  }
  if (eflag_either) evdwl = area * (0.5 * a * overlap * overlap + 0.5 * tau2 / a);

  // welding: the pair links where it is, with the contact's stresses (no jump of the pair's
  // force or energy; the many-body term gains the link: manybody_changes)
  if (fr.weld > 0.0 && -sigma >= fr.weld && linkable(type[i], type[j])) {
    v[C::REF] = ri + rj;
    v[C::AREA] = area;
    v[C::KAPPA] = v[C::EPL] = 0.0;
    v[C::ROT] = v[C::ROT + 1] = v[C::ROT + 2] = 0.0;
    word = state_word(kept_word(word, false), 1, trial);
    changes.formed += w;
    if (responds && setting.manybody) {
      const double dv = area * overlap;
      dtheta[i][0] += dv * aj / (ai + aj);
      if (force->newton_pair || j < atom->nlocal) dtheta[j][0] += dv * ai / (ai + aj);
    }
  }
}

/* ----------------------------------------------------------------------
   the many-body energy the changes of this step take: theta_i moves by the
   changes of state (column 0: breaking, welding), damage (1) and plastic
   flow (2); lambda_i Omega_i theta_i^2 / 2 at the changed theta, less at
   the old one, is tallied with each in that order
------------------------------------------------------------------------- */

void PairMCA::manybody_changes(StateTally &changes)
{
  comm_what = COMM_DTHETA;
  if (force->newton_pair) comm->reverse_comm(this, 3);
  const int *type = atom->type;
  const double *theta = sums;
  for (int i = 0; i < atom->nlocal; i++) {
    const double omega = element_volume(i);
    const double half = 0.5 * scaled[type[i]].lambda * omega;
    double now = theta[i], e_now = half * now * now;
    double released[3];
    for (int c = 0; c < 3; c++) {
      now += dtheta[i][c] / omega;
      const double e = half * now * now;
      released[c] = e_now - e;
      e_now = e;
    }
    changes.ejump += released[0];
    changes.work[TALLY_DAMAGE] += released[1];
    changes.work[TALLY_PLASTIC] += released[2];
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
  // link yes|no (last): whether elements of types I and J link when they touch
  if (narg >= 4 && strcmp(arg[narg - 2], "link") == 0) {
    const std::string v = arg[narg - 1];
    if (v != "yes" && v != "no")
      error->all(FLERR, "{}: link must be yes or no (got '{}')", who, v);
    const int np1 = atom->ntypes + 1;
    for (int i = ilo; i <= ihi; i++)
      for (int j = jlo; j <= jhi; j++) unlinkable[i * np1 + j] = unlinkable[j * np1 + i] = v == "no";
    narg -= 2;
    if (narg == 2) return;
  }
  if (ilo != jlo || ihi != jhi)
    error->all(FLERR, "{}: a material belongs to an element type: give pair_coeff I I (got {} "
               "{}); a pair of two types takes each element's own (pair_coeff I J link yes|no "
               "sets whether they link)", who, arg[0], arg[1]);
  const McaMaterial m = McaMaterial::read(who, narg - 2, arg + 2, lmp);
  for (int i = ilo; i <= ihi; i++) {
    material[i] = m;
    material_set[i] = 1;
  }
}

// the moduli in energy/volume (pressure units / nktv2p), as the kernel uses them
void PairMCA::scale_materials()
{
  scaled.clear();
  responds = 0;
  for (const McaMaterial &m : material) {
    scaled.push_back(m.scaled(1.0 / force->nktv2p));
    if (m.strength > 0.0 || m.yield > 0.0 || m.weld > 0.0) responds = 1;
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
  plasticity.init(material);
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
  target[C::KAPPA] = source[C::KAPPA];
  target[C::EPL] = source[C::EPL];
  target[C::SIG] = source[C::SIG];
  for (int k = 0; k < 3; k++) {
    target[C::TAU + k] = -source[C::TAU + k];
    target[C::DPREV + k] = -source[C::DPREV + k];
    target[C::ROT + k] = -source[C::ROT + k];
  }
  state.transfer_word(source, target);
}

void *PairMCA::extract(const char *name, int &dim)
{
  dim = -1;    // an object, not a parameter: fix adapt refuses dimensions other than 0 and 2
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
  fwrite(unlinkable.data(), sizeof(int), unlinkable.size(), fp);
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
  if (comm->me == 0)
    utils::sfread(FLERR, unlinkable.data(), sizeof(int), unlinkable.size(), fp, nullptr, error);
  MPI_Bcast(unlinkable.data(), unlinkable.size(), MPI_INT, 0, world);
}

void PairMCA::write_restart_settings(FILE *fp)
{
  const int layout = C::NVALUES;    // a pair's doubles: restarts of another layout are refused
  fwrite(&layout, sizeof(int), 1, fp);
  setting.write_restart(fp);
  state.write_restart(fp);
}

void PairMCA::read_restart_settings(FILE *fp)
{
  int layout = 0;
  if (comm->me == 0) utils::sfread(FLERR, &layout, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&layout, 1, MPI_INT, 0, world);
  if (layout != C::NVALUES)
    error->all(FLERR, "Pair mca: the restart file was written by another version of the plugin "
               "(its pairs keep another state): start from a data file, the links are made anew");
  setting.read_restart(fp, lmp);
  state.enable();
  state.read_restart(fp);
}

// link no of a type with itself rides on its line; of two types only in write_data ... pair ij
void PairMCA::write_data(FILE *fp)
{
  const int np1 = atom->ntypes + 1;
  for (int i = 1; i < np1; i++)
    fmt::print(fp, "{} {}{}\n", i, material[i].words(), linkable(i, i) ? "" : " link no");
  for (int i = 1; i < np1; i++)
    for (int j = i + 1; j < np1; j++)
      if (!linkable(i, j) && comm->me == 0)
        error->warning(FLERR, "Pair mca: write_data keeps 'pair_coeff {} {} link no' only with "
                       "the keyword pair ij", i, j);
}

void PairMCA::write_data_all(FILE *fp)
{
  const int np1 = atom->ntypes + 1;
  for (int i = 1; i < np1; i++)
    for (int j = i; j < np1; j++) {
      if (i == j) fmt::print(fp, "{} {} {}{}\n", i, i, material[i].words(), linkable(i, i) ? "" : " link no");
      else fmt::print(fp, "{} {} link {}\n", i, j, linkable(i, j) ? "yes" : "no");
    }
}

/* ---------------------------------------------------------------------- */

int PairMCA::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  int m = 0;
  if (comm_what == COMM_RETURNED) {
    for (int i = 0; i < n; i++) {
      buf[m++] = returned[list[i]][0];
      buf[m++] = returned[list[i]][1];
    }
  } else {
    for (int i = 0; i < n; i++) buf[m++] = sums[list[i]];
  }
  return m;
}

void PairMCA::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  if (comm_what == COMM_RETURNED) {
    for (int i = first; i < first + n; i++) {
      returned[i][0] = buf[m++];
      returned[i][1] = buf[m++];
    }
  } else {
    for (int i = first; i < first + n; i++) sums[i] = buf[m++];
  }
}

int PairMCA::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (comm_what == COMM_STRESS)
      for (int k = 0; k < STRESS_COLUMNS; k++) buf[m++] = stress[i][k];
    else if (comm_what == COMM_DTHETA)
      for (int k = 0; k < 3; k++) buf[m++] = dtheta[i][k];
    else
      buf[m++] = sums[i];
  }
  return m;
}

void PairMCA::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int i = 0; i < n; i++) {
    const int to = list[i];
    if (comm_what == COMM_STRESS)
      for (int k = 0; k < STRESS_COLUMNS; k++) stress[to][k] += buf[m++];
    else if (comm_what == COMM_DTHETA)
      for (int k = 0; k < 3; k++) dtheta[to][k] += buf[m++];
    else
      sums[to] += buf[m++];
  }
}

double PairMCA::memory_usage()
{
  return (double) nmax * (1 + STRESS_COLUMNS + 2 + 3) * sizeof(double);
}
