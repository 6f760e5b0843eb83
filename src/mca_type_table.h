/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: what pair_coeff gives pair_style mca,
   per element type: its material (mca_material.h) and, per pair of types,
   whether they link; read from pair_coeff, written to and read from restart
   and data files, and turned into the per-type-pair models
   (mca_pair_model.h) and the moduli in energy/volume that the force
   evaluation uses.
     pair_coeff I I bulk K shear G ... [link yes|no]
     pair_coeff I J link yes|no
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_TYPE_TABLE_H
#define LMP_CLUSTERDYN_MCA_TYPE_TABLE_H

#include "mca_material.h"
#include "mca_pair_model.h"
#include "pointers.h"

#include <cstdio>
#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaTypeTable : protected Pointers {
   public:
    explicit McaTypeTable(LAMMPS *lmp) : Pointers(lmp) {}
    void allocate();    // for atom->ntypes: nothing given yet, every pair of types links
    void coeff(int narg, char **arg);
    // init_style(): the materials in energy/volume (pressure / nktv2p), in plane stress with
    // its in-plane lambda
    void init(bool plane_stress);
    // init_one(): the type pair's model, both orders (an error names a type without material);
    // apart: the types never link (they meet by contact segments)
    void make_model(int itype, int jtype, bool apart);
    const McaPairModel &model(int itype, int jtype) const
    {
      return models[itype * (ntypes + 1) + jtype];
    }

    const std::vector<McaMaterial> &as_given() const { return material; }
    bool has_material(int itype) const { return material_set[itype]; }
    const std::vector<McaMaterial> &scaled() const { return in_energy; }
    // a material breaks (strength or spall kinetics), damages, yields or welds
    bool responds() const;
    bool links(int itype, int jtype) const { return !unlinkable[itype * (ntypes + 1) + jtype]; }

    void write_restart(FILE *) const;
    void read_restart(FILE *);    // after allocate()
    void write_data(FILE *) const;
    void write_data_line(FILE *, int itype, int jtype) const;

   private:
    int ntypes = 0;
    std::vector<McaMaterial> material;    // per atom type, as given (pressure units)
    std::vector<McaMaterial> in_energy;   // the same in energy/volume
    std::vector<int> material_set;
    std::vector<int> unlinkable;          // per type pair (i * (ntypes + 1) + j): never link
    std::vector<McaPairModel> models;     // per type pair, made by init_one
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
