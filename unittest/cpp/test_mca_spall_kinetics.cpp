// McaSpallKinetics (mca_spall_kinetics.h, doc/pair_mca.rst "Spall kinetics"): the cumulative
// damage dD/dt = A (sigma~ / S)^lambda of Tuler and Butcher, with lambda and A from the rate law
// sigma_sp = S (rate / rate_ref)^m; under a linear ramp sigma~ = K rate t, integrated here with
// small steps, the transmitted tension (1 - D) sigma~ peaks at S (rate / rate_ref)^m, at D =
// 1 / (lambda + 2); the damage of the ramp against its closed form; the trapezoid rule second
// order; no growth in compression, D never above 1.
#include "mca_spall_kinetics.h"

#include "gtest/gtest.h"

#include <cmath>

using LAMMPS_NS::ClusterDyn::McaSpallKinetics;

namespace {

constexpr double S = 1.2e9, RATE_REF = 1.0e5, K = 7.737e10;

struct Peak {
  double stress, damage, time;
};

// the peak of (1 - D) sigma~ under sigma~ = K rate t, steps of dt
Peak ramp_peak(const McaSpallKinetics &law, double rate, double dt)
{
  Peak best{0.0, 0.0, 0.0};
  double d = 0.0;
  for (long n = 1; d < 1.0; n++) {
    const double before = K * rate * (n - 1) * dt, after = K * rate * n * dt;
    d = law.advance(d, before, after, dt);
    const double carried = -McaSpallKinetics::transmitted(-after, d);
    if (carried > best.stress) best = {carried, d, n * dt};
  }
  return best;
}

}    // namespace

TEST(McaSpallKinetics, ExponentAndRateFromTheRateLaw)
{
  const auto law = McaSpallKinetics::of_rate_law(S, RATE_REF, 0.2, K);
  EXPECT_DOUBLE_EQ(law.lambda, 4.0);
  const double c = 5.0 / std::pow(6.0, 1.2);
  EXPECT_DOUBLE_EQ(McaSpallKinetics::peak_share(4.0), c);
  EXPECT_NEAR(law.rate, 5.0 * std::pow(c, 5.0) * K / S * RATE_REF, 1e-12 * law.rate);
  EXPECT_TRUE(law.active());
  EXPECT_FALSE(McaSpallKinetics{}.active());
}

TEST(McaSpallKinetics, RampPeaksAtTheRateLawsStrength)
{
  for (const double m : {0.1, 0.2, 0.33}) {
    const auto law = McaSpallKinetics::of_rate_law(S, RATE_REF, m, K);
    for (const double rate : {1.0e3, 1.0e5, 1.0e7}) {
      const double strength = S * std::pow(rate / RATE_REF, m);
      const double dt = strength / (K * rate) / 20000.0;    // 20,000 steps to the strength
      const Peak p = ramp_peak(law, rate, dt);
      EXPECT_NEAR(p.stress / strength, 1.0, 1e-6) << "m " << m << " rate " << rate;
      EXPECT_NEAR(p.damage, 1.0 / (law.lambda + 2.0), 1e-3) << "m " << m << " rate " << rate;
    }
  }
}

TEST(McaSpallKinetics, RampDamageFollowsItsClosedForm)
{
  // D(t) = A (K rate / S)^lambda t^(lambda + 1) / (lambda + 1)
  const auto law = McaSpallKinetics::of_rate_law(S, RATE_REF, 0.25, K);
  const double rate = 2.0e5, dt = 1.0e-11;
  double d = 0.0;
  for (int n = 1; n <= 2000; n++) {
    d = law.advance(d, K * rate * (n - 1) * dt, K * rate * n * dt, dt);
    if (n % 500 == 0) {
      const double t = n * dt;
      const double exact = law.rate * std::pow(K * rate / S, law.lambda) *
          std::pow(t, law.lambda + 1.0) / (law.lambda + 1.0);
      EXPECT_NEAR(d / exact, 1.0, 1e-4) << "step " << n;
    }
  }
}

TEST(McaSpallKinetics, TrapezoidIsSecondOrder)
{
  // the damage at a fixed time of the ramp: halving dt quarters the error
  const auto law = McaSpallKinetics::of_rate_law(S, RATE_REF, 0.2, K);
  const double rate = 1.0e5, time = 1.8e-7;
  const double exact = law.rate * std::pow(K * rate / S, law.lambda) *
      std::pow(time, law.lambda + 1.0) / (law.lambda + 1.0);
  double error[2];
  for (int k = 0; k < 2; k++) {
    const int n = 40 << k;
    const double dt = time / n;
    double d = 0.0;
    for (int i = 1; i <= n; i++) d = law.advance(d, K * rate * (i - 1) * dt, K * rate * i * dt, dt);
    error[k] = std::fabs(d - exact);
  }
  ASSERT_GT(exact, 0.05);
  ASSERT_LT(exact, 1.0);
  EXPECT_NEAR(error[0] / error[1], 4.0, 0.1);
}

TEST(McaSpallKinetics, NoGrowthInCompressionAndNeverBeyondWhole)
{
  const auto law = McaSpallKinetics::of_rate_law(S, RATE_REF, 0.2, K);
  EXPECT_EQ(law.advance(0.3, -2.0 * S, -S, 1.0), 0.3);
  EXPECT_EQ(law.growth(0.0), 0.0);
  EXPECT_EQ(law.advance(0.9, 10.0 * S, 10.0 * S, 1.0), 1.0);
  EXPECT_EQ(law.advance(1.0, 10.0 * S, 10.0 * S, 1.0), 1.0);
  // half the step's growth where the tension begins during it
  EXPECT_DOUBLE_EQ(law.advance(0.0, -S, S, 1.0e-9), 0.5e-9 * law.rate);
  // the transmitted pressure: whole in compression, (1 - D) in tension
  EXPECT_EQ(McaSpallKinetics::transmitted(5.0, 0.7), 5.0);
  EXPECT_DOUBLE_EQ(McaSpallKinetics::transmitted(-5.0, 0.7), -1.5);
}
