// The tails of spline_tails.h (doc/pair_spline.rst): cut is the law up to Rc a; wagner's
// spline joins the law at its inflection point b with Pi, Pi', Pi'' and ends at ac with
// Pi = Pi' = 0 (LJ: b = 1.10868 a, ac = 1.52454 a); lagunov is Pi(r) (1 - ((r - Rs)/(Rc -
// Rs))^2)^2, continuous with its slope at Rs and zero with its slope at Rc.  Forces against
// central differences of the energies; derivs() against differences of eval().
#include "spline_tails.h"

#include "gtest/gtest.h"

#include <cmath>

using namespace LAMMPS_NS::ClusterDyn;

namespace {

// Morse D = 1, a = 1, alpha = 6, kappa K: b = a + ln 2 / (K alpha), Pi(b) = -3/4 D,
// f* = K alpha D / 2 (closed forms of the kappa-modified base)
SplineCoeff morse(double kappa)
{
  SplineCoeff c{};
  c.d = 1.0;
  c.a = 1.0;
  c.p = 6.0;
  c.kappa = kappa;
  MorseLaw::setup(c);
  return c;
}

TailShape morse_shape(const SplineCoeff &c, double rc_rel, double rs_rel)
{
  TailShape s{};
  s.b = c.a + std::log(2.0) / (c.kappa * c.p);
  s.pib = -0.75 * c.d;
  s.fstar = 0.5 * c.kappa * c.p * c.d;
  s.rc_rel = rc_rel;
  s.rs_rel = rs_rel;
  s.i = s.j = 1;
  return s;
}

double morse_energy(const SplineCoeff &c, double r)
{
  const double e = std::exp(-c.kappa * c.p * (r - c.a));
  return c.d * (e * e - 2.0 * e);
}

// LJ D = 1, a = 1: b = (13/7)^(1/6), Pi(b) = (7/13)^2 - 2 (7/13), f* = |Pi'(b)|
SplineCoeff lj()
{
  SplineCoeff c{};
  c.d = 1.0;
  c.a = 1.0;
  c.p = 12.0;
  c.q = 6.0;
  c.kappa = 1.0;
  LJLaw::setup(c);
  return c;
}

TailShape lj_shape()
{
  TailShape s{};
  const double x6 = 7.0 / 13.0;    // (a/b)^6
  s.b = std::pow(13.0 / 7.0, 1.0 / 6.0);
  s.pib = x6 * x6 - 2.0 * x6;
  s.fstar = 12.0 / s.b * (x6 - x6 * x6);
  s.i = s.j = 1;
  return s;
}

// the tail's energy at r (and f(r) = fpair r), scalar and SIMD forms
template <class Tail, class Law, bool SIMD = false>
double energy(const SplineCoeff &c, double r, double *force = nullptr)
{
  double fpair;
  const double e = Tail::template eval<true, Law, SIMD>(c, r * r, fpair);
  if (force) *force = fpair * r;
  return e;
}

// eval()'s force against -dE/dr, and derivs() against eval() and its differences
template <class Tail, class Law> void expect_consistent(const SplineCoeff &c, double r)
{
  const double h = 1e-5 * r;
  double f, d[4], dp[4], dm[4];
  const double e = energy<Tail, Law>(c, r, &f);
  const double fd = -(energy<Tail, Law>(c, r + h) - energy<Tail, Law>(c, r - h)) / (2.0 * h);
  EXPECT_NEAR(f, fd, 1e-7 * (1.0 + std::fabs(fd))) << "r " << r;
  Tail::template derivs<Law>(c, r, d);
  Tail::template derivs<Law>(c, r + h, dp);
  Tail::template derivs<Law>(c, r - h, dm);
  EXPECT_NEAR(d[0], e, 1e-12) << "r " << r;
  EXPECT_NEAR(d[1], -f, 1e-10 * (1.0 + std::fabs(f))) << "r " << r;
  for (int k = 1; k < 3; k++) {
    const double dk = (dp[k] - dm[k]) / (2.0 * h);
    EXPECT_NEAR(d[k + 1], dk, 1e-6 * (1.0 + std::fabs(dk))) << "derivative " << k + 1 << " r " << r;
  }
}

}    // namespace

TEST(SplineTails, CutIsTheLawUpToRc)
{
  SplineCoeff c = morse(1.2);
  CutTail::derive<MorseLaw>(c, morse_shape(c, 1.3, 0.0), nullptr);
  EXPECT_NEAR(c.rc, 1.3 * c.a, 1e-15);
  for (double r : {0.9, 1.0, 1.25}) {
    EXPECT_NEAR((energy<CutTail, MorseLaw>(c, r)), morse_energy(c, r), 1e-14);
    expect_consistent<CutTail, MorseLaw>(c, r);
  }
}

TEST(SplineTails, WagnerJoinsAtBAndEndsAtAc)
{
  for (double kappa : {1.0, 1.4}) {
    SplineCoeff c = morse(kappa);
    const TailShape s = morse_shape(c, 0.0, 0.0);
    WagnerTail::derive<MorseLaw>(c, s, nullptr);
    // the law's Pi, Pi', Pi'' at b (closed forms: Pi'' = 0, Pi' = f*)
    double below[4], above[4];
    const double eps = 1e-9;
    WagnerTail::derivs<MorseLaw>(c, s.b * (1.0 - eps), below);
    WagnerTail::derivs<MorseLaw>(c, s.b * (1.0 + eps), above);
    EXPECT_NEAR(above[0], s.pib, 1e-8) << kappa;
    EXPECT_NEAR(below[0], s.pib, 1e-8) << kappa;
    EXPECT_NEAR(above[1], s.fstar, 1e-7 * s.fstar) << kappa;
    EXPECT_NEAR(below[1], s.fstar, 1e-7 * s.fstar) << kappa;
    EXPECT_NEAR(above[2], 0.0, 1e-6 * s.fstar / s.b) << kappa;
    EXPECT_NEAR(below[2], 0.0, 1e-6 * s.fstar / s.b) << kappa;
    // at ac: Pi = Pi' = 0, and ac^2 = b^2 (5 - sqrt(16 + 24 Pi(b)/(b f*)))
    const double ac = s.b * std::sqrt(5.0 - std::sqrt(16.0 + 24.0 * s.pib / (s.b * s.fstar)));
    EXPECT_NEAR(c.rc, ac, 1e-14) << kappa;
    double end[4];
    WagnerTail::derivs<MorseLaw>(c, ac * (1.0 - 1e-12), end);
    EXPECT_NEAR(end[0], 0.0, 1e-12) << kappa;
    EXPECT_NEAR(end[1], 0.0, 1e-10) << kappa;
    // the law below b, beyond it -a2 w^2 + a3 w^3 (w = ac^2 - r^2) with the doc's a2, a3
    EXPECT_NEAR((energy<WagnerTail, MorseLaw>(c, 1.05)), morse_energy(c, 1.05), 1e-14);
    const double b2 = s.b * s.b, ac2 = ac * ac;
    const double a2 = (5.0 * b2 - ac2) * s.fstar / (8.0 * b2 * s.b * (ac2 - b2));
    const double a3 = (3.0 * b2 - ac2) * s.fstar / (12.0 * b2 * s.b * (ac2 - b2) * (ac2 - b2));
    for (double r : {s.b * (1.0 + 1e-3), 0.5 * (s.b + ac), 0.99 * ac}) {
      const double w = ac2 - r * r;
      EXPECT_NEAR((energy<WagnerTail, MorseLaw>(c, r)), -a2 * w * w + a3 * w * w * w, 1e-14) << r;
    }
    // forces and derivatives agree with the energy on both sides
    for (double r : {0.95, 0.5 * (s.b + ac), 0.98 * ac})
      expect_consistent<WagnerTail, MorseLaw>(c, r);
  }
}

TEST(SplineTails, WagnerOfLJEndsAt1_52454)
{
  SplineCoeff c = lj();
  WagnerTail::derive<LJLaw>(c, lj_shape(), nullptr);
  EXPECT_NEAR(c.rc, 1.52454, 5e-6);
  double f;
  EXPECT_NEAR((energy<WagnerTail, LJLaw>(c, c.rc * (1.0 - 1e-12), &f)), 0.0, 1e-12);
  EXPECT_NEAR(f, 0.0, 1e-10);
  // the SIMD form (both sides blended) gives the scalar values
  for (double r : {0.95, 1.05, 1.2, 1.5}) {
    double fs, fv;
    const double es = energy<WagnerTail, LJLaw>(c, r, &fs);
    EXPECT_NEAR((energy<WagnerTail, LJLaw, true>(c, r, &fv)), es, 1e-14);
    EXPECT_NEAR(fv, fs, 1e-13 * (1.0 + std::fabs(fs)));
  }
}

TEST(SplineTails, LagunovSmoothsFromRsToRc)
{
  for (double rs_rel : {0.0, 1.05}) {    // Rs = b by default, or given
    SplineCoeff c = morse(1.0);
    const TailShape s = morse_shape(c, 1.4, rs_rel);
    LagunovTail::derive<MorseLaw>(c, s, nullptr);
    const double rs = rs_rel > 0.0 ? rs_rel : s.b, rc = 1.4;
    EXPECT_NEAR(c.rs, rs, 1e-15);
    EXPECT_NEAR(c.rc, rc, 1e-15);
    const auto closed = [&](double r) {
      const double x = r < rs ? 0.0 : (r - rs) / (rc - rs), k = 1.0 - x * x;
      return morse_energy(c, r) * k * k;
    };
    for (double r : {0.9, rs, 0.5 * (rs + rc), 1.39}) {
      EXPECT_NEAR((energy<LagunovTail, MorseLaw>(c, r)), closed(r), 1e-14) << r;
      EXPECT_NEAR((energy<LagunovTail, MorseLaw, true>(c, r)), closed(r), 1e-14) << r;
    }
    // (not across Rs, where Pi'' jumps)
    for (double r : {0.9, 0.5 * (rs + rc), 1.39}) expect_consistent<LagunovTail, MorseLaw>(c, r);
    // value and slope continuous at Rs, zero at Rc
    double below[4], above[4], end[4];
    LagunovTail::derivs<MorseLaw>(c, rs * (1.0 - 1e-11), below);
    LagunovTail::derivs<MorseLaw>(c, rs * (1.0 + 1e-11), above);
    EXPECT_NEAR(above[0], below[0], 1e-9);
    EXPECT_NEAR(above[1], below[1], 1e-8);
    LagunovTail::derivs<MorseLaw>(c, rc * (1.0 - 1e-12), end);
    EXPECT_NEAR(end[0], 0.0, 1e-12);
    EXPECT_NEAR(end[1], 0.0, 1e-10);
  }
}

TEST(SplineTails, LagunovInflectionOfTheSmoothedLaw)
{
  SplineCoeff c = morse(1.0);
  const TailShape s = morse_shape(c, 1.3, 1.02);    // smoothing starts before b = 1.1155
  LagunovTail::derive<MorseLaw>(c, s, nullptr);
  const double b = LagunovTail::inflection<MorseLaw>(c, s.b);
  EXPECT_GT(b, 1.02);
  EXPECT_LT(b, s.b);    // the smoothing pulls the strongest attraction inwards
  double d[4];
  LagunovTail::derivs<MorseLaw>(c, b, d);
  EXPECT_NEAR(d[2], 0.0, 1e-9);
  // starting at or after b, the base's b stands
  SplineCoeff late = morse(1.0);
  LagunovTail::derive<MorseLaw>(late, morse_shape(late, 1.3, 1.2), nullptr);
  EXPECT_DOUBLE_EQ(LagunovTail::inflection<MorseLaw>(late, s.b), s.b);
}

TEST(SplineTails, WithTailDispatchesById)
{
  const auto id_of = [](auto tail) {
    return decltype(tail)::id;
  };
  for (int id : {CUT, WAGNER, LAGUNOV}) EXPECT_EQ(with_tail(id, id_of), id);
}
