// McaHourglassSpring (mca_hourglass_spring.h, doc/pair_mca.rst "The hourglass spring"): the
// pull S b e_hg with b the series of the halves, and the energy as the pull's work by the
// trapezoid rule over each step, which is S b e^2 / 2 exactly while b holds and e_hg follows
// the pair's motion, and the work (not S b e^2 / 2) once b changes.
#include "mca_hourglass_spring.h"

#include "gtest/gtest.h"

#include <array>

using LAMMPS_NS::ClusterDyn::McaContact;
using LAMMPS_NS::ClusterDyn::McaHourglassSpring;

namespace {

using C = McaContact;

std::array<double, C::NVALUES> pair_values(double area)
{
  std::array<double, C::NVALUES> v{};
  v[C::AREA] = area;
  return v;
}

}    // namespace

TEST(McaHourglassSpring, PullsWithTheHalvesInSeries)
{
  auto v = pair_values(0.3);
  v[C::HG] = 0.02;
  double energy;
  const double f = McaHourglassSpring::pull(v.data(), 2.0, 6.0, false, energy);
  EXPECT_DOUBLE_EQ(f, 0.3 * 1.5 * 0.02);
  EXPECT_EQ(energy, 0.0);    // a setup does no work
  EXPECT_DOUBLE_EQ(v[C::FHG], f);
  EXPECT_EQ(McaHourglassSpring::pull(v.data(), 0.0, 0.0, false, energy), 0.0);
}

TEST(McaHourglassSpring, EnergyIsTheWorkOfThePull)
{
  // a linear spring stretched in unequal steps: the trapezoid sum is S b e^2 / 2 exactly
  auto v = pair_values(0.5);
  const double b = 4.0, steps[] = {0.01, 0.03, -0.015, 0.002};
  double energy, e = 0.0;
  McaHourglassSpring::pull(v.data(), 2.0 * b, 2.0 * b, false, energy);
  for (const double dr : steps) {
    e += dr;
    v[C::HG] = e;
    v[C::DR] = dr;
    McaHourglassSpring::pull(v.data(), 2.0 * b, 2.0 * b, true, energy);
    EXPECT_NEAR(energy, 0.5 * 0.5 * b * e * e, 1e-17);
  }
  // stiffened at a fixed e_hg: no motion, no work, the energy holds (S b e^2 / 2 would jump)
  v[C::DR] = 0.0;
  const double held = energy;
  McaHourglassSpring::pull(v.data(), 4.0 * b, 4.0 * b, true, energy);
  EXPECT_EQ(energy, held);
  // released along the stiffer spring: it gives back (F_before + F_now) dr / 2
  const double f0 = v[C::FHG];
  v[C::HG] = 0.0;
  v[C::DR] = -e;
  const double f1 = McaHourglassSpring::pull(v.data(), 4.0 * b, 4.0 * b, true, energy);
  EXPECT_EQ(f1, 0.0);
  EXPECT_NEAR(energy, held - 0.5 * f0 * e, 1e-17);
  McaHourglassSpring::clear(v.data());
  EXPECT_EQ(v[C::EHG] + v[C::FHG] + v[C::HG], 0.0);
}
