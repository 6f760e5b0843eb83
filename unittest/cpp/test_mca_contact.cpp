// McaContact (mca_contact.h, doc/pair_mca.rst "The pair law", "The moment of a link",
// "Rotations and objectivity"): two halves a_i = 2 G_i / R_i in series carry one stress;
// Turn is the rotation by phi (against a rotation built from an orthonormal frame about the
// axis); slide() turns tau with the contact so that a rigid rotation makes no stress, and adds
// a du_t; moment() bends with a S^2/(4 pi) and twists with twice that (a 2d strip: a S^3/12), energy 1/2 m.phi.
#include "mca_contact.h"

#include "gtest/gtest.h"

#include <array>
#include <cmath>

using LAMMPS_NS::ClusterDyn::McaContact;

namespace {

using Vec = std::array<double, 3>;

double dot(const Vec &a, const Vec &b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(const Vec &a, const Vec &b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec scaled(const Vec &a, double s)
{
  return {a[0] * s, a[1] * s, a[2] * s};
}
Vec unit(const Vec &a)
{
  return scaled(a, 1.0 / std::sqrt(dot(a, a)));
}

// v turned by the angle |phi| about phi, right-handed, in the frame (k, e1, e2 = k x e1)
Vec rotated(const Vec &v, const Vec &phi)
{
  const double angle = std::sqrt(dot(phi, phi)), c = std::cos(angle), s = std::sin(angle);
  const Vec k = unit(phi), e1 = unit(cross(k, {0.3, -0.5, 0.8})), e2 = cross(k, e1);
  const double vk = dot(v, k), v1 = dot(v, e1), v2 = dot(v, e2);
  Vec out;
  for (int m = 0; m < 3; m++)
    out[m] = vk * k[m] + v1 * (c * e1[m] + s * e2[m]) + v2 * (c * e2[m] - s * e1[m]);
  return out;
}

Vec turned(const Vec &v, const Vec &phi)
{
  const McaContact::Turn turn(phi.data());
  Vec out = v;
  turn.apply(out.data());
  return out;
}

void expect_vec(const Vec &got, const Vec &want, double tol)
{
  for (int m = 0; m < 3; m++) EXPECT_NEAR(got[m], want[m], tol) << "component " << m;
}

}    // namespace

TEST(McaContact, TurnIsTheRotationByPhi)
{
  // about z by 90 degrees: x -> y, y -> -x
  expect_vec(turned({1.0, 0.0, 0.0}, {0.0, 0.0, M_PI / 2}), {0.0, 1.0, 0.0}, 1e-15);
  expect_vec(turned({0.0, 1.0, 0.0}, {0.0, 0.0, M_PI / 2}), {-1.0, 0.0, 0.0}, 1e-15);
  const Vec v = {0.7, -1.3, 2.1};
  for (const Vec &phi : {Vec{0.1, 0.2, -0.3}, Vec{-1.5, 0.4, 2.0}, Vec{0.0, 1e-7, 0.0}}) {
    const Vec t = turned(v, phi);
    expect_vec(t, rotated(v, phi), 1e-14);
    EXPECT_NEAR(dot(t, t), dot(v, v), 1e-13);              // length kept
    expect_vec(turned(phi, phi), phi, 1e-15);              // the axis stays
    expect_vec(turned(t, scaled(phi, -1.0)), v, 1e-14);    // and back
  }
  expect_vec(turned(v, {0.0, 0.0, 0.0}), v, 0.0);    // no turn
}

// a step's turn is small: below a = 1e-2 the factors come from their series (mca_contact.h);
// on both sides of that bound, and across it, the turn is the rotation to round-off (a wrong
// coefficient of a^4 would show as 1e-11)
TEST(McaContact, SmallTurnsByTheSeriesAreTheRotation)
{
  const Vec v = {0.7, -1.3, 2.1}, axis = unit({0.3, 0.9, -0.4});
  const double bound = std::sqrt(McaContact::Turn::SERIES);
  EXPECT_DOUBLE_EQ(bound, 1e-2);
  for (double angle : {1e-9, 1e-5, 1e-3, 5e-3, 0.9999999 * bound, 1.0000001 * bound, 0.02}) {
    const Vec phi = scaled(axis, angle), t = turned(v, phi);
    expect_vec(t, rotated(v, phi), 4e-15);    // a few ulp of |v| (the reference's own round-off)
    EXPECT_NEAR(dot(t, t), dot(v, v), 4e-15) << "angle " << angle;
    // the part along the axis stays, the rest turns by the angle
    const Vec along = scaled(axis, dot(v, axis)), vp = {v[0] - along[0], v[1] - along[1],
                                                        v[2] - along[2]};
    const Vec tp = {t[0] - along[0], t[1] - along[1], t[2] - along[2]};
    EXPECT_NEAR(dot(t, axis), dot(v, axis), 1e-15);
    EXPECT_NEAR(dot(cross(vp, tp), axis) / dot(vp, vp), std::sin(angle), 1e-15) << "angle " << angle;
  }
  // no jump at the bound: turns just below and just above it differ by their angles' difference
  const Vec below = turned(v, scaled(axis, bound * (1.0 - 1e-9)));
  const Vec above = turned(v, scaled(axis, bound * (1.0 + 1e-9)));
  expect_vec(below, above, 1e-15 + 2e-11 * std::sqrt(dot(v, v)));
}

TEST(McaContact, RigidRotationMakesNoStress)
{
  const double a = 7.0;
  const Vec phi = {0.02, -0.05, 0.03};    // the contact's spin x dt
  const Vec d0 = {1.0, 0.2, -0.1}, n0 = unit(d0);
  const Vec t0 = scaled(unit(cross(n0, {0.0, 0.0, 1.0})), 0.4);    // in the tangent plane
  Vec tau = t0, dprev = d0;
  const Vec d = rotated(d0, phi), n = unit(d);
  const McaContact::Turn turn(phi.data());
  McaContact::slide(tau.data(), dprev.data(), d.data(), n.data(), &turn, a);
  expect_vec(tau, rotated(t0, phi), 1e-14);    // carried along, no increment
  expect_vec(dprev, d, 0.0);
}

TEST(McaContact, SlideAddsTheTangentialPartOnly)
{
  const double a = 7.0;
  const Vec n = {0.0, 0.0, 1.0}, dprev0 = {0.0, 0.0, 1.0}, d = {0.01, -0.02, 1.03};
  Vec tau = {0.1, 0.0, 0.0}, dprev = dprev0, dut = {9.0, 9.0, 9.0};
  McaContact::slide(tau.data(), dprev.data(), d.data(), n.data(), nullptr, a, dut.data());
  expect_vec(tau, {0.1 + a * 0.01, -a * 0.02, 0.0}, 1e-15);
  expect_vec(dut, {0.01, -0.02, 0.0}, 1e-15);    // the slide it reports: du's tangential part
  // a stress left out of the tangent plane is brought into it at its magnitude
  Vec tilted = {0.3, 0.0, 0.4}, still = d;
  McaContact::slide(tilted.data(), still.data(), d.data(), n.data(), nullptr, a);
  expect_vec(tilted, {0.5, 0.0, 0.0}, 1e-15);
}

TEST(McaContact, MomentBendsAndTwists)
{
  const double a = 3.0, area = 0.9, bend = a * area * area / (4.0 * M_PI);
  const Vec n = unit({1.0, 1.0, 0.0});
  Vec m;
  const Vec phi_b = {0.0, 0.0, 0.02};    // about an axis across the pair: bending
  double e = McaContact::moment(phi_b.data(), n.data(), a, area, false, m.data());
  expect_vec(m, scaled(phi_b, bend), 1e-15);
  EXPECT_NEAR(e, 0.5 * bend * dot(phi_b, phi_b), 1e-17);
  const Vec phi_t = scaled(n, 0.03);    // about the pair's line: twisting, J = 2 I
  e = McaContact::moment(phi_t.data(), n.data(), a, area, false, m.data());
  expect_vec(m, scaled(phi_t, 2.0 * bend), 1e-15);
  EXPECT_NEAR(e, bend * dot(phi_t, phi_t), 1e-17);
  // any rotation: E = 1/2 m.phi, and m = dE/dphi
  const Vec phi = {0.01, -0.03, 0.02};
  e = McaContact::moment(phi.data(), n.data(), a, area, false, m.data());
  EXPECT_NEAR(e, 0.5 * dot(m, phi), 1e-17);
  const double h = 1e-6;
  for (int k = 0; k < 3; k++) {
    Vec p = phi, q = phi, mm;
    p[k] += h;
    q[k] -= h;
    const double de = McaContact::moment(p.data(), n.data(), a, area, false, mm.data()) -
        McaContact::moment(q.data(), n.data(), a, area, false, mm.data());
    EXPECT_NEAR(m[k], de / (2.0 * h), 1e-9 * bend) << k;
  }
}

// in 2d the contact is a strip of length S (unit thickness): I = S^3 / 12 about z
TEST(McaContact, PlanarMomentBendsTheStrip)
{
  const double a = 3.0, area = 0.9, bend = a * area * area * area / 12.0;
  const Vec n = unit({1.0, 1.0, 0.0}), phi = {0.0, 0.0, 0.02};
  Vec m;
  const double e = McaContact::moment(phi.data(), n.data(), a, area, true, m.data());
  expect_vec(m, scaled(phi, bend), 1e-15);
  EXPECT_NEAR(e, 0.5 * bend * dot(phi, phi), 1e-17);
}
