// McaSegmentLaw (mca_segment_law.h, doc/pair_mca.rst "Contact segments and micro-roughness"):
// a segment of two surface types interpolated along it;
// the nearest point of a segment, the rest height sqrt(3)/2 (R_k + R_s), the normal force as
// the gradient of its energy (finite differences over the three elements), the dry limit
// (Coulomb with K_mu, capped by the junction's shear strength) and the tangential spring's
// stick, slip and dissipated work.
#include "mca_segment_law.h"

#include "gtest/gtest.h"

#include <cmath>

using LAMMPS_NS::ClusterDyn::McaSegmentLaw;

TEST(McaSegmentLaw, NearestPointOnTheSegmentAndItsEnds)
{
  const double xi[2] = {0.0, 0.0}, xj[2] = {2.0, 0.0};
  const double above[2] = {0.5, 1.5};
  McaSegmentLaw::Foot f = McaSegmentLaw::nearest(xi, xj, above);
  EXPECT_NEAR(f.t, 0.25, 1e-15);
  EXPECT_NEAR(f.h, 1.5, 1e-15);
  EXPECT_NEAR(f.n[1], 1.0, 1e-15);
  EXPECT_NEAR(f.e[0], -1.0, 1e-15);    // e = z x n
  const double beyond[2] = {3.0, 1.0};
  f = McaSegmentLaw::nearest(xi, xj, beyond);
  EXPECT_EQ(f.t, 1.0);
  EXPECT_NEAR(f.h, std::sqrt(2.0), 1e-15);
  const double lone[2] = {0.3, 0.4};
  f = McaSegmentLaw::nearest(xi, xi, lone);    // a lone end
  EXPECT_EQ(f.t, 0.0);
  EXPECT_NEAR(f.h, 0.5, 1e-15);
}

TEST(McaSegmentLaw, RestHeightIsTheHollowOfTheRow)
{
  // equal elements: k touching i and j (centres 2R apart) sits sqrt(3) R above their line
  EXPECT_NEAR(McaSegmentLaw::rest_height(0.5, 0.5, 0.5, 0.3), std::sqrt(3.0) * 0.5, 1e-15);
  EXPECT_NEAR(McaSegmentLaw::rest_height(1.0, 0.5, 1.5, 0.25),
              0.5 * std::sqrt(3.0) * (1.0 + 0.75 * 0.5 + 0.25 * 1.5), 1e-15);
}

// the forces k: F n, i: -(1 - t) F n, j: -t F n are minus the gradient of kn (h0 - h)^2 / 2
TEST(McaSegmentLaw, NormalForceIsTheGradientOfItsEnergy)
{
  const double kn = 3.0, h0 = 0.9;
  double x[3][2] = {{0.1, -0.05}, {1.05, 0.1}, {0.4, 0.75}};    // i, j, k
  const auto energy = [&](double p[3][2]) {
    const McaSegmentLaw::Foot f = McaSegmentLaw::nearest(p[0], p[1], p[2]);
    double e;
    McaSegmentLaw::normal(kn, h0, f.h, e);
    return e;
  };
  const McaSegmentLaw::Foot f = McaSegmentLaw::nearest(x[0], x[1], x[2]);
  double e;
  const double fn = McaSegmentLaw::normal(kn, h0, f.h, e);
  ASSERT_GT(fn, 0.0);
  const double share[3] = {-(1.0 - f.t), -f.t, 1.0};
  const double step = 1e-6;
  for (int a = 0; a < 3; a++)
    for (int c = 0; c < 2; c++) {
      double p[3][2], q[3][2];
      for (int b = 0; b < 3; b++)
        for (int d = 0; d < 2; d++) p[b][d] = q[b][d] = x[b][d];
      p[a][c] += step;
      q[a][c] -= step;
      const double numeric = -(energy(p) - energy(q)) / (2.0 * step);
      EXPECT_NEAR(share[a] * fn * f.n[c], numeric, 1e-8) << a << " " << c;
    }
  EXPECT_EQ(McaSegmentLaw::normal(kn, h0, 1.0, e), 0.0);    // apart: nothing
  EXPECT_EQ(e, 0.0);
}

TEST(McaSegmentLaw, DryLimitIsCoulombWithRoughnessCappedByTheJunction)
{
  const McaSegmentLaw law{0.4, 0.0, 2.0};
  EXPECT_NEAR(law.dry_limit(1.0, 1.2, 0.5), 0.4 * 1.2 * 1.0, 1e-15);
  // pressed hard: the junction's shear strength S sigma0 / sqrt(3)
  EXPECT_NEAR(law.dry_limit(10.0, 1.0, 0.5), 0.5 * 2.0 / std::sqrt(3.0), 1e-15);
  const McaSegmentLaw free{0.4, 0.0, 0.0};
  EXPECT_NEAR(free.dry_limit(10.0, 1.0, 0.5), 4.0, 1e-15);
}

TEST(McaSegmentLaw, SpringSticksThenSlipsDissipatingTheLimitTimesTheSlip)
{
  const McaSegmentLaw law{0.5, 0.0, 0.0};
  const double kt = 2.0, limit = 0.1, dt = 0.01, vt = 1.0;
  double xi = 0.0, work = 0.0, energy = 0.0, dissipated = 0.0;
  double force = 0.0;
  for (int n = 0; n < 3; n++) {    // sticks: xi = 0.03 < limit / kt = 0.05
    force = law.friction(xi, vt, dt, kt, limit, 1.0, work, energy);
    dissipated += work;
  }
  EXPECT_NEAR(xi, 0.03, 1e-15);
  EXPECT_NEAR(force, -kt * 0.03, 1e-15);
  EXPECT_EQ(dissipated, 0.0);
  EXPECT_NEAR(energy, 0.5 * kt * 0.03 * 0.03, 1e-17);
  for (int n = 0; n < 10; n++) {    // slides 0.1 more: the spring holds 0.05, 0.08 slips
    force = law.friction(xi, vt, dt, kt, limit, 1.0, work, energy);
    dissipated += work;
  }
  EXPECT_NEAR(xi, 0.05, 1e-15);
  EXPECT_NEAR(force, -limit, 1e-15);
  EXPECT_NEAR(dissipated, limit * 0.08, 1e-15);
}

TEST(McaSegmentLaw, ViscousPartOpposesTheSlideAndDissipates)
{
  const McaSegmentLaw law{0.0, 3.0, 0.0};
  double xi = 0.0, work, energy;
  const double s = 0.5, vt = -0.2, dt = 0.01;
  const double force = law.friction(xi, vt, dt, 1.0, 0.0, s, work, energy);
  EXPECT_NEAR(force, -3.0 * s * vt, 1e-15);
  EXPECT_NEAR(work, 3.0 * s * vt * vt * dt, 1e-15);
}

TEST(McaSegmentLaw, TwoSurfaceTypesInterpolateAlongTheSegment)
{
  const McaSegmentLaw li{0.2, 1.0, 0.0}, lj{0.6, 3.0, 4.0};
  const McaSegmentLaw at0 = McaSegmentLaw::between(li, lj, 0.0);
  const McaSegmentLaw mid = McaSegmentLaw::between(li, lj, 0.25);
  EXPECT_EQ(at0.mu0, li.mu0);
  EXPECT_EQ(at0.eta0, li.eta0);
  EXPECT_EQ(at0.sigma0, li.sigma0);
  EXPECT_NEAR(mid.mu0, 0.3, 1e-15);
  EXPECT_NEAR(mid.eta0, 1.5, 1e-15);
  // the junction's limit by its inverse, none counting as infinite: 1 / (0.25 / 4) = 16,
  // which grows without bound towards the end that has none
  EXPECT_NEAR(mid.sigma0, 16.0, 1e-13);
  EXPECT_GT(McaSegmentLaw::between(li, lj, 1e-6).sigma0, 1e6);
  const McaSegmentLaw both{0.2, 1.0, 2.0};
  EXPECT_NEAR(McaSegmentLaw::between(both, lj, 0.5).sigma0, 1.0 / 0.375, 1e-13);
  // the same segment seen from its other end: t -> 1 - t
  const McaSegmentLaw back = McaSegmentLaw::between(lj, li, 0.75);
  EXPECT_NEAR(back.mu0, mid.mu0, 1e-15);
}
