// McaUnlinkedPair (mca_unlinked_pair.h, doc/pair_mca.rst "Unlinked contacts"): compression
// S_u a (r - R_i - R_j), dry friction capped at mu |sigma_n|, viscous friction eta v_t of the
// contact points' relative tangential velocity, welding at the weld stress; a broken link's
// contact at its stress-free separation r_ref + e_p.
#include "mca_unlinked_pair.h"

#include "gtest/gtest.h"

#include <cmath>

using namespace LAMMPS_NS::ClusterDyn;
using C = McaContact;

namespace {

McaPairFrame frame(double r, double ri, double rj)
{
  double x0[3], x1[3];
  x0[0] = x0[1] = x0[2] = 0.0;
  x1[0] = 0.0;
  x1[1] = r;
  x1[2] = 0.0;
  double *x[2] = {x0, x1};
  McaPairFrame p(x, 0, 1);
  p.orient(ri, rj);
  return p;
}

}    // namespace

TEST(McaUnlinkedPair, CompressionOnTheHarmonicMeanFace)
{
  const double ri = 0.5, rj = 0.3, a = 7.0, r = 0.79;
  const McaUnlinkedPair touch(ri, rj, ri + rj, a, r, 3);
  const double rh = 2.0 * ri * rj / (ri + rj);
  EXPECT_NEAR(touch.area, std::sqrt(2.0) * rh * rh, 1e-15);
  EXPECT_NEAR(touch.sigma, a * (r - ri - rj), 1e-15);
  // the normal force is minus the slope of the energy S a overlap^2 / 2
  const double h = 1e-7;
  auto energy = [&](double rr) {
    const McaUnlinkedPair t(ri, rj, ri + rj, a, rr, 3);
    return 0.5 * t.area * a * t.overlap * t.overlap;
  };
  EXPECT_NEAR((energy(r + h) - energy(r - h)) / (2.0 * h), touch.area * touch.sigma, 1e-9);
}

TEST(McaUnlinkedPair, RollingWithoutSlipHasNoViscousStress)
{
  const double n[3] = {0.0, 1.0, 0.0}, qi = 0.5, qj = 0.3, w = 2.0;
  const double omega_i[3] = {0.0, 0.0, w}, omega_j[3] = {0.0, 0.0, -w * qi / qj};
  // i turns about z and stands still; its contact point moves at -qi w along x; j, turning the
  // other way, rolls on it with its centre still
  const double vi[3] = {0.0, 0.0, 0.0}, vj[3] = {0.0, 0.0, 0.0};
  double visc[3];
  EXPECT_NEAR(McaUnlinkedPair::viscous(3.0, vi, vj, omega_i, omega_j, n, qi, qj, visc), 0.0, 1e-28);
  // j sliding along x at u past a still i: eta u, tangential only
  const double slide[3] = {0.4, 0.2, 0.0}, still[3] = {0.0, 0.0, 0.0};
  const double power = McaUnlinkedPair::viscous(3.0, vi, slide, still, still, n, qi, qj, visc);
  EXPECT_NEAR(visc[0], 3.0 * 0.4, 1e-15);
  EXPECT_EQ(visc[1], 0.0);
  EXPECT_NEAR(power, 1.2 * 1.2, 1e-14);
}

TEST(McaUnlinkedPair, SlidingAtTheCapDissipatesMuSigmaPerDistance)
{
  const double ri = 0.5, rj = 0.5, a = 50.0, r = 0.98, mu = 0.3, du = 0.01;
  McaPairModel model;
  model.friction = McaFriction{mu, 0.0, 0.0};
  const McaUnlinkedPair touch(ri, rj, ri + rj, a, r, 3);
  double v[C::NVALUES] = {};
  int word = 0;
  StateTally changes;
  const McaPairTally tally{changes, 1.0, nullptr, 0, 1, McaPairHalves(2.0 * a, 2.0 * a), true, nullptr};
  McaPairForce out;
  const McaPairFrame p = frame(r, ri, rj);
  touch.step(model, word, 0, v, p, nullptr, a, nullptr, nullptr, 0.0, tally, true, out);
  EXPECT_EQ(word, WORD_KEPT);    // a contact with dry friction keeps its stress
  EXPECT_NEAR(out.fi[1], touch.area * touch.sigma, 1e-15);
  // slid by du along x, beyond the cap (a du > mu |sigma|): the contact slips
  double x0[3] = {0.0, 0.0, 0.0}, x1[3] = {du, r, 0.0};
  double *x[2] = {x0, x1};
  McaPairFrame moved(x, 0, 1);
  moved.orient(ri, rj);
  const McaUnlinkedPair pressed(ri, rj, ri + rj, a, moved.r, 3);
  const double before = changes.work[WORK_FRICTION];
  pressed.step(model, word, 0, v, moved, nullptr, a, nullptr, nullptr, 0.0, tally, true, out);
  const double cap = mu * std::fabs(pressed.sigma);
  EXPECT_NEAR(std::hypot(out.ft[0], out.ft[1]), pressed.area * cap, 1e-12);
  // the slide's tangential part (to the new normal), less the elastic part the cap stores
  const double slide = du * moved.n[1];    // |du - (du . n) n| for du along x
  ASSERT_GT(a * slide, cap);
  EXPECT_NEAR(changes.work[WORK_FRICTION] - before, pressed.area * cap * (slide - cap / a),
              1e-12);
}

TEST(McaUnlinkedPair, WeldsPressedAtTheWeldStressIfTheTypesLink)
{
  const double ri = 0.5, rj = 0.5, a = 10.0, r = 0.9;    // sigma = -1
  McaPairModel model;
  model.friction = McaFriction{0.0, 0.0, 0.5};
  StateTally changes;
  const McaPairTally tally{changes, 1.0, nullptr, 0, 1, McaPairHalves(20.0, 20.0), true, nullptr};
  McaPairForce out;
  const McaPairFrame p = frame(r, ri, rj);
  const McaUnlinkedPair touch(ri, rj, ri + rj, a, r, 3);
  for (const bool links : {false, true}) {
    model.links = links;
    double v[C::NVALUES] = {};
    int word = 0;
    touch.step(model, word, 0, v, p, nullptr, a, nullptr, nullptr, 0.0, tally, false, out);
    EXPECT_EQ(state_now(word), links ? 1 : 0);
    if (links) {
      EXPECT_EQ(v[C::REF], ri + rj);    // linked at contact: its force unchanged
      EXPECT_EQ(v[C::AREA], touch.area);
    }
  }
  EXPECT_EQ(changes.formed, 1.0);
}

TEST(McaUnlinkedPair, ABrokenLinkTouchesAtItsStressFreeSeparation)
{
  const double ri = 0.5, rj = 0.5, a = 10.0;
  double v[C::NVALUES];
  for (int k = 0; k < C::NVALUES; k++) v[k] = 1.0 + k;    // a link's state
  v[C::REF] = 0.97;
  v[C::EPL] = -0.05;    // shortened by plastic flow
  const double d[3] = {0.0, 0.93, 0.0};
  int word = state_word(1, 0, 0);    // broken now
  word = McaUnlinkedPair::keep_contact(word, v, d);
  EXPECT_TRUE(word & WORD_KEPT);
  EXPECT_EQ(state_now(word), 0);
  EXPECT_DOUBLE_EQ(v[C::REF], 0.92);
  for (int k = 0; k < 3; k++) {
    EXPECT_EQ(v[C::TAU + k], 0.0);    // no tangential stress carried over
    EXPECT_EQ(v[C::DPREV + k], d[k]);
  }
  for (const int k : {C::AREA, C::KAPPA, C::EPL, C::SIG, C::ET, C::EHG}) EXPECT_EQ(v[k], 0.0);
  EXPECT_DOUBLE_EQ(McaUnlinkedPair::contact_distance(word, v, ri, rj), 0.92);
  EXPECT_EQ(McaUnlinkedPair::contact_distance(word & ~WORD_KEPT, v, ri, rj), ri + rj);
  // pressed from there: S_u a (r - 0.92), energy S_u a (r - 0.92)^2 / 2
  const McaUnlinkedPair pressed(ri, rj, 0.92, a, 0.91, 3);
  EXPECT_NEAR(pressed.sigma, -0.1, 1e-12);
  EXPECT_NEAR(pressed.energy(), 0.5 * pressed.area * a * 0.01 * 0.01, 1e-15);
}

TEST(McaUnlinkedPair, AnOpenContactKeepsABrokenLinksDistanceOnlyWhileCloserThanTheRadii)
{
  const double ri = 0.5, rj = 0.5;
  double v[C::NVALUES] = {};
  v[C::REF] = 0.92;
  v[C::TAU] = 0.3;
  const double d[3] = {0.0, 0.95, 0.0};
  const int kept = state_word(0, 0, 0) | WORD_KEPT;
  const int word = McaUnlinkedPair::open(kept, v, 0.95 * 0.95, d, ri + rj);
  EXPECT_EQ(word, kept);    // open at 0.95 > 0.92, still closer than R_i + R_j
  EXPECT_EQ(v[C::TAU], 0.0);
  EXPECT_EQ(v[C::DPREV + 1], 0.95);
  EXPECT_EQ(McaUnlinkedPair::open(kept, v, 1.01 * 1.01, d, ri + rj), 0);    // apart: forgotten
  v[C::REF] = 0.0;    // a contact of the elements' radii keeps nothing open
  EXPECT_EQ(McaUnlinkedPair::open(kept, v, 0.95 * 0.95, d, ri + rj), 0);
}

TEST(McaUnlinkedPair, AContactLeftPressedTakesItsEnergyFromTheBreak)
{
  // a link of r_ref 0.97 with e_p 0.01 breaks at r = 0.975 (its own elongation compressive,
  // the many-body term pulling): the contact closes at 0.98 and is pressed by 0.005
  const double ri = 0.5, rj = 0.5, a = 10.0;
  double v[C::NVALUES] = {};
  v[C::REF] = 0.97;
  v[C::EPL] = 0.01;
  StateTally changes;
  changes.ejump = 1.0;    // what the link's own energy released
  const McaPairTally tally{changes, 0.5, nullptr, 0, 1, McaPairHalves(20.0, 20.0), false, nullptr};
  const McaPairFrame p = frame(0.975, ri, rj);
  const int word = McaUnlinkedPair::left_by_break(state_word(1, 0, 0), v, p, ri, rj, a, 3, tally);
  EXPECT_TRUE(word & WORD_KEPT);
  const McaUnlinkedPair left(ri, rj, 0.98, a, 0.975, 3);
  EXPECT_NEAR(changes.ejump, 1.0 - 0.5 * 0.5 * left.area * a * 0.005 * 0.005, 1e-15);
  // apart from its contact distance a break leaves nothing to take
  double w[C::NVALUES] = {};
  w[C::REF] = 0.97;
  StateTally apart;
  const McaPairTally tally_apart{apart, 1.0, nullptr, 0, 1, McaPairHalves(20.0, 20.0), true, nullptr};
  McaUnlinkedPair::left_by_break(state_word(1, 0, 0), w, frame(0.975, ri, rj), ri, rj, a, 3,
                                 tally_apart);
  EXPECT_EQ(apart.ejump, 0.0);
}
