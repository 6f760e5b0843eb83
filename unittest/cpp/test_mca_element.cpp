// McaElement (mca_element.h, doc/pair_mca.rst "Elements"): an element of radius R in a packing
// of fraction F stands for Omega = (4 pi / 3) R^3 / F, in 2d pi R^2 / F; its links' areas
// D Omega / (Z R) make Love's identity sum S R n n = Omega I hold on fcc and on the triangular
// packing; Love's formula sums q sym(n (x) f) over its pairs.
#include "mca_element.h"

#include "gtest/gtest.h"

#include <array>
#include <cmath>
#include <vector>

using LAMMPS_NS::ClusterDyn::McaElement;

TEST(McaElement, VolumeIsTheSphereOverThePackingFraction)
{
  const double fcc = M_PI / std::sqrt(18.0);
  EXPECT_NEAR(McaElement::volume(0.5, fcc, 3), 1.0 / std::sqrt(2.0), 1e-15);    // fcc cell / 4
  EXPECT_NEAR(McaElement::volume(2.0, 1.0, 3), 32.0 * M_PI / 3.0, 1e-13);
}

TEST(McaElement, AreaIsTheDiscOverThePackingFraction)
{
  // the triangular packing of unit discs: the hexagonal cell of inradius 1/2, area sqrt(3)/2
  const double triangular = M_PI / std::sqrt(12.0);
  EXPECT_NEAR(McaElement::volume(0.5, triangular, 2), std::sqrt(3.0) / 2.0, 1e-15);
  EXPECT_NEAR(McaElement::volume(2.0, 0.5, 2), 8.0 * M_PI, 1e-13);
}

// sum over the Z links of S R n n = Omega I: fcc's 12 and the triangular packing's 6
TEST(McaElement, AreaSharesMakeLovesIdentity)
{
  const double r = 0.5;
  const double fcc = M_PI / std::sqrt(18.0), triangular = M_PI / std::sqrt(12.0);
  for (const int dim : {2, 3}) {
    const double omega = McaElement::volume(r, dim == 2 ? triangular : fcc, dim);
    std::vector<std::array<double, 3>> dirs;
    if (dim == 2)
      for (int k = 0; k < 6; k++) dirs.push_back({cos(k * M_PI / 3), sin(k * M_PI / 3), 0.0});
    else
      for (int a = 0; a < 3; a++)
        for (const double s1 : {1.0, -1.0})
          for (const double s2 : {1.0, -1.0}) {
            std::array<double, 3> d = {0.0, 0.0, 0.0};
            d[a] = s1 / std::sqrt(2.0);
            d[(a + 1) % 3] = s2 / std::sqrt(2.0);
            dirs.push_back(d);
          }
    const double s = McaElement::area_share(omega, dirs.size(), r, dim);
    double sum[3][3] = {};
    for (const auto &n : dirs)
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) sum[a][b] += s * r * n[a] * n[b];
    for (int a = 0; a < dim; a++)
      for (int b = 0; b < dim; b++) EXPECT_NEAR(sum[a][b], a == b ? omega : 0.0, 1e-14) << dim;
  }
  // the triangular packing's contact is its hexagon's side 2 R / sqrt(3)
  EXPECT_NEAR(McaElement::area_share(McaElement::volume(r, triangular, 2), 6, r, 2),
              2.0 * r / std::sqrt(3.0), 1e-15);
}

TEST(McaElement, UnlinkedAreaIsAFaceOfTheHarmonicMeanRadius)
{
  EXPECT_NEAR(McaElement::unlinked_area(0.5, 0.5, 3), std::sqrt(2.0) * 0.25, 1e-15);
  const double rh = 2.0 * 0.5 * 2.0 / 2.5;    // 0.8
  EXPECT_NEAR(McaElement::unlinked_area(0.5, 2.0, 3), std::sqrt(2.0) * rh * rh, 1e-15);
  EXPECT_NEAR(McaElement::unlinked_area(2.0, 0.5, 3), McaElement::unlinked_area(0.5, 2.0, 3), 1e-15);
  EXPECT_NEAR(McaElement::unlinked_area(0.5, 2.0, 2), 2.0 * rh / std::sqrt(3.0), 1e-15);
}

TEST(McaElement, DyadIsTheSymmetricPart)
{
  const double n[3] = {0.6, 0.0, 0.8}, f[3] = {1.0, -2.0, 3.0};
  double sym[6];
  McaElement::dyad(n, f, sym);
  const int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
  for (int k = 0; k < 6; k++)
    EXPECT_NEAR(sym[k], 0.5 * (n[row[k]] * f[col[k]] + n[col[k]] * f[row[k]]), 1e-15) << k;
}

// six neighbours along +-x, +-y, +-z pressing with the force p S (arms q): Love's stress is
// -p S 2 q / Omega on the diagonal and nothing off it
TEST(McaElement, LoveOfAnIsotropicPressure)
{
  const double p = 3.0, area = 0.7, q = 0.5, omega = 1.25;
  double row[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  for (int axis = 0; axis < 3; axis++)
    for (const double sign : {1.0, -1.0}) {
      double n[3] = {0.0, 0.0, 0.0}, f[3], sym[6];
      n[axis] = sign;
      for (int k = 0; k < 3; k++) f[k] = -p * area * n[k];
      McaElement::dyad(n, f, sym);
      McaElement::add_love(row, q, sym);
    }
  for (int k = 0; k < 3; k++) EXPECT_NEAR(row[k] / omega, -p * area * 2.0 * q / omega, 1e-15);
  for (int k = 3; k < 6; k++) EXPECT_EQ(row[k], 0.0);
}
