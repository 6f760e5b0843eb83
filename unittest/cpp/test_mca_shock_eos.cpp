// McaShockEos (mca_shock_eos.h, doc/pair_mca.rst "Shock equation of state"): on the reference
// Hugoniot the Mie-Grueneisen pressure is the Rankine-Hugoniot jump p = rho0 us up with
// us = c0 + s up and energy rho0 up^2 / 2; the trapezoidal energy step lands on it in one jump;
// small steps follow an isentrope that comes back to its start; the viscosity's linear term acts
// both ways, its quadratic one in compression; the reference curve's limit 1 - 1/s.
#include "mca_shock_eos.h"

#include "gtest/gtest.h"

#include <cmath>

using LAMMPS_NS::ClusterDyn::McaShockEos;

namespace {

// aluminium in SI: rho0 2703 kg/m^3, c0 5350 m/s, s 1.34, Gamma0 2.0
const double RHO0 = 2703.0, C0 = 5350.0;
const McaShockEos AL{RHO0 * C0 * C0, 1.34, 2.0, 0.06, 1.2};

}    // namespace

TEST(McaShockEos, TheHugoniotIsTheRankineHugoniotJump)
{
  for (const double up : {200.0, 500.0, 1000.0, 2000.0}) {
    const double us = C0 + 1.34 * up, eta = up / us;
    const double p = RHO0 * us * up, u = 0.5 * RHO0 * up * up;
    EXPECT_NEAR(AL.hugoniot_pressure(eta), p, 1e-12 * p) << up;
    EXPECT_NEAR(AL.hugoniot_energy(eta), u, 1e-12 * u) << up;
    EXPECT_NEAR(AL.pressure(1.0 - eta, u), p, 1e-12 * p) << up;
    // 10 % more energy at that volume: Gamma0 rho0 de more pressure
    EXPECT_NEAR(AL.pressure(1.0 - eta, 1.1 * u), p + 2.0 * 0.1 * u, 1e-12 * p) << up;
  }
  EXPECT_EQ(AL.hugoniot_pressure(-0.01), -0.01 * RHO0 * C0 * C0);    // tension: linear
}

TEST(McaShockEos, OneTrapezoidalJumpLandsOnTheHugoniot)
{
  const double up = 1500.0, us = C0 + 1.34 * up, j1 = 1.0 - up / us;
  const double u = AL.energy_after(0.0, 0.0, j1, 0.0, 0.5 * (j1 - 1.0));
  EXPECT_NEAR(u, 0.5 * RHO0 * up * up, 1e-10 * RHO0 * up * up);
}

TEST(McaShockEos, SmallStepsFollowAnIsentropeThatReturns)
{
  // compress to J = 0.8 and back in 20000 steps without viscosity: at J = 0.8 the energy is
  // the isentrope's du/dJ = -p(J, u) (integrated by Runge-Kutta 4), below the Hugoniot's; it
  // comes back to zero (to the scheme's second order)
  double ui = 0.0;
  const int nk = 2000;
  const double h = -0.2 / nk;
  for (int k = 0; k < nk; k++) {
    const double jk = 1.0 + k * h;
    const double k1 = -AL.pressure(jk, ui), k2 = -AL.pressure(jk + h / 2, ui + h / 2 * k1);
    const double k3 = -AL.pressure(jk + h / 2, ui + h / 2 * k2);
    const double k4 = -AL.pressure(jk + h, ui + h * k3);
    ui += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  double j = 1.0, u = 0.0;
  const int n = 20000;
  double lowest = 0.0;
  for (int k = 1; k <= 2 * n; k++) {
    const double j1 = k <= n ? 1.0 - 0.2 * k / n : 0.8 + 0.2 * (k - n) / n;
    u = AL.energy_after(u, 0.5 * AL.pressure(j, u) * (j1 - j), j1, 0.0, 0.5 * (j1 - j));
    j = j1;
    if (k == n) {
      const double uh = AL.hugoniot_energy(0.2);
      EXPECT_LT(u, uh);
      EXPECT_NEAR(u, ui, 1e-6 * ui);
    }
    lowest = std::fmin(lowest, u);
  }
  EXPECT_NEAR(u, 0.0, 1e-6 * AL.hugoniot_energy(0.2));
  EXPECT_GE(lowest, -1e-6 * AL.hugoniot_energy(0.2));
}

TEST(McaShockEos, ViscosityIsLinearInExpansionAndQuadraticInCompression)
{
  const double rho = 3000.0, length = 1e-5, rate = 1e7;
  const double linear = rho * length * rate * 0.06 * C0;
  EXPECT_NEAR(AL.viscosity(-rate, rho, C0, length), -linear, 1e-12 * linear);
  EXPECT_EQ(AL.viscosity(0.0, rho, C0, length), 0.0);
  const double q = rho * length * rate * (0.06 * C0 + 1.44 * length * rate);
  EXPECT_NEAR(AL.viscosity(rate, rho, C0, length), q, 1e-12 * q);
}

TEST(McaShockEos, TheReferenceCurveEndsAtOneMinusOneOverS)
{
  EXPECT_NEAR(AL.limit(), 1.0 - 1.0 / 1.34, 1e-15);
  const McaShockEos flat{1.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_EQ(flat.limit(), 0.0);
  EXPECT_EQ(flat.hugoniot_pressure(0.5), 0.5);
}

TEST(McaShockEos, EnergyAfterSolvesForTheTransmittedPressure)
{
  // u1 = u0 - w0 - s1 (f p(J1, u1) + q1): the energy of an element that transmits the share f
  // of its pressure (a damaged element in tension, mca_spall_kinetics.h), for f = 1 and below
  for (const double f : {1.0, 0.6, 0.0}) {
    for (const double j1 : {1.03, 0.9}) {
      const double u0 = 2.0e6, w0 = -1.5e5, q1 = 3.0e5, s1 = 0.5 * (j1 - 1.0);
      const double u1 = AL.energy_after(u0, w0, j1, q1, s1, f);
      EXPECT_NEAR(u1, u0 - w0 - s1 * (f * AL.pressure(j1, u1) + q1), 1e-9 * std::fabs(u0))
          << "f " << f << " J1 " << j1;
    }
  }
}
