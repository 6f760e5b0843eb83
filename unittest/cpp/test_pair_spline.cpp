// Spline pair styles under MPI: every law and tail gives the serial energy,
// pressure and per-atom forces on 1, 2 and 4 ranks, with newton on and off.
#include "lammps_session.h"

#include "atom.h"
#include "gtest/gtest.h"

#include <cmath>

using namespace clusterdyn_test;

namespace {

struct Case {
  const char *pair_style;
  const char *pair_coeff;
};

const Case cases[] = {
    {"morse/spline cut 1.2", "1.0 6.0 1.0"},
    {"morse/spline wagner", "1.0 6.0 1.0 kappa 1.1"},
    {"morse/spline lagunov 1.4", "1.0 6.0 1.0"},
    {"lj/spline cut 1.4", "1.0 1.0"},
    {"lj/spline wagner", "1.0 1.0 kappa 1.2"},
    {"mie/spline lagunov 1.5 start 1.1", "1.0 1.0 10 5"},
    {"harmonic/spline cut 1.2", "1.0 6.0 1.0"},
    {"harmonic/spline lagunov 1.3 start 1.1", "1.0 6.0 1.0 kappa 0.9"},
};

std::vector<std::string> block(const Case &c, const char *newton)
{
  return {fmt::format("newton {}", newton),
          "units lj",
          "lattice fcc 1.4142135623730951",    // nearest neighbours at a = 1
          "region box block 0 4 0 4 0 4",
          "create_box 1 box",
          "create_atoms 1 box",
          "mass 1 1.0",
          "reset_atoms id sort yes",    // atom IDs independent of the decomposition
          "displace_atoms all random 0.03 0.03 0.03 4711",
          "velocity all create 0.05 12345 loop geom",
          fmt::format("pair_style {}", c.pair_style),
          fmt::format("pair_coeff * * {}", c.pair_coeff),
          "pair_modify shift yes",
          "neighbor 0.3 bin",
          "timestep 0.001",
          "fix 1 all nve",
          "thermo_style custom step pe ke press",
          "run 20"};
}

}    // namespace

TEST(PairSplineMpi, EveryLawAndTailEqualsSerial)
{
  for (const auto &c : cases) {
    for (const char *newton : {"on", "off"}) {
      const auto input = block(c, newton);
      const auto serial = Session::run(MPI_COMM_SELF, input, {"pe", "press"});
      const auto parallel = Session::run(MPI_COMM_WORLD, input, {"pe", "press"});
      const double pe = serial.thermo[0];
      ASSERT_TRUE(std::isfinite(pe)) << c.pair_style;
      EXPECT_LT(pe, 0.0) << c.pair_style;
      EXPECT_NEAR(parallel.thermo[0], pe, 1e-10 * std::fabs(pe)) << c.pair_style << " " << newton;
      EXPECT_NEAR(parallel.thermo[1], serial.thermo[1], 1e-8 * std::fabs(pe))
          << c.pair_style << " " << newton;
      const auto &fs = serial.f, &fp = parallel.f;
      double fmax = 0.0, dmax = 0.0;
      for (size_t k = 0; k < fs.size(); k++) {
        fmax = std::max(fmax, std::fabs(fs[k]));
        dmax = std::max(dmax, std::fabs(fs[k] - fp[k]));
      }
      EXPECT_GT(fmax, 0.0) << c.pair_style;
      EXPECT_LE(dmax, 1e-9 * fmax) << c.pair_style << " " << newton;
    }
  }
}
