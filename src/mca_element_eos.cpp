/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the pressure of the elements of
   pair_style mca with a shock equation of state (see mca_element_eos.h).
------------------------------------------------------------------------- */

#include "mca_element_eos.h"

#include "mca_element.h"
#include "mca_element_shape.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix_property_atom.h"
#include "force.h"
#include "memory.h"
#include "modify.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

McaElementEos::McaElementEos(LAMMPS *lmp, McaExchange &exchange) :
    Pointers(lmp), exchange(exchange), sums(nullptr), pressures(nullptr), heat(nullptr), nmax(0), fraction(1.0),
    scaled(nullptr), store(nullptr), made(false), dvolume(-1), energy(-1), visc(-1), damaged(-1),
    heated(-1)
{
}

McaElementEos::~McaElementEos()
{
  memory->destroy(sums);
  memory->destroy(heat);
  // the elements' state goes with the style (a new pair_style starts afresh), as pair
  // granular's history
  if (made && modify->nfix && modify->get_fix_by_id(FIX_ID)) modify->delete_fix(FIX_ID);
}

void McaElementEos::init(const std::vector<McaMaterial> &materials, double packing_fraction)
{
  scaled = &materials;
  fraction = packing_fraction;
  laws.clear();
  kinetics.clear();
  bool any = false;
  for (const McaMaterial &m : materials) any = any || m.shock();
  if (!any) return;
  for (const McaMaterial &m : materials) {
    laws.push_back(m.shock() ? McaShockEos{m.bulk, m.slope, m.gruneisen, m.b1, m.b2}
                             : McaShockEos{});
    kinetics.push_back(m.kinetic() ? McaSpallKinetics::of_rate_law(m.spall, m.spall_rate,
                                                                     m.spall_m, m.bulk)
                                   : McaSpallKinetics{});
  }
  store = dynamic_cast<FixPropertyAtom *>(modify->get_fix_by_id(FIX_ID));
  if (!store && made)
    error->all(FLERR, "Pair mca: fix {} (the elements' volume, internal energy, viscosity and "
               "damage of their shock equation of state) was removed: re-issue pair_style mca "
               "to start afresh", FIX_ID);
  if (!store)
    store = dynamic_cast<FixPropertyAtom *>(modify->add_fix(fmt::format(
        "{} all property/atom d_mca_dvolume d_mca_energy d_mca_viscosity d_mca_damage "
        "d_mca_heat", FIX_ID)));
  made = true;
  // not in data files: read_data would meet the section before the style makes the fix
  // (a data file starts the elements at J = 1, u = 0; restart files keep them)
  if (store) store->wd_section = 0;
  int flag, cols;
  dvolume = atom->find_custom("mca_dvolume", flag, cols);
  energy = atom->find_custom("mca_energy", flag, cols);
  visc = atom->find_custom("mca_viscosity", flag, cols);
  damaged = atom->find_custom("mca_damage", flag, cols);
  heated = atom->find_custom("mca_heat", flag, cols);
  if (!store || dvolume < 0 || energy < 0 || visc < 0 || damaged < 0 || heated < 0)
    error->all(FLERR, "Pair mca: the elements' equation-of-state state (fix {} property/atom "
               "d_mca_dvolume d_mca_energy d_mca_viscosity d_mca_damage d_mca_heat) is missing "
               "or taken", FIX_ID);
  check_densities();
}

void McaElementEos::grow(int nmax_atoms)
{
  if (nmax_atoms <= nmax) return;
  nmax = nmax_atoms;
  memory->destroy(sums);
  memory->destroy(heat);
  memory->create(heat, nmax, 1, "pair:eos_heat");
  memory->create(sums, nmax, SUMS, "pair:eos_sums");
  pressures = sums;    // finish() reads an element's sums before it writes its pressures
}

double McaElementEos::memory_usage() const
{
  return (double) nmax * (SUMS + 1) * sizeof(double);
}

double McaElementEos::volume(int i) const
{
  return McaElement::volume(atom->radius[i], fraction, domain->dimension);
}

// the mass of an element is rho0 Omega ("set density rho0/F"): an element of another density
// would carry its pressure at the wrong sound speed
void McaElementEos::check_densities() const
{
  const int *type = atom->type;
  int bad = -1;
  double found = 0.0, wanted = 0.0;
  for (int i = 0; i < atom->nlocal && bad < 0; i++) {
    const McaMaterial &m = (*scaled)[type[i]];
    if (!m.shock() || atom->radius[i] <= 0.0) continue;
    const double rho = atom->rmass[i] / volume(i);
    if (std::fabs(rho / m.rho0 - 1.0) > 1.0e-3) {
      bad = type[i];
      found = rho;
      wanted = m.rho0;
    }
  }
  int any = bad, worst;
  MPI_Allreduce(&any, &worst, 1, MPI_INT, MPI_MAX, world);
  if (worst < 0) return;
  if (bad >= 0)
    error->one(FLERR, "Pair mca: elements of type {} have the density {:.6g} (mass / element "
               "volume), not their shock rho0 {:.6g}: give them 'set ... density rho0/F' with F "
               "the fraction", bad, found, wanted);
  error->all(FLERR, "Pair mca: elements have another density than their shock rho0");
}

void McaElementEos::begin(int nall)
{
  if (nall > 0) memset(sums[0], 0, sizeof(double) * nall * SUMS);    // memory->create: one block
}

void McaElementEos::finish(Advance how, double dt)
{
  exchange.to_owners(sums, SUMS);
  for (int i = 0; i < atom->nlocal; i++)
    if (!advance_element(i, how, dt))
      for (int k = 0; k < FORWARD; k++) pressures[i][k] = 0.0;
  exchange.to_ghosts(pressures, FORWARD);
}

namespace {
// the shape sums at the last evaluation's separations: K' = K - M - M^T + N, M' = M - N
void last_shape(const double *s, double *last)
{
  const double *n = s + McaElementEos::MOVES, *mm = s + 6;
  const double v[15] = {s[0] - 2.0 * mm[0] + n[0], s[1] - 2.0 * mm[4] + n[1],
                        s[2] - 2.0 * mm[8] + n[2], s[3] - mm[1] - mm[3] + n[3],
                        s[4] - mm[2] - mm[6] + n[4], s[5] - mm[5] - mm[7] + n[5],
                        mm[0] - n[0], mm[1] - n[3], mm[2] - n[4],
                        mm[3] - n[3], mm[4] - n[1], mm[5] - n[5],
                        mm[6] - n[4], mm[7] - n[5], mm[8] - n[2]};
  for (int k = 0; k < 15; k++) last[k] = v[k];
}

double trace(const double g[3][3])
{
  return g[0][0] + g[1][1] + g[2][2];
}

// det(I + g)
double stretch(const double g[3][3])
{
  const double a[3][3] = {{1.0 + g[0][0], g[0][1], g[0][2]},
                          {g[1][0], 1.0 + g[1][1], g[1][2]},
                          {g[2][0], g[2][1], 1.0 + g[2][2]}};
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
      a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
      a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}
}    // namespace

// element i over a step of dt, or a move between runs, or neither (finish()): its volume ratio
// and energy, its pressure tensor P = (p + q) Omega J K^-1 and displacement gradient; false: it
// has no shock law or no volume.  A step advances J by exp((tr H' + tr H) / 2) (H' the
// gradient at the last step's separations, H at this step's); a move between runs, of any size,
// by det(I + H'), exact for a homogeneous one, and is checked against the pole even where the
// moved element's links no longer span a volume.  With spall kinetics a step advances D at the
// new state's tension, and the energy follows the transmitted pressure at the old and new D
// (the forces of the two steps).  The old pressure is the one the last step's forces took: before
// that step's plastic heat (h, added after them), p(J0, u0 - h).
bool McaElementEos::advance_element(int i, Advance how, double dt)
{
  const int type = atom->type[i];
  const McaSpallKinetics &spall = kinetics[type];
  // a type whose material has (now) no kinetics holds no damage: a pair_coeff that takes it
  // away, or gives the type the linear law, starts its elements afresh at D = 0
  double &dmg = atom->dvector[damaged][i];
  if (!spall.active()) dmg = 0.0;
  if (laws[type].bulk == 0.0) return false;
  const McaShockEos &law = laws[type];
  const double *s = sums[i];
  double &dvol = atom->dvector[dvolume][i], &u = atom->dvector[energy][i];
  double &q = atom->dvector[visc][i];
  double inv[6], grad[3][3], last[15], inv0[6], grad0[3][3];
  const bool shaped = McaElementShape::invert(s, inv);
  if (shaped) McaElementShape::gradient(s, inv, grad);
  bool had_shape = false;
  if (how != NONE) {
    last_shape(s, last);
    had_shape = McaElementShape::invert(last, inv0);
    if (had_shape) McaElementShape::gradient(last, inv0, grad0);
    if (how == MOVED && had_shape && !((1.0 + dvol) * stretch(grad0) > law.limit()))
      beyond_limit(i, (1.0 + dvol) * stretch(grad0));
  }
  if (!shaped) {
    q = 0.0;
    atom->dvector[heated][i] = 0.0;    // no pressure: the heat is in u alone
    return false;
  }
  double *out = pressures[i];    // the row of s, which is read no more
  const double sym[6] = {grad[0][0], grad[1][1], grad[2][2], 0.5 * (grad[0][1] + grad[1][0]),
                         0.5 * (grad[0][2] + grad[2][0]), 0.5 * (grad[1][2] + grad[2][1])};
  for (int k = 0; k < 6; k++) out[GRADIENT + k] = sym[k];
  out[HAS_VOLUME] = 1.0;
  double j1 = 1.0 + dvol;
  if (how != NONE) {
    // the last step's gradient (as this one's where its separations spanned no volume)
    const double now = trace(grad), before = had_shape ? trace(grad0) : now;
    const McaMaterial &m = (*scaled)[type];
    const double j0 = j1;
    j1 = how == MOVED && had_shape ? j0 * stretch(grad0) : j0 * exp(0.5 * (before + now));
    if (!(j1 > law.limit())) beyond_limit(i, j1);
    const double p0 = law.pressure(j0, u) - law.gamma * atom->dvector[heated][i];
    const double w0 = 0.5 * (McaSpallKinetics::transmitted(p0, dmg) + q) * j0 * before;
    if (how == STEP)
      q = force->mvv2e * law.viscosity(-0.5 * (before + now) / dt, m.rho0 / j1, m.c0,
                                        2.0 * atom->radius[i]);
    const double u_whole = law.energy_after(u, w0, j1, q, 0.5 * j1 * now);
    const double tension = -law.pressure(j1, u_whole);
    if (how == STEP && spall.active()) dmg = spall.advance(dmg, -p0, tension, dt);
    u = tension > 0.0 && dmg > 0.0
        ? law.energy_after(u, w0, j1, q, 0.5 * j1 * now, 1.0 - dmg)
        : u_whole;
    dvol = j1 - 1.0;
  }
  atom->dvector[heated][i] = 0.0;    // these forces take the heat
  const double pressure = McaSpallKinetics::transmitted(law.pressure(j1, u), dmg) + q,
               scale = pressure * volume(i) * j1;
  for (int k = 0; k < 6; k++) out[k] = scale * inv[k];
  out[MEAN] = q - pressure;    // -p
  out[DAMAGE] = dmg;
  return true;
}

void McaElementEos::beyond_limit(int i, double ratio) const
{
  const McaShockEos &law = laws[atom->type[i]];
  error->one(FLERR, "Pair mca: element {} compressed to V/V0 = {:.4g}, beyond the limit 1 - 1/s "
             "= {:.4g} of its shock equation of state (a shock too strong for this s, or a time "
             "step too long, or a box change or displacement between runs)", atom->tag[i], ratio,
             law.limit());
  std::abort();    // not reached: error->one() throws
}

// a lattice of elements compressed slowly along one axis buckles near V/V0 = 0.62-0.64 (fix
// deform on fcc [100] aluminium, with and without yield), long before the pole: its elements
// scatter and their links leave the list
std::string McaElementEos::lost_links_reason() const
{
  if (!active()) return "";
  double mine = 1.0, least;
  for (int i = 0; i < atom->nlocal; i++)
    if (laws[atom->type[i]].bulk > 0.0) mine = MIN(mine, 1.0 + atom->dvector[dvolume][i]);
  MPI_Allreduce(&mine, &least, 1, MPI_DOUBLE, MPI_MIN, world);
  if (least > 0.8) return "";
  return fmt::format("the shock-law elements are compressed to V/V0 = {:.3g} at the least: a "
                     "lattice of elements compressed below about 0.65 of its volume along one "
                     "axis (fix deform, a piston) buckles under its pressure forces whatever the "
                     "time step (measured: fcc [100], aluminium, at 0.62-0.64 with and without "
                     "yield), and its elements scatter; it is the model's limit, not the skin's",
                     least);
}

double McaElementEos::damage(int i) const
{
  return damaged >= 0 ? atom->dvector[damaged][i] : 0.0;
}

void McaElementEos::begin_heat(int nall)
{
  if (nall > 0) memset(heat[0], 0, sizeof(double) * nall);    // memory->create: one block
}

void McaElementEos::finish_heat()
{
  exchange.to_owners(heat, 1);
  for (int i = 0; i < atom->nlocal; i++)
    if (laws[atom->type[i]].bulk > 0.0) {
      const double h = heat[i][0] / volume(i);
      atom->dvector[energy][i] += h;
      atom->dvector[heated][i] += h;    // what the next step's old pressure leaves out
    }
}

void McaElementEos::tally_energy(double *total, double *per_atom) const
{
  for (int i = 0; i < atom->nlocal; i++) {
    if (laws[atom->type[i]].bulk == 0.0) continue;
    const double e = atom->dvector[energy][i] * volume(i);
    if (total) *total += e;
    if (per_atom) per_atom[i] += e;
  }
}
