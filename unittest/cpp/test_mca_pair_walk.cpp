// McaPairFrame (mca_pair_walk.h, doc/pair_mca.rst "Objectivity"): one pair's separation, length,
// direction, the arms q_ij = r R_i / (R_i + R_j) and q_ji = r - q_ij to the contact point, and
// the turn of the pair's frame by the contact's spin, dt (q_ij omega_i + q_ji omega_j) / r.
#include "mca_pair_walk.h"

#include "gtest/gtest.h"

#include <cmath>

using namespace LAMMPS_NS::ClusterDyn;

TEST(McaPairFrame, SeparationDirectionAndArms)
{
  double xi[3] = {1.0, 2.0, 3.0}, xj[3] = {4.0, 6.0, 3.0};
  double *x[2] = {xi, xj};
  McaPairFrame p(x, 0, 1);
  EXPECT_EQ(p.rsq, 25.0);
  p.orient(0.5, 2.0);
  EXPECT_EQ(p.r, 5.0);
  EXPECT_NEAR(p.n[0], 0.6, 1e-15);
  EXPECT_NEAR(p.n[1], 0.8, 1e-15);
  EXPECT_EQ(p.n[2], 0.0);
  EXPECT_NEAR(p.qi, 1.0, 1e-15);    // 5 x 0.5 / 2.5: the contact point divides r as R_i : R_j
  EXPECT_NEAR(p.qj, 4.0, 1e-15);
  EXPECT_DOUBLE_EQ(p.inverse, 0.2);    // 1 / r, which the direction and the turn take
}

// a direction of unit length from the reciprocal of r, to round-off, off the axes too
TEST(McaPairFrame, DirectionIsUnitFromTheReciprocal)
{
  double xi[3] = {0.3, -1.7, 2.9}, xj[3] = {-2.2, 0.4, 1.3};
  double *x[2] = {xi, xj};
  McaPairFrame p(x, 0, 1);
  p.orient(1.0, 1.0);
  EXPECT_NEAR(p.r * p.inverse, 1.0, 1e-15);
  EXPECT_NEAR(McaContact::dot(p.n, p.n), 1.0, 4e-16);
  for (int k = 0; k < 3; k++) EXPECT_NEAR(p.n[k], p.d[k] / p.r, 1e-15);
}

// both elements spinning at Omega (a rigid rotation): the frame turns by Omega dt whatever the
// radii; one spinning alone turns it by its arm's share
TEST(McaPairFrame, TurnOfTheContact)
{
  double xi[3] = {0.0, 0.0, 0.0}, xj[3] = {0.0, 1.0, 0.0};
  double *x[2] = {xi, xj};
  McaPairFrame p(x, 0, 1);
  p.orient(0.3, 0.7);
  const double omega[3] = {0.0, 0.0, 2.0}, still[3] = {0.0, 0.0, 0.0}, dt = 0.1;
  const McaContact::Turn rigid = p.turn(omega, omega, dt);
  double v[3] = {1.0, 0.0, 0.0};
  rigid.apply(v);
  EXPECT_NEAR(v[0], std::cos(0.2), 1e-15);
  EXPECT_NEAR(v[1], std::sin(0.2), 1e-15);
  const McaContact::Turn one = p.turn(omega, still, dt);
  double u[3] = {1.0, 0.0, 0.0};
  one.apply(u);
  EXPECT_NEAR(std::atan2(u[1], u[0]), 0.2 * 0.3, 1e-15);
}
