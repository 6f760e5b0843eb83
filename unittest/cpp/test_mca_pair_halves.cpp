// McaPairHalves (mca_pair_halves.h): a pair's half stiffnesses with one reciprocal of their sum;
// the stiffness in series a_i a_j / (a_i + a_j) and the shares a_j / (a_i + a_j) of i and
// a_i / (a_i + a_j) of j, against their closed forms, each to round-off; the shares sum to 1,
// the softer element takes the larger share (its half stretches more), and equal halves split
// evenly at half the stiffness.
#include "mca_pair_halves.h"

#include "mca_contact.h"

#include "gtest/gtest.h"

using LAMMPS_NS::ClusterDyn::McaContact;
using LAMMPS_NS::ClusterDyn::McaPairHalves;

// the elements' halves a = 2 G / R in series: 1/a = 1/a_i + 1/a_j, the same either way round;
// an elongation e split by the shares loads both halves to the pair's stress a e
TEST(McaPairHalves, HalvesInSeriesCarryOneStress)
{
  const double gi = 3.0, ri = 0.5, gj = 1.0, rj = 0.8;
  const double ai = McaContact::half_stiffness(gi, ri), aj = McaContact::half_stiffness(gj, rj);
  EXPECT_NEAR(ai, 12.0, 1e-14);
  EXPECT_NEAR(aj, 2.5, 1e-14);
  const McaPairHalves h(ai, aj);
  const double a = h.series();
  EXPECT_NEAR(1.0 / a, 1.0 / ai + 1.0 / aj, 1e-14);
  EXPECT_NEAR(McaPairHalves(aj, ai).series(), a, 1e-15);
  const double e = 0.01, ei = e * h.share_i(), ej = e * h.share_j();
  EXPECT_NEAR(ei + ej, e, 1e-17);
  EXPECT_NEAR(ai * ei, a * e, 1e-15);
  EXPECT_NEAR(aj * ej, a * e, 1e-15);
}

TEST(McaPairHalves, SeriesAndSharesAgainstTheirClosedForms)
{
  for (const double ai : {1.0, 3.7e9, 2.5e-3})
    for (const double aj : {1.0, 0.2 * ai, 7.0 * ai}) {
      const McaPairHalves h(ai, aj);
      EXPECT_NEAR(h.series(), ai * aj / (ai + aj), 4e-16 * ai * aj / (ai + aj));
      EXPECT_NEAR(h.share_i(), aj / (ai + aj), 4e-16);
      EXPECT_NEAR(h.share_j(), ai / (ai + aj), 4e-16);
      EXPECT_NEAR(h.share_i() + h.share_j(), 1.0, 4e-16);
      EXPECT_EQ(h.ai, ai);
      EXPECT_EQ(h.aj, aj);
    }
}

TEST(McaPairHalves, TheSofterHalfTakesTheLargerShare)
{
  const McaPairHalves h(1.0, 3.0);    // i the softer: it takes 3/4
  EXPECT_DOUBLE_EQ(h.share_i(), 0.75);
  EXPECT_DOUBLE_EQ(h.share_j(), 0.25);
  EXPECT_DOUBLE_EQ(h.series(), 0.75);
  const McaPairHalves even(4.0, 4.0);
  EXPECT_DOUBLE_EQ(even.series(), 2.0);
  EXPECT_DOUBLE_EQ(even.share_i(), 0.5);
  EXPECT_DOUBLE_EQ(even.share_j(), 0.5);
}
