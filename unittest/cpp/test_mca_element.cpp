// McaElement (mca_element.h, doc/pair_mca.rst "Elements"): an element of radius R in a packing
// of fraction F stands for Omega = (4 pi / 3) R^3 / F; Love's formula sums q sym(n (x) f) over
// its pairs.
#include "mca_element.h"

#include "gtest/gtest.h"

#include <cmath>

using LAMMPS_NS::ClusterDyn::McaElement;

TEST(McaElement, VolumeIsTheSphereOverThePackingFraction)
{
  const double fcc = M_PI / std::sqrt(18.0);
  EXPECT_NEAR(McaElement::volume(0.5, fcc), 1.0 / std::sqrt(2.0), 1e-15);    // fcc cell / 4
  EXPECT_NEAR(McaElement::volume(2.0, 1.0), 32.0 * M_PI / 3.0, 1e-13);
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
