/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the box a per-pair state needs.
   The state of a pair is kept by the partners' IDs, so an atom must not
   meet one partner through two periodic images: each periodic width of
   the box (triclinic: the distance between opposite faces) must exceed
   twice the neighbour list's reach (in 2d along x and y).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_PERIODIC_IMAGES_H
#define LMP_CLUSTERDYN_PERIODIC_IMAGES_H

#include "domain.h"
#include "error.h"
#include "lammps.h"
#include "neighbor.h"

#include <cmath>
#include <string>

namespace LAMMPS_NS {
namespace ClusterDyn {

  inline void check_single_images(LAMMPS *lmp, const std::string &who)
  {
    const Domain *domain = lmp->domain;
    const double reach = lmp->neighbor->cutneighmax;
    const double *h_inv = domain->h_inv;
    const double width[3] = {
        domain->triclinic ? 1.0 / sqrt(h_inv[0] * h_inv[0] + h_inv[5] * h_inv[5] +
                                       h_inv[4] * h_inv[4]) : domain->xprd,
        domain->triclinic ? 1.0 / sqrt(h_inv[1] * h_inv[1] + h_inv[3] * h_inv[3]) : domain->yprd,
        domain->triclinic ? 1.0 / h_inv[2] : domain->zprd};
    for (int k = 0; k < domain->dimension; k++)    // 2d: no images along z
      if (domain->periodicity[k] && width[k] <= 2.0 * reach)
        lmp->error->all(FLERR, "{}: the periodic box is {:.6g} wide along {}, not more than twice "
                        "the neighbour list's reach {:.6g}: an atom would meet a partner through "
                        "two images, which share one pair state; use a larger box (replicate)",
                        who, width[k], "xyz"[k], reach);
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
