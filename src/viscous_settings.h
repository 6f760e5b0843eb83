/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the arguments of fix viscous/relative
   and the damping rate they define, parsed whole:
     fix ID group viscous/relative gamma G | J J [mode full|normal]
         [weight none|dpd] [cutoff d]
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_VISCOUS_SETTINGS_H
#define LMP_CLUSTERDYN_VISCOUS_SETTINGS_H

#include "pointers.h"

#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct ViscousSettings {
    int by_j = 0;              // 0: rate G given; 1: G_ij = sqrt(C_ij / m_ij) / J
    double value = 0.0;        // G or J
    int normal = 0, dpd = 0;   // mode normal, weight dpd
    double cutoff = 0.0;       // 0: the pair style's cutoff of each type pair

    static ViscousSettings parse(LAMMPS *lmp, int narg, char **arg);

    // G_ij (1/time) of a pair of stiffness C_ij and reduced mass m_ij
    double rate(double stiffness, double mij, double ftm2v) const
    {
      return by_j ? sqrt(ftm2v * stiffness / mij) / value : value;
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
