// McaLinkedPair (mca_linked_pair.h, doc/pair_mca.rst "Linked pairs"): a link transmits
// (1 - D) S (sigma~ n + tau~); its energy S (a e^2/2 + |tau~|^2/(2a)) + the moment's; plastic
// flow returns sigma~ and tau~ radially about the mean stress; damage and breaking follow the
// response of mca_response.h.
#include "mca_linked_pair.h"

#include "gtest/gtest.h"

#include <cmath>

using namespace LAMMPS_NS::ClusterDyn;
using C = McaContact;

namespace {

// a link along x, at its reference length ref, area S, no stored stress
struct Link {
  double v[C::NVALUES] = {};
  Link(double ref, double area)
  {
    v[C::REF] = ref;
    v[C::AREA] = area;
  }
};

McaPairFrame frame_along_x(double r)
{
  double x0[3] = {0.0, 0.0, 0.0}, x1[3] = {r, 0.0, 0.0};
  double *x[2] = {x0, x1};
  McaPairFrame p(x, 0, 1);
  p.orient(0.5, 0.5);
  return p;
}

// a link along x at separation r returned by phi about mean: its effective stresses before
// and after, the work and volume change the return reports, its effective energies before and
// after
struct Returned {
  double sigma0, sigma, work, dv = 0.0, e_before, e_after;
  Returned(McaLinkedPair &law, double a, double r, double phi, double mean)
  {
    const double n[3] = {1.0, 0.0, 0.0};
    double moment[3];
    auto energy = [&]() {
      return law.energy(n, law.elongation(r), law.v[C::ET], moment);
    };
    e_before = energy();
    sigma0 = sigma = McaLinkedPair::elastic_stress(law.v, a, r);
    work = law.plastic_return(sigma, phi, mean, r, dv);
    e_after = energy();
  }
};

}    // namespace

TEST(McaLinkedPair, ForceIsMinusTheEnergysSlope)
{
  const McaResponse elastic;
  const double a = 4.0, ref = 1.0, r = 1.003, h = 1e-6;
  Link link(ref, 0.8);
  McaLinkedPair law(elastic, link.v, a);
  double moment[3], ep, em;
  const double n[3] = {1.0, 0.0, 0.0};
  ep = law.energy(n, law.elongation(r + h), 0.0, moment);
  em = law.energy(n, law.elongation(r - h), 0.0, moment);
  const double sigma = McaLinkedPair::elastic_stress(link.v, a, r);
  EXPECT_NEAR(sigma, a * (r - ref), 1e-15);
  // the force on i along n pulls it to j when stretched: dE/dr = S sigma
  EXPECT_NEAR((ep - em) / (2.0 * h), law.area * sigma, 1e-8);
}

TEST(McaLinkedPair, PlasticReturnScalesTheDeviatorAndDissipatesTheEnergyLost)
{
  const McaResponse elastic;
  const double a = 2.0, r = 1.01, phi = 0.6, mean = 0.005;
  Link link(1.0, 0.5);
  link.v[C::TAU + 1] = 0.01;
  link.v[C::ET] = 0.5 * 0.01 * 0.01 / a;    // its energy |tau~|^2 / (2a)
  McaLinkedPair law(elastic, link.v, a);
  const Returned got(law, a, r, phi, mean);
  EXPECT_NEAR(got.sigma - mean, phi * (got.sigma0 - mean), 1e-15);    // radial about the mean
  EXPECT_NEAR(link.v[C::TAU + 1], phi * 0.01, 1e-17);
  EXPECT_NEAR(link.v[C::EPL], (got.sigma0 - got.sigma) / a, 1e-15);    // the elongation that flowed
  EXPECT_NEAR(got.sigma, McaLinkedPair::elastic_stress(link.v, a, r), 1e-15);
  EXPECT_NEAR(got.work, got.e_before - got.e_after, 1e-15);    // no motion in the step
  EXPECT_NEAR(got.dv, -law.area * (got.sigma0 - got.sigma) / a, 1e-15);    // its volume
}

TEST(McaLinkedPair, PlasticWorkIsTheTrapezoidRuleOfTheStep)
{
  // the pair moved by dr and its contact slid by du_t this step (DR, DTAU = tau~ . du_t): the
  // work is the energy lost less half the return's drop of force times that motion,
  // S (1 - D) (d sigma dr + (1 - phi) tau~ . du_t) / 2; for a pair stretched by dr from the
  // return of the step before at sigma_y to the trial sigma_y + a dr, returned to sigma_y,
  // that is S sigma_y dr: the yield stress times the plastic elongation
  const McaResponse elastic;
  const double a = 2.0, sigma_y = 0.01, dr = 0.002, phi = sigma_y / (sigma_y + a * dr);
  Link link(1.0, 0.5);
  link.v[C::EPL] = -sigma_y / a;    // at sigma_y at r = 1, before the step
  link.v[C::DR] = dr;
  McaLinkedPair law(elastic, link.v, a);
  const Returned got(law, a, 1.0 + dr, phi, 0.0);
  EXPECT_NEAR(got.sigma, sigma_y, 1e-16);
  EXPECT_NEAR(got.work, 0.5 * sigma_y * dr, 1e-16);
  EXPECT_NEAR(got.e_before - got.e_after - got.work, 0.5 * 0.5 * a * dr * dr, 1e-16);
  // the tangential part alike: tau~ grown by a du_t returned by phi gives (1 - phi) tau~ du_t / 2
  Link slid(1.0, 0.5);
  slid.v[C::TAU + 1] = 0.03;
  slid.v[C::ET] = 0.5 * 0.03 * 0.03 / a;
  slid.v[C::DTAU] = 0.03 * 0.004;
  McaLinkedPair tangential(elastic, slid.v, a);
  const Returned turned(tangential, a, 1.0, 0.5, 0.0);
  EXPECT_NEAR(turned.work, turned.e_before - turned.e_after - 0.5 * 0.5 * 0.5 * 0.03 * 0.004,
              1e-17);
}

TEST(McaLinkedPair, HoldsDamagesAndBreaksAtTheResponsesStresses)
{
  const McaResponse response{1.0, 0.6};    // damage from 0.6, unlinks at 2 x 1.0 - 0.6 = 1.4
  const double a = 1.0;
  Link link(1.0, 1.0);
  double lost = 1.0;
  // below sigma_d the largest stress is kept and nothing is lost; compression never damages
  EXPECT_EQ(McaLinkedPair(response, link.v, a).respond(0.5, 0.0, lost), McaLinkedPair::DAMAGES);
  EXPECT_EQ(lost, 0.0);
  EXPECT_EQ(link.v[C::KAPPA], 0.5);
  EXPECT_EQ(McaLinkedPair(response, link.v, a).respond(0.4, 0.0, lost), McaLinkedPair::HOLDS);
  EXPECT_EQ(McaLinkedPair(response, link.v, a).respond(-5.0, 0.0, lost), McaLinkedPair::HOLDS);
  McaLinkedPair law(response, link.v, a);
  EXPECT_EQ(law.respond(1.0, 0.0, lost), McaLinkedPair::DAMAGES);
  EXPECT_EQ(link.v[C::KAPPA], 1.0);
  EXPECT_NEAR(lost, 1.0 - response.intact(1.0), 1e-15);
  McaLinkedPair damaged(response, link.v, a);    // lost counts from what was left
  EXPECT_EQ(damaged.respond(1.2, 0.0, lost), McaLinkedPair::DAMAGES);
  EXPECT_NEAR(lost, response.intact(1.0) - response.intact(1.2), 1e-15);
  McaLinkedPair breaking(response, link.v, a);
  EXPECT_EQ(breaking.respond(1.4, 0.0, lost), McaLinkedPair::BREAKS);
  EXPECT_EQ(lost, breaking.intact);
}

// a link of area 0.3 at rest length 1 stretched to 1.05 with a = 10 (sigma = 0.5), strength 1,
// stepped without rotation; w: its tally's weight (1/2: a ghost pair with newton off)
struct Stepped {
  const McaResponse response{1.0, 0.0};
  const double a = 10.0;
  Link link{1.0, 0.3};
  StateTally changes;
  const McaPairTally tally;
  McaPairForce out;
  const McaPairFrame p = frame_along_x(1.05);
  const double omega[3] = {0.0, 0.0, 0.0};
  explicit Stepped(double w) : tally{changes, w, nullptr, 0, 1, McaPairHalves(1.0, 1.0), true, nullptr} {}
  bool step(double sigma, const McaPressureLoad *pressure)
  {
    McaLinkedPair law(response, link.v, a);
    return law.step(sigma, 1.0, 0.0, p, nullptr, omega, omega, 0.01, tally, true, pressure, out);
  }
};

TEST(McaLinkedPair, StepTransmitsTheIntactShareOrBreaks)
{
  Stepped s(0.5);
  const double a = s.a;
  StateTally &changes = s.changes;
  McaPairForce &out = s.out;
  ASSERT_TRUE(s.step(0.5, nullptr));
  EXPECT_NEAR(out.fi[0], 0.3 * 0.5, 1e-15);
  EXPECT_NEAR(out.evdwl, 0.3 * 0.5 * a * 0.05 * 0.05, 1e-15);
  EXPECT_EQ(changes.broken, 0.0);
  const double energy = out.evdwl;
  EXPECT_FALSE(s.step(1.0, nullptr));
  EXPECT_EQ(changes.broken, 0.5);                         // a pair with a ghost, newton off
  EXPECT_NEAR(changes.ejump, 0.5 * energy, 1e-15);        // the energy it took with it
}

TEST(McaLinkedPair, PressureAddsItsForceAndItsNormalStressBreaks)
{
  // strength 1; the pair's own stress 0.5 holds, with its elements' mean stress of 0.6 in
  // tension it breaks; pressed by a mean stress of -0.6 it holds and transmits the pressure's
  // force (intact share 1)
  Stepped s(1.0);
  McaPairForce &out = s.out;
  const McaPressureLoad push{{-0.3 * 0.6, 0.01, 0.0}, -0.6};    // compression, pushing i away
  ASSERT_TRUE(s.step(0.5, &push));
  EXPECT_NEAR(out.fi[0], 0.3 * 0.5 - 0.3 * 0.6, 1e-15);
  EXPECT_NEAR(out.fi[1], 0.01, 1e-15);
  const McaPressureLoad pull{{0.3 * 0.6, 0.0, 0.0}, 0.6};        // tension, pulling i to j
  EXPECT_FALSE(s.step(0.5, &pull));
  EXPECT_EQ(s.changes.broken, 1.0);
}

// A damaged pair (1 - D < 1) that yields: the stress it transmits, (1 - D) sigma~, returns
// radially about the mean stress of its elements (a transmitted stress, from Love's formula):
// (1 - D) sigma~' - sigma_m = phi ((1 - D) sigma~ - sigma_m), doc/pair_mca.rst (c); the
// plastic elongation keeps sigma~' = a (r - r_ref - e_p), tau~ scales by phi, and the work is
// the transmitted share (1 - D) of the effective energy lost.  Oracle: the return written from
// the doc, with the response's 1 - D = g(kappa)/kappa.
TEST(McaLinkedPair, DamagedPairReturnsItsTransmittedStressAboutTheMean)
{
  const McaResponse response{1.0, 0.6};
  const double a = 2.0, r = 1.5, phi = 0.7, mean = 0.3, kappa = 1.2;
  Link link(1.0, 0.5);
  link.v[C::KAPPA] = kappa;
  link.v[C::TAU + 2] = 0.04;
  link.v[C::ET] = 0.5 * 0.04 * 0.04 / a;
  McaLinkedPair law(response, link.v, a);
  const double u = 1.0 - (kappa - 0.6) / (2.0 * (1.0 - 0.6));
  const double intact = (1.0 - 0.4 * u * u) / kappa;    // g(kappa) / kappa
  ASSERT_NEAR(law.intact, intact, 1e-15);
  ASSERT_LT(intact, 0.95);
  const Returned got(law, a, r, phi, mean);    // sigma0 1.0: transmitted intact, above 0.3
  const double sigma0 = got.sigma0, sigma = got.sigma;
  EXPECT_NEAR(intact * sigma - mean, phi * (intact * sigma0 - mean), 1e-15);
  EXPECT_NEAR(sigma, (mean + phi * (intact * sigma0 - mean)) / intact, 1e-15);
  EXPECT_NEAR(link.v[C::TAU + 2], phi * 0.04, 1e-17);
  EXPECT_NEAR(link.v[C::EPL], (sigma0 - sigma) / a, 1e-15);
  EXPECT_NEAR(sigma, McaLinkedPair::elastic_stress(link.v, a, r), 1e-15);
  EXPECT_NEAR(got.work, intact * (got.e_before - got.e_after), 1e-15);
  EXPECT_NEAR(got.dv, -intact * law.area * (sigma0 - sigma) / a, 1e-15);
}
