// Foundation: the plugin loads by path, registers its styles, a missing file
// fails clearly, and a run under MPI gives the serial energy.
#include "lammps_session.h"

#include "gtest/gtest.h"

#include <cmath>

using namespace clusterdyn_test;

TEST(Plugin, LoadsByPathAndRegistersEveryStyle)
{
  Session s;
  for (const auto &style : plugin_pair_styles())
    EXPECT_EQ(s.lmp->force->pair_map->count(style), 1U) << style;
  for (const auto &style : plugin_fix_styles())
    EXPECT_EQ(s.lmp->modify->fix_map->count(style), 1U) << style;
  for (const auto &style : plugin_compute_styles())
    EXPECT_EQ(s.lmp->modify->compute_map->count(style), 1U) << style;
}

TEST(Plugin, MissingFileFailsClearly)
{
  Session s(MPI_COMM_WORLD, false);
  try {
    load_plugin(s.lmp, "/nonexistent/clusterdynplugin.so");
    FAIL() << "no error for a missing plugin file";
  } catch (std::runtime_error &e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/clusterdynplugin.so"), std::string::npos);
  }
  EXPECT_EQ(s.lmp->force->pair_map->count("morse/spline"), 0U);
}

// fcc Morse block with thermal noise: energy and pressure on all ranks equal a
// serial instance of the same input (MPI_COMM_SELF)
static std::vector<std::string> morse_block(const std::string &pair_style,
                                            const std::string &pair_coeff)
{
  return {"units lj",
          "lattice fcc 1.0",
          "region box block 0 5 0 5 0 5",
          "create_box 1 box",
          "create_atoms 1 box",
          "mass 1 1.0",
          "displace_atoms all random 0.05 0.05 0.05 4711",
          "velocity all create 0.1 12345 loop geom",
          pair_style,
          pair_coeff,
          "neighbor 0.3 bin",
          "timestep 0.002",
          "fix 1 all nve",
          "thermo_style custom step pe ke press",
          "run 50"};
}

TEST(Plugin, StockMorseMpiEqualsSerial)
{
  const auto input = morse_block("pair_style morse 1.8", "pair_coeff * * 1.0 5.0 1.1");
  const auto serial = Session::run(MPI_COMM_SELF, input, {"pe", "ke", "press"});
  const auto parallel = Session::run(MPI_COMM_WORLD, input, {"pe", "ke", "press"});
  const double pe = serial.thermo[0];
  EXPECT_LT(pe, 0.0);
  EXPECT_NEAR(parallel.thermo[0], pe, 1e-10 * std::fabs(pe));
  EXPECT_NEAR(parallel.thermo[1], serial.thermo[1], 1e-10 * std::fabs(pe));
  EXPECT_NEAR(parallel.thermo[2], serial.thermo[2], 1e-8 * std::fabs(pe));
}
