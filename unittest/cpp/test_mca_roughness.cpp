// McaRoughness (mca_roughness.h, doc/pair_mca.rst "Contact segments and micro-roughness"): the
// review's eq 18, two piecewise sinusoids about 1 of whole periods: continuous, above
// 1 - 3/2 (A1 + A2), mean 1 over the profile, periodic over its length, the same for the same
// seed; a contact's mean over S equals the quadrature of K_mu and its swing falls as S grows.
#include "mca_roughness.h"

#include "gtest/gtest.h"

#include <cmath>

using LAMMPS_NS::ClusterDyn::McaRoughness;

namespace {

McaRoughness profile(int seed = 7, double length = 40.0)
{
  const McaRoughness::Wave waves[2] = {{0.2, 0.5, 3.0}, {0.1, 0.1, 0.8}};
  return McaRoughness(waves, seed, -3.0, length);
}

double quadrature(const McaRoughness &k, double a, double b)
{
  const int n = 20000;
  const double h = (b - a) / n;
  double sum = 0.5 * (k.value(a) + k.value(b));
  for (int m = 1; m < n; m++) sum += k.value(a + m * h);
  return sum * h;
}

double swing(const McaRoughness &k, double s)
{
  double lo = INFINITY, hi = -INFINITY;
  for (int m = 0; m < 4000; m++) {
    const double v = k.mean(-3.0 + 0.01 * m, s);
    lo = std::fmin(lo, v);
    hi = std::fmax(hi, v);
  }
  return hi - lo;
}

}    // namespace

TEST(McaRoughness, FlatWithoutWaves)
{
  const McaRoughness flat;
  EXPECT_TRUE(flat.flat());
  EXPECT_EQ(flat.value(1.7), 1.0);
  EXPECT_EQ(flat.mean(1.7, 0.3), 1.0);
}

TEST(McaRoughness, ContinuousPositiveAndPeriodic)
{
  const McaRoughness k = profile();
  double lo = INFINITY, jump = 0.0, prev = k.value(-3.0);
  for (int m = 1; m <= 400000; m++) {
    const double v = k.value(-3.0 + 1e-4 * m);
    lo = std::fmin(lo, v);
    jump = std::fmax(jump, std::fabs(v - prev));
    prev = v;
  }
  EXPECT_GT(lo, 1.0 - 1.5 * (0.2 + 0.1));
  EXPECT_LT(lo, 0.9);                                  // it does swing
  EXPECT_LT(jump, 1e-4 * M_PI * 1.5 * (0.2 / 0.5 + 0.1 / 0.1));    // the steepest slope
  for (const double x : {-2.9, 0.37, 11.1})
    EXPECT_NEAR(k.value(x), k.value(x + 40.0), 1e-12) << x;
}

TEST(McaRoughness, SameSeedSameProfileOtherSeedAnother)
{
  const McaRoughness a = profile(7), b = profile(7), c = profile(8);
  double diff = 0.0;
  for (int m = 0; m < 100; m++) {
    const double x = 0.37 * m;
    EXPECT_EQ(a.value(x), b.value(x));
    diff = std::fmax(diff, std::fabs(a.value(x) - c.value(x)));
  }
  EXPECT_GT(diff, 0.05);
}

TEST(McaRoughness, ContactMeanIsTheQuadratureAndTheWholeMeanIsOne)
{
  const McaRoughness k = profile();
  for (const double x : {-2.0, 4.33, 36.9})    // the last across the period's end
    for (const double s : {0.05, 0.6, 2.5})
      EXPECT_NEAR(k.mean(x, s), quadrature(k, x - 0.5 * s, x + 0.5 * s) / s, 1e-7) << x << s;
  EXPECT_NEAR(k.mean(17.0, 40.0), 1.0, 1e-12);    // whole periods: every piece averages 1
}

TEST(McaRoughness, SwingFallsAsTheContactGrows)
{
  const McaRoughness k = profile();
  const double point = swing(k, 1e-3), small = swing(k, 0.5), large = swing(k, 4.0);
  EXPECT_GT(point, 0.4);
  EXPECT_LT(small, 0.8 * point);
  EXPECT_LT(large, 0.3 * small);
}

// The last piece of a profile whose length is not a whole number of regular pieces: with the
// regularity d = 2 l every regular piece is one period 2 l long (n = 1 + floor(u (2 d/(2l) -
// 1)) = 1); pieces are laid while one more period still fits, and the last piece fills the
// rest with round(rest / 2l) whole periods of the stretched (or shrunk) half-period
// rest / (2 round(rest / 2l)).  Over L = 10.7 (l = 0.5) regular pieces start at 0, 1, ..., 8
// and the last one at 9 has rest 1.7: two periods of half-period 0.425, zeros at 9 + 0.425 k
// (not one period of 0.85, nor a regular piece at 9 and a sliver of 0.7 at 10); over L = 10.3
// the last piece at 9 has rest 1.3: one period of half-period 0.65 (not a sliver of 0.3).
// Oracle: the shape A sin(pi (x - start) / l') of one wave (the other's amplitude 0), its
// amplitude A read at the first crest, so that the random amplitude drops out.
namespace {

void expect_last_piece(double length, double start, double half, int periods)
{
  const double x0 = -3.0;
  const McaRoughness::Wave waves[2] = {{0.2, 0.5, 1.0}, {0.0, 0.1, 0.8}};
  const McaRoughness k(waves, 11, x0, length);
  EXPECT_NEAR(start + 2.0 * periods * half, length, 1e-12);
  const double crest = k.value(x0 + start + 0.5 * half) - 1.0;
  EXPECT_GE(std::fabs(crest), 0.5 * 0.2 - 1e-12);
  EXPECT_LE(std::fabs(crest), 1.5 * 0.2 + 1e-12);
  double worst = 0.0, at = start;
  for (int m = 0; m <= 200; m++) {    // the whole last piece, through to the period's end
    const double u = start + (length - start) * m / 200.0;
    const double off = std::fabs(k.value(x0 + u) - 1.0 - crest * sin(M_PI * (u - start) / half));
    if (off > worst) worst = off, at = u;
  }
  EXPECT_LT(worst, 1e-12) << "L " << length << ": the last piece's shape off at " << at;
  // the regular piece before it is one period of the half-period 0.5
  const double before = k.value(x0 + start - 0.75) - 1.0;
  EXPECT_GE(std::fabs(before), 0.5 * 0.2 - 1e-12);
  for (const double u : {start - 1.0, start - 0.5, start})
    EXPECT_NEAR(k.value(x0 + u), 1.0, 1e-12) << "L " << length << " zero at " << u;
  EXPECT_NEAR(k.value(x0 + start - 0.25) - 1.0, -before, 1e-12);
}

}    // namespace

TEST(McaRoughness, LastPieceFillsTheRestWithTheNearestWholeNumberOfPeriods)
{
  expect_last_piece(10.7, 9.0, 1.7 / 4.0, 2);
  expect_last_piece(10.3, 9.0, 1.3 / 2.0, 1);
  expect_last_piece(12.0, 11.0, 0.5, 1);    // a whole number of periods: no stretch
}
