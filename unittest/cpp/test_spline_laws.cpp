// The base laws of spline_laws.h against their textbook forms (doc/pair_spline.rst): energy
// and force f = -Pi' at chosen r, the force against a central difference of the energy, the
// derivatives of derivs() against differences of each other, the kappa modification
// Pi_K(r) = Pi(K (r - a) + a), the inflection points and the stock lj/cut and mie/cut forms.
#include "spline_laws.h"

#include "gtest/gtest.h"

#include <cmath>
#include <functional>

using namespace LAMMPS_NS::ClusterDyn;

namespace {

// the coefficients of Law, set up (derivs() of Mie reads setup()'s constants)
template <class Law> SplineCoeff coeff(double d, double a, double p, double q, double kappa)
{
  SplineCoeff c{};
  c.d = d;
  c.a = a;
  c.p = p;
  c.q = q;
  c.kappa = kappa;
  Law::setup(c);
  return c;
}

// -dE/dr by a central difference (step 1e-5 r: truncation ~1e-10, round-off ~1e-11 relative)
double force_fd(const std::function<double(double)> &energy, double r)
{
  const double h = 1e-5 * r;
  return -(energy(r + h) - energy(r - h)) / (2.0 * h);
}

// eval<KAPPA>() of Law against a closed-form energy E(r) and force F(r) at radii rs
template <class Law, bool KAPPA>
void expect_law(const SplineCoeff &c, const std::function<double(double)> &energy,
                const std::function<double(double)> &force, std::initializer_list<double> rs)
{
  const auto eval = [&](double r) {
    double fpair;
    return Law::template eval<KAPPA>(c, r * r, fpair);
  };
  for (double r : rs) {
    double fpair;
    const double e = Law::template eval<KAPPA>(c, r * r, fpair);
    const double scale = c.d / c.a;    // forces are of order D/a
    EXPECT_NEAR(e, energy(r), 1e-12 * c.d + 1e-12 * std::fabs(energy(r)))
        << Law::style << " r " << r;
    EXPECT_NEAR(fpair * r, force(r), 1e-12 * scale + 1e-12 * std::fabs(force(r)))
        << Law::style << " r " << r;
    EXPECT_NEAR(fpair * r, force_fd(eval, r), 1e-7 * (scale + std::fabs(force(r))))
        << Law::style << " r " << r;
  }
}

// derivs(): d[0] the closed form, d[k+1] the central difference of d[k]
template <class Law>
void expect_derivs(const SplineCoeff &c, const std::function<double(double)> &energy)
{
  for (double s : {0.9 * c.a, c.a, 1.1 * c.a, 1.35 * c.a}) {
    double d[4], dp[4], dm[4];
    const double h = 1e-5 * s;
    Law::derivs(c, s, d);
    Law::derivs(c, s + h, dp);
    Law::derivs(c, s - h, dm);
    EXPECT_NEAR(d[0], energy(s), 1e-12 * c.d) << Law::style << " s " << s;
    for (int k = 0; k < 3; k++) {
      const double fd = (dp[k] - dm[k]) / (2.0 * h);
      EXPECT_NEAR(d[k + 1], fd, 1e-7 * (std::fabs(fd) + c.d / std::pow(c.a, k + 1)))
          << Law::style << " derivative " << k + 1 << " s " << s;
    }
  }
}

// the minimum -D at a and Pi''(b) = 0 at the law's inflection point
template <class Law> void expect_well(const SplineCoeff &c)
{
  double d[4];
  Law::derivs(c, c.a, d);
  EXPECT_NEAR(d[0], -c.d, 1e-14 * c.d) << Law::style;
  EXPECT_NEAR(d[1], 0.0, 1e-12 * c.d / c.a) << Law::style;
  EXPECT_GT(d[2], 0.0) << Law::style;
  if (!Law::has_inflection) return;
  const double b = Law::inflection(c);
  EXPECT_GT(b, c.a) << Law::style;
  Law::derivs(c, b, d);
  EXPECT_NEAR(d[2], 0.0, 1e-12 * c.d / (c.a * c.a)) << Law::style;
}

}    // namespace

TEST(SplineLaws, MorseIsTheTextbookMorse)
{
  // reduced units, and the aluminium clusters of doc/pair_spline.rst in SI (J, m)
  struct Set {
    double d, alpha, a;
  };
  for (const Set &p : {Set{0.7, 5.5, 1.3}, Set{2.46e-6, 3.76e5, 1e-5}}) {
    const double D = p.d, alpha = p.alpha, a = p.a;
    const auto e = [&](double r) {
      return D * (std::exp(-2.0 * alpha * (r - a)) - 2.0 * std::exp(-alpha * (r - a)));
    };
    const auto f = [&](double r) {
      return 2.0 * alpha * D * (std::exp(-2.0 * alpha * (r - a)) - std::exp(-alpha * (r - a)));
    };
    const SplineCoeff c = coeff<MorseLaw>(D, a, alpha, 0.0, 1.0);
    expect_law<MorseLaw, false>(c, e, f, {0.8 * a, a, 1.15 * a, 1.6 * a});
    expect_derivs<MorseLaw>(c, e);
    expect_well<MorseLaw>(c);
    EXPECT_NEAR(MorseLaw::inflection(c), a + std::log(2.0) / alpha, 1e-15 * a);
  }
}

TEST(SplineLaws, MorseKappaIsMorseWithKappaAlpha)
{
  const double D = 0.7, alpha = 5.5, a = 1.3, K = 1.3;
  const auto e = [&](double r) {
    return D * (std::exp(-2.0 * K * alpha * (r - a)) - 2.0 * std::exp(-K * alpha * (r - a)));
  };
  const auto f = [&](double r) {
    return 2.0 * K * alpha * D *
        (std::exp(-2.0 * K * alpha * (r - a)) - std::exp(-K * alpha * (r - a)));
  };
  const SplineCoeff c = coeff<MorseLaw>(D, a, alpha, 0.0, K);
  expect_law<MorseLaw, false>(c, e, f, {0.85 * a, 1.1 * a, 1.4 * a});
}

TEST(SplineLaws, HarmonicIsTheParabolaOfMorsesStiffness)
{
  const double D = 2.0, alpha = 3.0, a = 0.9;
  const auto e = [&](double r) {
    return alpha * alpha * D * (r - a) * (r - a) - D;
  };
  const auto f = [&](double r) {
    return -2.0 * alpha * alpha * D * (r - a);
  };
  const SplineCoeff c = coeff<HarmonicLaw>(D, a, alpha, 0.0, 1.0);
  expect_law<HarmonicLaw, false>(c, e, f, {0.7 * a, a, 1.2 * a});
  expect_derivs<HarmonicLaw>(c, e);
  expect_well<HarmonicLaw>(c);
  // C = Pi''(a) = 2 alpha^2 D, Morse's
  double dh[4], dm[4];
  HarmonicLaw::derivs(c, a, dh);
  MorseLaw::derivs(coeff<MorseLaw>(D, a, alpha, 0.0, 1.0), a, dm);
  EXPECT_NEAR(dh[2], 2.0 * alpha * alpha * D, 1e-13);
  EXPECT_NEAR(dm[2], dh[2], 1e-12);
  // kappa K: the stiffness K^2 C
  const double K = 0.8;
  const auto ek = [&](double r) {
    return K * K * alpha * alpha * D * (r - a) * (r - a) - D;
  };
  const auto fk = [&](double r) {
    return -2.0 * K * K * alpha * alpha * D * (r - a);
  };
  expect_law<HarmonicLaw, false>(coeff<HarmonicLaw>(D, a, alpha, 0.0, K), ek, fk,
                                 {0.7 * a, 1.3 * a});
}

TEST(SplineLaws, LJIsLennardJonesInBothKernels)
{
  const double D = 1.7, a = 1.2;
  const auto e = [&](double r) {
    return D * (std::pow(a / r, 12) - 2.0 * std::pow(a / r, 6));
  };
  const auto f = [&](double r) {
    return 12.0 * D / r * (std::pow(a / r, 12) - std::pow(a / r, 6));
  };
  for (double r : {0.9 * a, a, 1.3 * a}) {    // lj/cut: 4 eps ((sigma/r)^12 - (sigma/r)^6)
    const double sigma = a / std::pow(2.0, 1.0 / 6.0), sr6 = std::pow(sigma / r, 6);
    EXPECT_NEAR(e(r), 4.0 * D * (sr6 * sr6 - sr6), 1e-13 * D);
  }
  const SplineCoeff c = coeff<LJLaw>(D, a, 12.0, 6.0, 1.0);
  expect_law<LJLaw, false>(c, e, f, {0.9 * a, a, 1.3 * a, 2.0 * a});
  expect_law<LJLaw, true>(c, e, f, {0.9 * a, a, 1.3 * a, 2.0 * a});
  expect_derivs<LJLaw>(c, e);
  expect_well<LJLaw>(c);
  // b = (13/7)^(1/6) a = 1.10868 a (doc/pair_spline.rst)
  EXPECT_NEAR(LJLaw::inflection(c), std::pow(13.0 / 7.0, 1.0 / 6.0) * a, 1e-14);
  EXPECT_NEAR(LJLaw::inflection(c) / a, 1.10868, 5e-6);
}

TEST(SplineLaws, MieIsMieCut)
{
  const double D = 0.9, a = 1.1, n = 10.0, m = 5.0;
  const auto e = [&](double r) {
    return D / (n - m) * (m * std::pow(a / r, n) - n * std::pow(a / r, m));
  };
  const auto f = [&](double r) {
    return D * n * m / ((n - m) * r) * (std::pow(a / r, n) - std::pow(a / r, m));
  };
  // mie/cut: C eps ((sigma/r)^n - (sigma/r)^m), C = n/(n-m) (n/m)^(m/(n-m)), a = sigma (n/m)^(1/(n-m))
  const double sigma = a / std::pow(n / m, 1.0 / (n - m));
  const double C = n / (n - m) * std::pow(n / m, m / (n - m));
  for (double r : {0.9 * a, a, 1.4 * a})
    EXPECT_NEAR(e(r), C * D * (std::pow(sigma / r, n) - std::pow(sigma / r, m)), 1e-13 * D);
  const SplineCoeff c = coeff<MieLaw>(D, a, n, m, 1.0);
  expect_law<MieLaw, false>(c, e, f, {0.9 * a, a, 1.4 * a});
  expect_law<MieLaw, true>(c, e, f, {0.9 * a, a, 1.4 * a});
  expect_derivs<MieLaw>(c, e);
  expect_well<MieLaw>(c);
  // Mie(12, 6) is LJ
  double dm[4], dl[4];
  MieLaw::derivs(coeff<MieLaw>(D, a, 12.0, 6.0, 1.0), 1.2 * a, dm);
  LJLaw::derivs(coeff<LJLaw>(D, a, 12.0, 6.0, 1.0), 1.2 * a, dl);
  for (int k = 0; k < 4; k++) EXPECT_NEAR(dm[k], dl[k], 1e-12 * (1.0 + std::fabs(dl[k])));
}

TEST(SplineLaws, KappaModifiesTheArgument)
{
  // Pi_K(r) = Pi(K (r - a) + a), f_K(r) = K f(K (r - a) + a), for the kappa kernels of LJ and Mie
  const double D = 1.3, a = 0.95, K = 1.4, n = 9.0, m = 6.0;
  const auto s = [&](double r) {
    return K * (r - a) + a;
  };
  const auto e_lj = [&](double r) {
    return D * (std::pow(a / s(r), 12) - 2.0 * std::pow(a / s(r), 6));
  };
  const auto f_lj = [&](double r) {
    return K * 12.0 * D / s(r) * (std::pow(a / s(r), 12) - std::pow(a / s(r), 6));
  };
  expect_law<LJLaw, true>(coeff<LJLaw>(D, a, 12.0, 6.0, K), e_lj, f_lj, {0.85 * a, a, 1.2 * a});
  const auto e_mie = [&](double r) {
    return D / (n - m) * (m * std::pow(a / s(r), n) - n * std::pow(a / s(r), m));
  };
  const auto f_mie = [&](double r) {
    return K * D * n * m / ((n - m) * s(r)) * (std::pow(a / s(r), n) - std::pow(a / s(r), m));
  };
  expect_law<MieLaw, true>(coeff<MieLaw>(D, a, n, m, K), e_mie, f_mie, {0.85 * a, a, 1.2 * a});
}
