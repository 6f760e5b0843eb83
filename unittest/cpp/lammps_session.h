// A LAMMPS instance for tests: quiet, on a given communicator, with the plugin
// loaded by path and its styles checked (plugin load only logs a failure).
// LAMMPS keeps one plugin registry per process: a second instance cannot load
// the plugin while another holds it, so sessions run one after the other and
// unload the plugin ("plugin clear") when they end.
#ifndef CLUSTERDYN_TEST_LAMMPS_SESSION_H
#define CLUSTERDYN_TEST_LAMMPS_SESSION_H

#include "force.h"
#include "input.h"
#include "modify.h"
#include "lammps.h"
#include "library.h"
#include "platform.h"

#include <mpi.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace clusterdyn_test {

// every style the plugin registers
inline const std::vector<std::string> &plugin_pair_styles()
{
  static const std::vector<std::string> styles = {
      "morse/spline", "morse/spline/omp", "lj/spline",       "lj/spline/omp",
      "mie/spline",   "mie/spline/omp",   "harmonic/spline", "harmonic/spline/omp"};
  return styles;
}

inline const std::vector<std::string> &plugin_fix_styles()
{
  static const std::vector<std::string> styles = {"viscous/relative"};
  return styles;
}

inline const std::vector<std::string> &plugin_compute_styles()
{
  static const std::vector<std::string> styles = {"dust", "pair/params"};
  return styles;
}

// load the plugin by path; throws with a clear message when it is missing or
// does not register its styles
inline void load_plugin(LAMMPS_NS::LAMMPS *lmp, const std::string &path)
{
  if (!LAMMPS_NS::platform::file_is_readable(path))
    throw std::runtime_error("plugin file " + path + " is missing or unreadable");
  lmp->input->one("plugin load " + path);
  for (const auto &style : plugin_pair_styles())
    if (lmp->force->pair_map->count(style) == 0)
      throw std::runtime_error("plugin " + path + " did not register pair style " + style);
  for (const auto &style : plugin_fix_styles())
    if (lmp->modify->fix_map->count(style) == 0)
      throw std::runtime_error("plugin " + path + " did not register fix style " + style);
  for (const auto &style : plugin_compute_styles())
    if (lmp->modify->compute_map->count(style) == 0)
      throw std::runtime_error("plugin " + path + " did not register compute style " + style);
}

class Session {
 public:
  explicit Session(MPI_Comm comm = MPI_COMM_WORLD, bool with_plugin = true)
  {
    const char *args[] = {"test", "-log", "none", "-echo", "none", "-screen", "none", "-nocite"};
    lmp = new LAMMPS_NS::LAMMPS(8, (char **) args, comm);
    if (with_plugin) load_plugin(lmp, CLUSTERDYN_PLUGIN);
  }
  ~Session()
  {
    lmp->input->one("plugin clear");
    delete lmp;
  }
  Session(const Session &) = delete;
  Session &operator=(const Session &) = delete;

  void cmd(const std::string &line) { lmp->input->one(line); }
  void cmds(const std::vector<std::string> &lines)
  {
    for (const auto &line : lines) cmd(line);
  }
  double thermo(const char *keyword) { return lammps_get_thermo(lmp, keyword); }

  // thermo keywords and per-atom forces (ordered by atom ID) after running input
  struct Result {
    std::vector<double> thermo, f;
  };
  static Result run(MPI_Comm comm, const std::vector<std::string> &input,
                    const std::vector<const char *> &keywords)
  {
    Session s(comm);
    s.cmds(input);
    Result r;
    for (const char *k : keywords) r.thermo.push_back(s.thermo(k));
    r.f.resize(3 * lammps_get_natoms(s.lmp));
    lammps_gather_atoms(s.lmp, (char *) "f", 1, 3, r.f.data());
    return r;
  }

  LAMMPS_NS::LAMMPS *lmp;
};

}    // namespace clusterdyn_test

#endif
