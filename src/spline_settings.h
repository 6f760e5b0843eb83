/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the settings of the spline pair
   styles, parsed whole before any takes effect:
     pair_style STYLE cut Rc | wagner | lagunov Rc [start Rs]
                [chain N] [link L [relink yes|no]]
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_SPLINE_SETTINGS_H
#define LMP_CLUSTERDYN_SPLINE_SETTINGS_H

#include "spline_tails.h"

#include <cstdio>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct SplineSettings {
    int tail = CUT;          // Tail
    double rc = 0.0;         // tail end in units of a (cut, lagunov)
    double rs = 0.0;         // lagunov start in units of a; 0 = the inflection point b
    int chain_n = 0;         // chain N: pairs up to N apart in atom ID, Pi(r/n); 0 = off
    double link_l = 0.0;     // link L; 0 = off
    int relink = 0;
    static constexpr int MAX_CHAIN = 1000;
    static constexpr double MAX_RC = 100.0;    // tail end, units of a

    static SplineSettings parse(LAMMPS *lmp, const char *style, bool has_inflection, int narg,
                                char **arg);
    // pair_coeff I J <law args> [kappa K] [rc Rc] [rs Rs]: the keywords after the law's
    // arguments (narg, arg), checked against these settings; rc, rs: 0 = not given
    struct PairKeywords {
      double kappa = 1.0, rc = 0.0, rs = 0.0;
    };
    PairKeywords parse_pair_keywords(LAMMPS *lmp, const char *style, int narg, char **arg) const;
    // restart files: with the pair style's shift and mix flags between (the file format)
    void write_restart(FILE *fp, int offset_flag, int mix_flag) const;
    void read_restart(FILE *fp, int &offset_flag, int &mix_flag, LAMMPS *lmp);
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
