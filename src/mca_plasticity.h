/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: von Mises plasticity of movable
   cellular automata at the element (Psakhie 2013): where an element's
   stress intensity sigma_int = sqrt(3/2 s:s) (s the deviator of its
   stress by Love's formula) exceeds its yield stress sigma_y + H eps_p,
   the deviatoric parts of its pair stresses are scaled by
       phi = (sigma_y + H d eps_p) / sigma_int,   d eps_p = (sigma_int - sigma_y) / (3 G + H)
   (radial return).  The equivalent plastic strain eps_p of each element
   is a per-atom property (fix property/atom MCA_PLASTIC_STRAIN, created
   here as fix granular/mdr creates its own): it moves with its element and
   goes into restart files, not into data files (as the pair states).  In
   plane strain (dimension 2) the element's sigma_zz is Hooke's with no
   strain along z, nu (sigma_xx + sigma_yy) - E eps_p,zz, its plastic strain
   along z growing by the flow rule, d eps_p,zz = 3/2 d eps_p s_zz / sigma_int
   (a second column of the same fix).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_PLASTICITY_H
#define LMP_CLUSTERDYN_MCA_PLASTICITY_H

#include "mca_exchange.h"
#include "mca_material.h"

#include "pointers.h"

#include <algorithm>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaPlasticity : protected Pointers {
   public:
    static constexpr const char *FIX_ID = "MCA_PLASTIC_STRAIN";
    static constexpr const char *NAME = "mca_plastic_strain";
    static constexpr const char *NAME_ZZ = "mca_plastic_zz";
    enum { PHI = 0, MEAN = 1, COLUMNS = 2 };    // what each element sends to its ghosts

    McaPlasticity(LAMMPS *lmp, McaExchange &exchange) :
        Pointers(lmp), exchange(exchange), on(false), returned(nullptr), nmax(0)
    {
    }
    ~McaPlasticity() override;
    // a material that yields: the per-element plastic strain (made once, kept after)
    // plane_strain: dimension 2 in plane strain, where sigma_zz = nu (sigma_xx + sigma_yy) -
    // E eps_p,zz enters the von Mises stress; in plane stress and 3d Love's sum gives it
    void init(const std::vector<McaMaterial> &materials, bool plane_strain);
    bool active() const { return on; }
    void grow(int nmax_atoms);
    double memory_usage() const { return (double) nmax * COLUMNS * sizeof(double); }

    // stress: Love's stress of my elements (energy/volume, xx yy zz xy xz yz) from their
    // linked pairs; per element phi and the mean stress, sent to ghosts; eps_p of my
    // elements grows
    void return_map(double *const *stress, const std::vector<McaMaterial> &scaled);
    // of a pair of elements: the return factor phi = min(phi_i, phi_j) and the mean stress
    double phi(int i, int j) const { return std::min(returned[i][PHI], returned[j][PHI]); }
    double mean(int i, int j) const { return 0.5 * (returned[i][MEAN] + returned[j][MEAN]); }
    // plane strain: sigma_zz of owned element i from its in-plane stresses (m: its material, in
    // the units of the stresses)
    double out_of_plane(int i, const McaMaterial &m, double sxx, double syy) const
    {
      const double *zz = on ? column(NAME_ZZ) : nullptr;
      return m.poisson() * (sxx + syy) - (zz ? m.young() * zz[i] : 0.0);
    }


   private:
    McaExchange &exchange;
    bool on;
    bool plane_strain = false;
    double **returned;    // per element: phi and the mean stress
    int nmax;
    double *strain_array() const { return column(NAME); }
    double *column(const char *name) const;
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
