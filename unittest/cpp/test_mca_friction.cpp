// McaFriction (mca_friction.h, doc/pair_mca.rst "Unlinked contacts"): the dry part is an
// elastic tangential stress (stiffness a per unit slide) capped at mu |sigma_n|; beyond the
// cap the contact slips by (t - cap)/a and dissipates cap x slip.  Two surfaces: the geometric
// means of mu and eta; a weld needs both, at the higher pressure.
#include "mca_friction.h"

#include "gtest/gtest.h"

#include <cmath>

using LAMMPS_NS::ClusterDyn::McaFriction;

namespace {

double norm(const double *v)
{
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}    // namespace

TEST(McaFriction, StressBelowTheCapStays)
{
  const McaFriction f{0.5, 0.0, 0.0};
  double tau[3] = {0.3, -0.2, 0.1};    // |tau| = 0.374 < 0.5 x 0.8
  EXPECT_EQ(f.cap(tau, -0.8, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(tau[0], 0.3);
  EXPECT_DOUBLE_EQ(tau[1], -0.2);
  EXPECT_DOUBLE_EQ(tau[2], 0.1);
}

TEST(McaFriction, CapKeepsTheDirectionAndDissipatesCapTimesSlip)
{
  const double mu = 0.4, a = 2.5;
  const McaFriction f{mu, 0.0, 0.0};
  for (double sigma_n : {-3.0, 3.0}) {    // the cap takes |sigma_n|
    const double dir[3] = {0.6, 0.0, -0.8}, t = 2.0, limit = mu * 3.0;
    double tau[3] = {t * dir[0], t * dir[1], t * dir[2]};
    const double work = f.cap(tau, sigma_n, a);
    EXPECT_NEAR(norm(tau), limit, 1e-15);
    for (int k = 0; k < 3; k++) EXPECT_NEAR(tau[k], limit * dir[k], 1e-15);
    const double slip = (t - limit) / a;    // the part of the slide the cap did not store
    EXPECT_NEAR(work, limit * slip, 1e-15);
  }
  // a contact at its cap slid further by du: the work is mu |sigma_n| du
  const double limit = mu * 1.5, du = 0.01;
  double tau[3] = {0.0, limit + a * du, 0.0};
  EXPECT_NEAR(f.cap(tau, -1.5, a), limit * du, 1e-15);
  EXPECT_NEAR(tau[1], limit, 1e-15);
}

TEST(McaFriction, PairOfSurfaces)
{
  const McaFriction ij = McaFriction::of_pair(0.2, 3.0, 5.0, 0.8, 12.0, 7.0);
  const McaFriction ji = McaFriction::of_pair(0.8, 12.0, 7.0, 0.2, 3.0, 5.0);
  for (const McaFriction &f : {ij, ji}) {
    EXPECT_NEAR(f.mu, 0.4, 1e-15);
    EXPECT_NEAR(f.eta, 6.0, 1e-14);
    EXPECT_EQ(f.weld, 7.0);    // both weld: the higher pressure
  }
  EXPECT_EQ(McaFriction::of_pair(0.2, 0.0, 5.0, 0.8, 0.0, 0.0).weld, 0.0);    // one does not
  EXPECT_EQ(McaFriction::of_pair(0.0, 1.0, 0.0, 0.5, 1.0, 0.0).mu, 0.0);      // one frictionless
  EXPECT_FALSE((McaFriction{0.0, 1.0, 0.0}.keeps_state()));    // viscous only: no state
  EXPECT_TRUE((McaFriction{0.1, 0.0, 0.0}.keeps_state()));
  EXPECT_TRUE((McaFriction{0.0, 0.0, 2.0}.keeps_state()));
}
