// McaElementShape (mca_element_shape.h, doc/pair_mca.rst "Shock equation of state"): the span
// test of symmetric 3 x 3 matrices, rotated diagonal ones on both sides of its bound; K^-1 K = I;
// a full fcc neighbourhood and a free (100) face span a volume, a flat set of links and a chain
// do not; the gradient of an affine displacement is that displacement's matrix.
#include "mca_element_shape.h"

#include "gtest/gtest.h"

#include <cmath>

using LAMMPS_NS::ClusterDyn::McaElementShape;

namespace {

// sum of w x x^T over the vectors, w = 1, as xx yy zz xy xz yz
void shape(const double (*x)[3], int n, double *s)
{
  for (int k = 0; k < 6; k++) s[k] = 0.0;
  for (int j = 0; j < n; j++) {
    s[0] += x[j][0] * x[j][0];
    s[1] += x[j][1] * x[j][1];
    s[2] += x[j][2] * x[j][2];
    s[3] += x[j][0] * x[j][1];
    s[4] += x[j][0] * x[j][2];
    s[5] += x[j][1] * x[j][2];
  }
}

const double FCC[12][3] = {{1, 1, 0},  {1, -1, 0},  {-1, 1, 0}, {-1, -1, 0},
                           {1, 0, 1},  {1, 0, -1},  {-1, 0, 1}, {-1, 0, -1},
                           {0, 1, 1},  {0, 1, -1},  {0, -1, 1}, {0, -1, -1}};

}    // namespace

// R diag(d) R^T, R a rotation by 0.7 about z then 0.3 about x, as xx yy zz xy xz yz
void rotated_diagonal(const double *d, double *s)
{
  const double c1 = cos(0.7), s1 = sin(0.7), c2 = cos(0.3), s2 = sin(0.3);
  const double r[3][3] = {{c1, -s1, 0}, {c2 * s1, c2 * c1, -s2}, {s2 * s1, s2 * c1, c2}};
  double m[3][3];
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      m[a][b] = 0.0;
      for (int k = 0; k < 3; k++) m[a][b] += r[a][k] * d[k] * r[b][k];
    }
  const double v[6] = {m[0][0], m[1][1], m[2][2], m[0][1], m[0][2], m[1][2]};
  for (int k = 0; k < 6; k++) s[k] = v[k];
}

TEST(McaElementShape, SpansWhereTheSmallestEigenvalueExceedsATenthOfTheMean)
{
  // eigenvalues (x, 2, 5): the smallest is 0.1 of the mean (x + 7) / 3 at x = 0.7 / 2.9;
  // each ordering of the eigenvalues (which leading minor decides) on both sides of it
  const double edge = 0.7 / 2.9;
  for (int place = 0; place < 3; place++)
    for (const double side : {1.0 + 1e-9, 1.0 - 1e-9}) {
      const double x = edge * side;
      const double orders[3][3] = {{x, 2.0, 5.0}, {2.0, x, 5.0}, {5.0, 2.0, x}};
      const double *d = orders[place];
      double s[6];
      rotated_diagonal(d, s);
      EXPECT_EQ(McaElementShape::spans(s), side > 1.0) << place << " " << side;
      // the same matrix unrotated
      const double diag[6] = {d[0], d[1], d[2], 0.0, 0.0, 0.0};
      EXPECT_EQ(McaElementShape::spans(diag), side > 1.0) << place << " " << side;
    }
  const double iso[6] = {3.0, 3.0, 3.0, 0.0, 0.0, 0.0};
  EXPECT_TRUE(McaElementShape::spans(iso));
  // chains along x and along z: two eigenvalues below the bound, each found by another minor
  const double along_x[6] = {2.0, 1e-4, 1e-4, 0.0, 0.0, 0.0};
  EXPECT_FALSE(McaElementShape::spans(along_x));
  const double along_z[6] = {1e-4, 1e-4, 2.0, 0.0, 0.0, 0.0};
  EXPECT_FALSE(McaElementShape::spans(along_z));
}

TEST(McaElementShape, FullAndFreeFaceNeighbourhoodsSpanAVolume)
{
  double s[6], inv[6];
  shape(FCC, 12, s);
  ASSERT_TRUE(McaElementShape::invert(s, inv));
  EXPECT_NEAR(inv[0] * s[0] + inv[3] * s[3] + inv[4] * s[4], 1.0, 1e-14);
  EXPECT_NEAR(inv[0] * s[3] + inv[3] * s[1] + inv[4] * s[5], 0.0, 1e-14);
  // a (100) free face: the 4 links in the face and the 4 on one side
  const double face[8][3] = {{0, 1, 1}, {0, 1, -1}, {0, -1, 1}, {0, -1, -1},
                             {1, 1, 0}, {1, -1, 0}, {1, 0, 1},  {1, 0, -1}};
  shape(face, 8, s);
  // its K is diag(4, 6, 6) (the face normal along x): the smallest eigenvalue 0.75 of the mean
  EXPECT_NEAR(s[0], 4.0, 1e-14);
  EXPECT_NEAR(s[1], 6.0, 1e-14);
  EXPECT_TRUE(McaElementShape::invert(s, inv));
}

TEST(McaElementShape, FlatLinksAndChainsSpanNone)
{
  double s[6], inv[6];
  const double flat[4][3] = {{1, 1, 0}, {1, -1, 0}, {-1, 1, 0}, {-1, -1, 0.05}};
  shape(flat, 4, s);
  EXPECT_FALSE(McaElementShape::invert(s, inv));
  const double chain[2][3] = {{1, 0, 0}, {-1, 0.01, 0.01}};
  shape(chain, 2, s);
  EXPECT_FALSE(McaElementShape::invert(s, inv));
}

TEST(McaElementShape, GradientOfAnAffineDisplacementIsItsMatrix)
{
  const double h[3][3] = {{0.01, 0.002, -0.003}, {0.0, -0.02, 0.004}, {0.001, 0.0, 0.005}};
  double s[15] = {0};
  shape(FCC, 12, s);
  for (int j = 0; j < 12; j++) {
    double dx[3];
    for (int a = 0; a < 3; a++) dx[a] = h[a][0] * FCC[j][0] + h[a][1] * FCC[j][1] + h[a][2] * FCC[j][2];
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) s[6 + 3 * a + b] += dx[a] * FCC[j][b];
  }
  double inv[6], grad[3][3];
  ASSERT_TRUE(McaElementShape::invert(s, inv));
  McaElementShape::gradient(s, inv, grad);
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) EXPECT_NEAR(grad[a][b], h[a][b], 1e-15);
}

// a disordered neighbourhood: every entry of K is different and none is zero, so each cofactor
// of K^-1 is exercised (fcc's K is 4 I)
TEST(McaElementShape, InverseOfAGeneralShapeIsItsInverse)
{
  const double links[7][3] = {{1.0, 0.2, -0.1}, {-0.3, 1.1, 0.4},  {0.2, -0.5, 0.9},
                              {-0.8, -0.6, 0.3}, {0.5, 0.7, -0.9}, {0.1, -1.0, -0.6},
                              {-0.9, 0.4, 0.2}};
  double s[15] = {0}, inv[6];
  shape(links, 7, s);
  for (int k = 3; k < 6; k++) ASSERT_GT(std::fabs(s[k]), 0.05);
  ASSERT_TRUE(McaElementShape::invert(s, inv));
  const double K[3][3] = {{s[0], s[3], s[4]}, {s[3], s[1], s[5]}, {s[4], s[5], s[2]}};
  const double I[3][3] = {{inv[0], inv[3], inv[4]}, {inv[3], inv[1], inv[5]},
                          {inv[4], inv[5], inv[2]}};
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      double sum = 0.0;
      for (int c = 0; c < 3; c++) sum += K[a][c] * I[c][b];
      EXPECT_NEAR(sum, a == b ? 1.0 : 0.0, 1e-13) << a << b;
    }
  // and the gradient of an affine displacement of these links is its matrix
  const double h[3][3] = {{0.01, 0.002, -0.003}, {0.0, -0.02, 0.004}, {0.001, 0.0, 0.005}};
  for (int j = 0; j < 7; j++)
    for (int a = 0; a < 3; a++) {
      const double dx = h[a][0] * links[j][0] + h[a][1] * links[j][1] + h[a][2] * links[j][2];
      for (int b = 0; b < 3; b++) s[6 + 3 * a + b] += dx * links[j][b];
    }
  double grad[3][3];
  McaElementShape::gradient(s, inv, grad);
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) EXPECT_NEAR(grad[a][b], h[a][b], 1e-14);
}
