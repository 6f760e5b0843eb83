// McaResponse (mca_response.h, doc/pair_mca.rst "Response beyond elasticity"): the transmitted
// stress g(s) = (1 - D) s is the elastic line up to sigma_d, then the parabola that leaves the
// line with its slope and peaks at sigma_c when s = 2 sigma_c - sigma_d; type a never damages;
// a pair of two materials takes the weaker's, whichever element is i.
#include "mca_response.h"

#include "gtest/gtest.h"

#include <cmath>

using LAMMPS_NS::ClusterDyn::McaResponse;

namespace {

const double SC = 3.0, SD = 2.0;    // sigma_c, sigma_d

// the transmitted stress after loading to s (on the envelope: kappa = s)
double g(const McaResponse &r, double s)
{
  return r.intact(s) * s;
}

bool same(const McaResponse &x, const McaResponse &y)
{
  return x.strength == y.strength && x.damage == y.damage;
}

}    // namespace

TEST(McaResponse, ElasticUpToSigmaD)
{
  const McaResponse r{SC, SD};
  for (double s : {0.0, 0.5, 1.9, SD}) EXPECT_DOUBLE_EQ(r.intact(s), 1.0) << s;
  const McaResponse a{SC, 0.0};    // type a: no damage up to the strength
  for (double s : {1.0, 2.9, SC}) EXPECT_DOUBLE_EQ(a.intact(s), 1.0) << s;
  EXPECT_DOUBLE_EQ(a.peak(), SC);
}

TEST(McaResponse, ParabolaFromSigmaDToThePeak)
{
  const McaResponse r{SC, SD};
  EXPECT_DOUBLE_EQ(r.peak(), 2.0 * SC - SD);
  // the envelope, written as a parabola with vertex (2 sc - sd, sc) through (sd, sd)
  const double top = 2.0 * SC - SD;
  for (double s : {2.1, 2.5, 3.3, top}) {
    const double closed = SC - (s - top) * (s - top) / (4.0 * (SC - SD));
    EXPECT_NEAR(g(r, s), closed, 1e-14) << s;
    EXPECT_LE(r.intact(s), 1.0);
  }
  const double h = 1e-6;
  // leaves the elastic line continuous and with its slope 1
  EXPECT_NEAR(g(r, SD), SD, 1e-15);
  EXPECT_NEAR((g(r, SD + h) - g(r, SD)) / h, 1.0, 1e-6);
  // peaks at sigma_c, flat there
  EXPECT_NEAR(g(r, top), SC, 1e-14);
  EXPECT_NEAR((g(r, top + h) - g(r, top - h)) / (2.0 * h), 0.0, 1e-8);
  // unloading on the secant: at half the largest stress kappa, half of g(kappa)
  const double kappa = 3.5;
  EXPECT_NEAR(r.intact(kappa) * 0.5 * kappa, 0.5 * g(r, kappa), 1e-14);
}

TEST(McaResponse, EquivalentStressInTensionOnly)
{
  EXPECT_NEAR(McaResponse::equivalent(3.0, 16.0 / 3.0), 5.0, 1e-15);    // sqrt(9 + 3 16/3)
  EXPECT_NEAR(McaResponse::equivalent(2.0, 0.0), 2.0, 1e-15);
  EXPECT_EQ(McaResponse::equivalent(0.0, 1.0), 0.0);
  EXPECT_EQ(McaResponse::equivalent(-2.0, 1.0), 0.0);
}

TEST(McaResponse, PairTakesTheWeakerWhicheverIsI)
{
  struct Case {
    double sc_i, sd_i, sc_j, sd_j;    // two materials
    McaResponse weaker;
  };
  const Case cases[] = {
      {3.0, 0.0, 2.0, 0.0, {2.0, 0.0}},    // the lower strength
      {3.0, 1.0, 2.0, 1.5, {2.0, 1.5}},
      {3.0, 0.0, 3.0, 2.0, {3.0, 0.0}},    // equal strengths: type a unlinks first
      {3.0, 1.0, 3.0, 2.0, {3.0, 2.0}},    // then the higher damage threshold
      {0.0, 0.0, 3.0, 2.0, {3.0, 2.0}},    // no strength: unbreakable, the other's
      {0.0, 0.0, 0.0, 0.0, {0.0, 0.0}},
  };
  for (const Case &c : cases) {
    const McaResponse ij = McaResponse::of_pair(c.sc_i, c.sd_i, c.sc_j, c.sd_j);
    const McaResponse ji = McaResponse::of_pair(c.sc_j, c.sd_j, c.sc_i, c.sd_i);
    EXPECT_TRUE(same(ij, c.weaker)) << c.sc_i << " " << c.sd_i << " " << c.sc_j << " " << c.sd_j;
    EXPECT_TRUE(same(ji, c.weaker)) << c.sc_i << " " << c.sd_i << " " << c.sc_j << " " << c.sd_j;
  }
  EXPECT_FALSE(McaResponse::of_pair(0.0, 0.0, 0.0, 0.0).active());
  EXPECT_TRUE(McaResponse::of_pair(0.0, 0.0, 1.0, 0.0).active());
}
