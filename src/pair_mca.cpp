/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair_style mca (see pair_mca.h).

   One force evaluation, as pair eam's: (a setup only) link the pairs of
   fresh elements and give them their contact areas; the volumetric strain
   of each element from its linked pairs, summed onto owners and sent to
   ghosts; (plasticity) the trial pair stresses, the elements' stresses
   from them and their radial return; then the pair forces and torques,
   with damage, breaking, friction and welding; last the energy that the
   changes of state took from the many-body term.
------------------------------------------------------------------------- */

#include "pair_mca.h"

#include "mca_link_turns.h"
#include "mca_linked_pair.h"
#include "mca_pressure_pair.h"
#include "mca_unlinked_pair.h"
#include "skin_check.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

using C = McaContact;

PairMCA::PairMCA(LAMMPS *lmp) :
    PairColumnExchange(lmp), types(lmp), guard(lmp), plasticity(lmp, *this), manybody(lmp, *this), stress(lmp, *this),
    eos(lmp, *this), stiffness(lmp), state(lmp, this, "Pair mca", C::NVALUES, NWORK), tracks_changes(false), linking(lmp, *this), segments(lmp), report(lmp), full(nullptr)
{
  single_enable = 0;
  restartinfo = 1;
  writedata = 1;
  manybody_flag = 1;
  nondefault_history_transfer = 1;
  beyond_contact = 1;    // fix neigh/history keeps every listed pair's state, not only contacts
  // the plastic trial, the step's motion and slide: written by the passes before they are read
  state.within_compute({C::SIG, C::DR, C::DTAU});
  // the most columns a component sends to ghosts or sums onto owners (PairColumnExchange)
  comm_forward = std::max<int>(McaPlasticity::COLUMNS, McaElementEos::FORWARD);
  comm_reverse = std::max<int>(std::max<int>(McaElementStress::COLUMNS, McaManybody::NCHANGES),
                               McaElementEos::SUMS);
  // pvector: broken links, links formed, the energy of those changes, then the energy dissipated
  // by damage, by plastic flow and by friction (McaWork; all since the links were made)
  nextra = 3 + NWORK;
  pvector = new double[nextra]();
}

PairMCA::~PairMCA()
{
  delete[] pvector;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairMCA::grow()
{
  manybody.grow(atom->nmax);
  stress.grow(atom->nmax);
  plasticity.grow(atom->nmax);
  if (eos.active()) eos.grow(atom->nmax);
  stiffness.grow(atom->nmax);
}

/* ---------------------------------------------------------------------- */

void PairMCA::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const StatePass pass = state.begin();
  grow();
  stiffness.compute(types.scaled(), eos.active());
  guard.each_step();
  if (pass.fresh) linking.make(list, pass, types, setting.tolerance, setting.fraction);
  if (update->setupflag && update->whichflag == 1) guard.at_setup(types.scaled(), setting.fraction);
  if (setting.manybody) volumetric_strain(pass);
  if (plasticity.active()) plastic_trial(pass);
  StateTally changes;
  pair_forces(pass, changes);
  if (segments.active())
    segments.compute(full, stiffness.halves(), setting.tolerance, elements_turn(), update->dt, changes,
                     *this, stress.wanted() ? &stress : nullptr);
  if (stress.wanted()) stress.to_owners(true);
  if (tracks_changes)
    manybody.tally_changes(changes, WORK_DAMAGE, WORK_PLASTIC, eos.heat_shares());
  if (eos.active()) eos.finish_heat();
  if (setting.manybody && eflag) manybody.tally_energy(eflag_global ? &eng_vdwl : nullptr,
                                                       eflag_atom ? eatom : nullptr);
  if (eos.active() && eflag)
    eos.tally_energy(eflag_global ? &eng_vdwl : nullptr, eflag_atom ? eatom : nullptr);
  if (vflag_fdotr) virial_fdotr_compute();
  state.end(changes, pvector);
}

// theta of every element from the elongations of its linked pairs (mca_manybody.h); with a
// shock law, its shape and velocity sums, then its volume, energy and pressure
// (mca_element_eos.h)
void PairMCA::volumetric_strain(const StatePass &pass)
{
  const int nlocal = atom->nlocal;
  const int newton = force->newton_pair;
  const bool pressure = eos.active(), moving = elements_turn();
  manybody.begin_strain(nlocal + atom->nghost);
  if (pressure) eos.begin(nlocal + atom->nghost);
  walk_pairs(list, pass, [&](int i, int j, int jj) {
    if (!state_now(pass.words[i][jj])) return;
    double *v = pass.pair_values(i, jj);
    const McaPairFrame p(atom->x, i, j);
    const McaResponse &resp = types.model(atom->type[i], atom->type[j]).response;
    const double carried = resp.intact(v[C::KAPPA]) * v[C::AREA], r = sqrt(p.rsq);
    const double elong = carried * McaLinkedPair::elongation(v, r);
    const bool jown = newton || j < nlocal;
    manybody.add_elongation(i, j, elong, stiffness.pair(i, j), jown);
    if (pressure) {
      eos.add_pair(i, j, p.d, v + C::DPREV, carried / v[C::REF], jown);
      v[C::DR] = moving ? C::motion(v, r) : 0.0;
      v[C::HG] += v[C::DR];    // less the affine part: later
    }
  });
  manybody.finish_strain();
  if (!pressure) return;
  eos.finish(moving ? McaElementEos::STEP
                    : (update->setupflag && update->whichflag == 1 ? McaElementEos::MOVED
                                                                    : McaElementEos::NONE),
             update->dt);
  // a shock-law element whose links span no volume (a pair, a chain, a sheet) has no pressure:
  // its pairs take the linear law's volumetric response, lambda = K - 2G/3, instead
  const int *type = atom->type;
  for (int i = 0; i < nlocal + atom->nghost; i++)
    if (eos.has_law(type[i]) && !eos.has_volume(i))
      manybody.add_modulus(i, types.scaled()[type[i]].bulk);
}

/* ----------------------------------------------------------------------
   plasticity: every linked pair's trial stresses (tau stored, sigma in
   SIG) and its relative rotation turned (side by side, mca_link_turns.h),
   the elements' stresses from them (Love's formula, in the list's order),
   then each element's radial return factor and mean stress, to ghosts
------------------------------------------------------------------------- */

void PairMCA::plastic_trial(const StatePass &pass)
{
  double **omega = atom->omega;
  const double *radius = atom->radius;
  const int nlocal = atom->nlocal;
  const int newton = force->newton_pair;
  const bool moving = elements_turn();
  const double dt = update->dt;
  stress.zero(nlocal + atom->nghost);
  McaLinkTurns links;
  const auto trials = [&] {
    links.advance();
    for (int b = 0; b < links.size(); b++) {
      const int i = links.i(b), j = links.j(b);
      double *v = links.values(b);
      const McaPairHalves halves = stiffness.pair(i, j);
      v[C::SIG] = normal_trial(i, j, v, links.pair(b).r, halves);
      const double intact = types.model(atom->type[i], atom->type[j]).response.intact(v[C::KAPPA]);
      stress.add_trial(i, j, links.pair(b), v, intact, halves, newton || j < nlocal);
    }
    links.clear();
  };
  walk_pairs(list, pass, [&](int i, int j, int jj) {
    if (!state_now(pass.words[i][jj])) return;
    double *v = pass.pair_values(i, jj);
    McaPairFrame p(atom->x, i, j);
    if (p.rsq == 0.0) coincident_elements(lmp, i, j);
    p.orient(radius[i], radius[j]);
    // this step's motion of the pair, for the trapezoid rule of the plastic work (with a shock
    // law the volume pass has taken it)
    if (!eos.active()) v[C::DR] = moving ? C::motion(v, sqrt(p.rsq)) : 0.0;
    if (links.add(i, j, v, p, stiffness.pair(i, j).series(), omega[i], omega[j], dt, moving))
      trials();
  });
  trials();
  stress.to_owners(false);
  plasticity.return_map(stress.trial(), types.scaled());
}

/* ----------------------------------------------------------------------
   every pair's forces and torques: a linked pair by its law
   (mca_linked_pair.h: sigma~ from this step's trial, returned by plastic
   flow, then damage and breaking), an unlinked pair closer than
   its contact distance by its contact (mca_unlinked_pair.h); torques q_ij n x F_t on
   i and q_ji n x F_t on j, and a link's moment on i and its opposite on
   j; the energy of each pair (the elements': compute())
------------------------------------------------------------------------- */

void PairMCA::pair_forces(const StatePass &pass, StateTally &changes)
{
  double **f = atom->f, **torque = atom->torque, **omega = atom->omega;
  const double *radius = atom->radius;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton = force->newton_pair;
  const int plastic = plasticity.active();
  const bool moving = elements_turn();
  // a minimizer's velocities mean nothing
  double **vel = update->whichflag == 1 ? atom->v : nullptr;
  const double dt = update->dt;
  const McaPressurePair pressure{eos, stiffness, atom->type, moving};
  if (stress.wanted()) stress.zero(nall);
  if (tracks_changes) manybody.begin_changes(nall);
  if (eos.active()) eos.begin_heat(nall);
  const McaElementShares volumes = tracks_changes ? manybody.volume_changes() : McaElementShares(),
                         heat = eos.heat_shares();

  walk_pairs(list, pass, [&](int i, int j, int jj) {
    const double ri = radius[i], rj = radius[j];
    McaPairFrame p(atom->x, i, j);
    int &word = pass.words[i][jj];
    const int linked = state_now(word);
    const double contact =
        linked ? 0.0 : McaUnlinkedPair::contact_distance(word, pass.pair_values(i, jj), ri, rj);
    if (!linked && segments.between(atom->type[i], atom->type[j])) {
      word = kept_word(word, false);
      return;
    }
    if (!linked && p.rsq >= contact * contact) {    // an open contact
      word = McaUnlinkedPair::open(word, pass.pair_values(i, jj), p.rsq, p.d, ri + rj);
      return;
    }
    if (p.rsq == 0.0) coincident_elements(lmp, i, j);
    p.orient(ri, rj);
    const McaPairHalves halves = stiffness.pair(i, j);
    const double a = halves.series();
    const bool jown = newton || j < nlocal;
    const McaPairTally tally{changes, jown ? 1.0 : 0.5, volumes, i, j, halves, jown, heat};
    // the turn of the pair's stored vectors; a link's, with plasticity, turned in the plastic pass
    const bool turned = linked && plastic;
    const C::Turn turn = moving && !turned ? p.turn(omega[i], omega[j], dt) : C::Turn();
    const C::Turn *turning = moving && !turned ? &turn : nullptr;
    const McaPairModel &model = types.model(atom->type[i], atom->type[j]);
    double *v = pass.pair_values(i, jj);
    McaPairForce out;
    if (linked) {
      McaLinkedPair link(model.response, v, a, domain->dimension == 2);
      const double sigma = plastic ? v[C::SIG] : trial_stresses(i, j, v, p, turning, halves);
      // with a shock law (and a volume) on either side the pair takes its elements' pressure;
      // on both, it returns its deviator about zero and has the hourglass spring; an element
      // of the shock law without a volume acts as one of the linear law (volumetric_strain)
      const bool si = eos.has_law(atom->type[i]) && eos.has_volume(i);
      const bool sj = eos.has_law(atom->type[j]) && eos.has_volume(j);
      const double phi = plastic ? plasticity.phi(i, j) : 1.0;
      const double mean = phi < 1.0 && !(si && sj) ? plasticity.mean(i, j) : 0.0;
      // the links' elongation over the step, for the plastic work's share of the many-body lag
      if (plastic) tally.volume_change(McaManybody::MOTION, link.intact * v[C::AREA] * v[C::DR]);
      McaPressureLoad load;
      double ehg = 0.0;
      if (si || sj) ehg = pressure.load(i, j, v, p, si && sj, load);
      if (!link.step(sigma, phi, mean, p, turning, omega[i], omega[j], dt, tally, eflag_either,
                     si || sj ? &load : nullptr, out)) {
        word = state_word(word, 0, pass.trial);    // from now on an unlinked pair
        if (!pass.trial)
          word = McaUnlinkedPair::left_by_break(word, v, p, ri, rj, a, domain->dimension, tally);
        return;
      }
      if (eflag_either) out.evdwl += link.intact * ehg;
    } else {
      McaUnlinkedPair(ri, rj, contact, a, p.r, domain->dimension)
          .step(model, word, pass.trial, pass.claim(i, jj), p, turning, a, vel, omega, dt, tally,
                eflag_either, out);
    }

    double ti[3];
    C::cross(p.n, out.ft, ti);
    for (int k = 0; k < 3; k++) {
      f[i][k] += out.fi[k];
      torque[i][k] += p.qi * ti[k] + out.mom[k];
      if (jown) {
        f[j][k] -= out.fi[k];
        torque[j][k] += p.qj * ti[k] - out.mom[k];
      }
    }
    if (evflag)
      ev_tally_xyz(i, j, nlocal, newton, out.evdwl, 0.0, out.fi[0], out.fi[1], out.fi[2], -p.d[0],
                   -p.d[1], -p.d[2]);
    if (stress.wanted()) {
      double sym[6];
      McaElement::dyad(p.n, out.fi, sym);
      stress.add(i, p.qi, sym, linked);
      if (jown) stress.add(j, p.qj, sym, linked);
    }
  });
}

// a setup re-evaluates the same positions; a minimizer does not turn the elements
bool PairMCA::elements_turn() const
{
  return !update->setupflag && update->whichflag == 1;
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

void PairMCA::allocate()
{
  allocated = 1;
  const int np1 = atom->ntypes + 1;
  memory->create(setflag, np1, np1, "pair:setflag");
  memory->create(cutsq, np1, np1, "pair:cutsq");
  // a material belongs to a type: every pair is set once both types have one (init_one)
  for (int i = 1; i < np1; i++)
    for (int j = i; j < np1; j++) setflag[i][j] = 1;
  types.allocate();
  segments.allocate(atom->ntypes);
}

// pair_coeff I I bulk K shear G ... | I J link yes|no (mca_type_table.h) | I J segments ...
// (mca_segment_contact.h)
void PairMCA::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  if (narg >= 3 && strcmp(arg[2], "segments") == 0) {
    segments.coeff(narg, arg);
    return;
  }
  if (narg >= 4 && strcmp(arg[narg - 2], "link") == 0) segments.refuse_link(arg);
  types.coeff(narg, arg);
}

void PairMCA::init_style()
{
  guard.check_style(tail_flag, offset_flag, setting.plane);
  guard.init();
  types.init(setting.plane == McaSettings::STRESS);
  guard.check_shock(types.as_given(), setting.manybody);
  tracks_changes = setting.manybody && types.responds();
  manybody.init(types.scaled(), setting.fraction);
  eos.init(types.scaled(), setting.fraction);
  stress.init(setting.fraction);
  plasticity.init(types.as_given(), setting.plane == McaSettings::STRAIN);
  segments.init();
  report.print(types, setting.fraction);
  state.explain_lost_links([this] { return eos.lost_links_reason(); });
  neighbor->add_request(this, NeighConst::REQ_HISTORY);
  if (segments.active()) neighbor->add_request(this, NeighConst::REQ_FULL)->set_id(1);
  state.keep_state_within(guard.state_reach(setting.tolerance));
  state.init();
}

// called for every type pair (for the type pairs pair_style hybrid gives this style): the
// pair's model, and its cutoff from the largest elements of the two types
double PairMCA::init_one(int i, int j)
{
  types.make_model(i, j, segments.between(i, j));
  const double cut = fmax(McaSettings::REACH * (1.0 + setting.tolerance) *
                              (guard.largest_radius(i) + guard.largest_radius(j)),
                          segments.cutoff(i, j, guard.largest_radius(i), guard.largest_radius(j),
                                          setting.tolerance));
  if (i == j && cut > 0.0) check_neighbor_skin(lmp, cut, "Pair mca");
  return cut;
}

/* ---------------------------------------------------------------------- */

void PairMCA::init_list(int id, NeighList *ptr)
{
  if (id == 1) full = ptr;
  else list = ptr;
}

void PairMCA::transfer_history(double *source, double *target, int, int)
{
  C::partner_copy(source, target);
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
  types.write_restart(fp);
  segments.write_restart(fp);
}

void PairMCA::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  types.read_restart(fp);    // into the table allocate() made
  segments.read_restart(fp);
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

// the materials per type; a pair of types that meets by segments needs the keyword pair ij
void PairMCA::write_data(FILE *fp)
{
  types.write_data(fp);
  if (segments.active() && comm->me == 0)
    error->warning(FLERR, "Pair mca: write_data keeps 'pair_coeff I J segments' only with the "
                   "keyword pair ij");
}

// one line per type pair: the segment law where two types meet by segments, else the material
// or the link flag
void PairMCA::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (!segments.write_data_line(fp, i, j)) types.write_data_line(fp, i, j);
}

double PairMCA::memory_usage()
{
  return stiffness.memory_usage() + manybody.memory_usage() + stress.memory_usage() +
      plasticity.memory_usage() + eos.memory_usage();
}
