/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair_style arguments of the spline
   styles (spline_settings.h).
------------------------------------------------------------------------- */

#include "spline_settings.h"

#include "keyword_set.h"

#include "comm.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

SplineSettings SplineSettings::parse(LAMMPS *lmp, const char *style, bool has_inflection,
                                     int narg, char **arg)
{
  Error *error = lmp->error;
  const std::string pair = fmt::format("Pair {}", style);
  SplineSettings s;
  if (narg < 1)
    error->all(FLERR, "Pair style {}: missing tail (cut Rc | wagner | lagunov Rc [start Rs])",
               style);
  const std::string name = arg[0];
  int iarg = 1;
  auto tail_number = [&](const char *what) {
    if (iarg >= narg || !utils::is_double(arg[iarg]))
      error->all(FLERR, "Pair style {} {}: expected a number {} (got {})", style, name, what,
                 iarg < narg ? fmt::format("'{}'", arg[iarg]) : std::string("nothing"));
    return arg[iarg++];
  };
  if (name == "cut") {
    s.tail = CUT;
    const char *rc = tail_number("Rc");
    s.rc = number_arg(pair, "cut Rc", rc, lmp);
    if (!(s.rc > 1.0))
      error->all(FLERR, "Pair style {} cut: Rc must be > 1 in units of a (got {}): the bond would "
                 "never hold", style, rc);
    if (!(s.rc <= MAX_RC))
      error->all(FLERR, "Pair style {} cut: Rc must be <= {} in units of a (got {})", style,
                 MAX_RC, rc);
  } else if (name == "wagner") {
    if (!has_inflection)
      error->all(FLERR, "Pair style {}: tail wagner needs an inflection point; the harmonic well "
                 "has none (use cut or lagunov Rc start Rs)", style);
    if (iarg < narg && utils::is_double(arg[iarg]))
      error->all(FLERR, "Pair style {} wagner: takes no arguments (got {})", style, arg[iarg]);
    s.tail = WAGNER;
  } else if (name == "lagunov") {
    s.tail = LAGUNOV;
    const char *rc = tail_number("Rc");
    s.rc = positive_arg(pair, "lagunov Rc", rc, lmp);
    if (!(s.rc > 1.0 && s.rc <= MAX_RC))
      error->all(FLERR, "Pair style {} lagunov: Rc must be > 1 and <= {} in units of a (got {})",
                 style, MAX_RC, rc);
    if (iarg < narg && strcmp(arg[iarg], "start") == 0) {
      iarg++;
      const char *rs = tail_number("Rs after start");
      s.rs = positive_arg(pair, "lagunov start Rs", rs, lmp);
      if (!(s.rs >= 1.0))
        error->all(FLERR, "Pair style {} lagunov: start Rs must be >= 1 in units of a (got {}): "
                   "a smoothing from inside a would move the equilibrium", style, rs);
      if (!(s.rc > s.rs))
        error->all(FLERR, "Pair style {} lagunov: Rc = {} must be > start Rs = {}", style, rc, rs);
    } else if (!has_inflection)
      error->all(FLERR, "Pair style {}: tail lagunov needs 'start Rs'; the harmonic well has no "
                 "inflection point to start at", style);
  } else
    error->all(FLERR, "Pair style {}: unknown tail '{}' (expected cut, wagner or lagunov)", style,
               name);

  // keywords after the tail
  int relink_set = -1;
  KeywordSet given(lmp, fmt::format("Pair style {} (after tail {})", style, name),
                   Keywords::SPLINE_STYLE);
  while (iarg < narg) {
    const std::string key = arg[iarg];
    given.add(key);
    if (key == "start")
      error->all(FLERR, "Pair style {}: start Rs must come right after lagunov Rc, once", style);
    if (iarg + 1 >= narg) error->all(FLERR, "Pair style {}: keyword {} needs a value", style, key);
    if (key == "chain") {
      const double n = integer_arg(fmt::format("Pair style {}", style), "chain N", arg[iarg + 1],
                                   lmp);
      if (n < 1 || n > MAX_CHAIN)
        error->all(FLERR, "Pair style {}: chain N must be between 1 and {} (got {})", style,
                   MAX_CHAIN, arg[iarg + 1]);
      s.chain_n = (int) n;
    } else if (key == "link") {
      s.link_l = number_arg(fmt::format("Pair style {}", style), "link L", arg[iarg + 1], lmp);
      if (!(s.link_l >= 1.0))
        error->all(FLERR, "Pair style {}: link L must be >= 1 in units of a (got {}): pairs "
                   "closer than L a are linked", style, arg[iarg + 1]);
    } else {
      const std::string yes_no = arg[iarg + 1];
      if (yes_no != "yes" && yes_no != "no")
        error->all(FLERR, "Pair style {}: relink must be yes or no (got '{}')", style, yes_no);
      relink_set = yes_no == "yes";
    }
    iarg += 2;
  }
  if (relink_set >= 0 && s.link_l == 0.0)
    error->all(FLERR, "Pair style {}: relink needs link L", style);
  if (s.chain_n && s.link_l > 0.0)
    error->all(FLERR, "Pair style {}: link and chain N do not combine (chain N fixes the "
               "neighbours by atom ID already)", style);
  s.relink = relink_set > 0;
  return s;
}

SplineSettings::PairKeywords SplineSettings::parse_pair_keywords(LAMMPS *lmp, const char *style,
                                                                int narg, char **arg) const
{
  Error *error = lmp->error;
  PairKeywords k;
  KeywordSet given(lmp, fmt::format("Pair {} pair_coeff", style), Keywords::SPLINE_COEFF);
  for (int iarg = 0; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    given.add(key);
    if (iarg + 1 >= narg)
      error->all(FLERR, "Pair {}: pair_coeff keyword {} needs a value", style, key);
    const double value = positive_arg(fmt::format("Pair {}", style), key.c_str(), arg[iarg + 1],
                                      lmp);
    if (key == "kappa") k.kappa = value;
    else if (key == "rc") {
      if (tail == WAGNER)
        error->all(FLERR, "Pair {}: keyword rc does not apply to tail wagner (its cutoff follows "
                   "from the law)", style);
      if (!(value > 1.0 && value <= MAX_RC))
        error->all(FLERR, "Pair {}: rc must be > 1 and <= {} in units of a (got {})", style,
                   MAX_RC, arg[iarg + 1]);
      k.rc = value;
    } else {
      if (tail != LAGUNOV)
        error->all(FLERR, "Pair {}: keyword rs applies only to tail lagunov", style);
      if (!(value >= 1.0))
        error->all(FLERR, "Pair {}: rs must be >= 1 in units of a (got {}): a smoothing from "
                   "inside a would move the equilibrium", style, arg[iarg + 1]);
      k.rs = value;
    }
  }
  return k;
}

void SplineSettings::write_restart(FILE *fp, int offset_flag, int mix_flag) const
{
  fwrite(&tail, sizeof(int), 1, fp);
  fwrite(&rc, sizeof(double), 1, fp);
  fwrite(&rs, sizeof(double), 1, fp);
  fwrite(&offset_flag, sizeof(int), 1, fp);
  fwrite(&mix_flag, sizeof(int), 1, fp);
  fwrite(&chain_n, sizeof(int), 1, fp);
  fwrite(&link_l, sizeof(double), 1, fp);
  fwrite(&relink, sizeof(int), 1, fp);
}

void SplineSettings::read_restart(FILE *fp, int &offset_flag, int &mix_flag, LAMMPS *lmp)
{
  Error *error = lmp->error;
  if (lmp->comm->me == 0) {
    utils::sfread(FLERR, &tail, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &rc, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &rs, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &offset_flag, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &mix_flag, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &chain_n, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &link_l, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &relink, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Comm world = lmp->world;
  MPI_Bcast(&tail, 1, MPI_INT, 0, world);
  MPI_Bcast(&rc, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&rs, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&offset_flag, 1, MPI_INT, 0, world);
  MPI_Bcast(&mix_flag, 1, MPI_INT, 0, world);
  MPI_Bcast(&chain_n, 1, MPI_INT, 0, world);
  MPI_Bcast(&link_l, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&relink, 1, MPI_INT, 0, world);
}
