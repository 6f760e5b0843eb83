/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: numeric arguments read with errors
   that name them (LAMMPS's own parsers say only "Expected floating point
   parameter instead of 'abc'").  who: "Pair morse/spline", "Fix ..." etc.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_ARG_VALUES_H
#define LMP_CLUSTERDYN_ARG_VALUES_H

#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  // a finite number within double precision
  inline double number_arg(const std::string &who, const char *name, const char *str,
                           LAMMPS *lmp)
  {
    errno = 0;
    const double value = utils::is_double(str) ? strtod(str, nullptr) : NAN;
    if (!std::isfinite(value) || errno == ERANGE)
      lmp->error->all(FLERR, "{}: {} must be a finite number (got '{}')", who, name, str);
    return value;
  }

  inline double positive_arg(const std::string &who, const char *name, const char *str,
                             LAMMPS *lmp)
  {
    const double value = number_arg(who, name, str, lmp);
    if (!(value > 0.0)) lmp->error->all(FLERR, "{}: {} must be > 0 (got {})", who, name, str);
    return value;
  }

  // an integer (written as one), within double precision's exact integers
  inline double integer_arg(const std::string &who, const char *name, const char *str,
                            LAMMPS *lmp)
  {
    if (!utils::is_integer(str))
      lmp->error->all(FLERR, "{}: {} must be an integer (got '{}')", who, name, str);
    const double value = number_arg(who, name, str, lmp);
    if (!(fabs(value) < 9.0e15))
      lmp->error->all(FLERR, "{}: {} is out of range (got {})", who, name, str);
    return value;
  }

  // an atom type or a range of them (N, *, N*, *M, N*M) within 1..ntypes
  inline void type_range(const std::string &who, const char *name, const std::string &str,
                         int ntypes, int &lo, int &hi, LAMMPS *lmp)
  {
    const size_t star = str.find('*');
    const std::string a = star == std::string::npos ? str : str.substr(0, star);
    const std::string b = star == std::string::npos ? str : str.substr(star + 1);
    auto bound = [&](const std::string &part, int fallback) {
      if (star != std::string::npos && part.empty()) return fallback;
      return utils::is_integer(part.c_str()) ? atoi(part.c_str()) : -1;
    };
    lo = bound(a, 1);
    hi = bound(b, ntypes);
    if (lo < 1 || hi > ntypes || lo > hi || str.find('*', star + 1) != std::string::npos)
      lmp->error->all(FLERR, "{}: {} must be an atom type or a range of them within 1-{} "
                      "(got '{}')", who, name, ntypes, str);
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
