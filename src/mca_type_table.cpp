/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the per-type input of pair_style mca
   (see mca_type_table.h).
------------------------------------------------------------------------- */

#include "mca_type_table.h"

#include "arg_values.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "utils.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

void McaTypeTable::allocate()
{
  ntypes = atom->ntypes;
  material.assign(ntypes + 1, McaMaterial());
  material_set.assign(ntypes + 1, 0);
  unlinkable.assign((ntypes + 1) * (ntypes + 1), 0);
  models.assign((ntypes + 1) * (ntypes + 1), McaPairModel());
}

/* ----------------------------------------------------------------------
   pair_coeff I I bulk K shear G | young E poisson nu: the material of
   element type(s) I; a pair of two types takes each element's own
------------------------------------------------------------------------- */

void McaTypeTable::coeff(int narg, char **arg)
{
  const std::string who = "Pair mca pair_coeff";
  if (narg < 2) error->all(FLERR, "{}: expected pair_coeff I I bulk K shear G", who);
  int ilo, ihi, jlo, jhi;
  type_range(who, "I", arg[0], ntypes, ilo, ihi, lmp);
  type_range(who, "J", arg[1], ntypes, jlo, jhi, lmp);
  // link yes|no (last): whether elements of types I and J link when they touch
  if (narg >= 4 && strcmp(arg[narg - 2], "link") == 0) {
    const std::string v = arg[narg - 1];
    if (v != "yes" && v != "no")
      error->all(FLERR, "{}: link must be yes or no (got '{}')", who, v);
    for (int i = ilo; i <= ihi; i++)
      for (int j = jlo; j <= jhi; j++)
        unlinkable[i * (ntypes + 1) + j] = unlinkable[j * (ntypes + 1) + i] = v == "no";
    narg -= 2;
    if (narg == 2) return;
  }
  if (ilo != jlo || ihi != jhi)
    error->all(FLERR, "{}: a material belongs to an element type: give pair_coeff I I (got {} "
               "{}); a pair of two types takes each element's own (pair_coeff I J link yes|no "
               "sets whether they link)", who, arg[0], arg[1]);
  const McaMaterial m = McaMaterial::read(who, narg - 2, arg + 2, lmp);
  for (int i = ilo; i <= ihi; i++) {
    material[i] = m;
    material_set[i] = 1;
  }
}

void McaTypeTable::init(bool plane_stress)
{
  in_energy.clear();
  for (const McaMaterial &m : material)
    in_energy.push_back((plane_stress ? m.in_plane_stress() : m).scaled(1.0 / force->nktv2p));
}

bool McaTypeTable::responds() const
{
  for (const McaMaterial &m : material)
    if (m.strength > 0.0 || m.kinetic() || m.yield > 0.0 || m.weld > 0.0) return true;
  return false;
}

void McaTypeTable::make_model(int itype, int jtype, bool apart)
{
  for (const int t : {itype, jtype})
    if (!material_set[t])
      error->all(FLERR, "Pair mca: no material for atom type {}: give pair_coeff {} {} bulk K "
                 "shear G (or young E poisson nu)", t, t, t);
  const McaPairModel m =
      McaPairModel::of_types(in_energy[itype], in_energy[jtype], links(itype, jtype) && !apart);
  models[itype * (ntypes + 1) + jtype] = models[jtype * (ntypes + 1) + itype] = m;
}

/* ---------------------------------------------------------------------- */

void McaTypeTable::write_restart(FILE *fp) const
{
  for (int i = 1; i <= ntypes; i++) {
    fwrite(&material_set[i], sizeof(int), 1, fp);
    material[i].write_restart(fp);
  }
  fwrite(unlinkable.data(), sizeof(int), unlinkable.size(), fp);
}

void McaTypeTable::read_restart(FILE *fp)
{
  for (int i = 1; i <= ntypes; i++) {
    if (comm->me == 0) utils::sfread(FLERR, &material_set[i], sizeof(int), 1, fp, nullptr, error);
    MPI_Bcast(&material_set[i], 1, MPI_INT, 0, world);
    material[i].read_restart(fp, lmp);
  }
  if (comm->me == 0)
    utils::sfread(FLERR, unlinkable.data(), sizeof(int), unlinkable.size(), fp, nullptr, error);
  MPI_Bcast(unlinkable.data(), unlinkable.size(), MPI_INT, 0, world);
}

// link no of a type with itself rides on its line; of two types only in write_data ... pair ij
void McaTypeTable::write_data(FILE *fp) const
{
  for (int i = 1; i <= ntypes; i++)
    fmt::print(fp, "{} {}{}\n", i, material[i].words(), links(i, i) ? "" : " link no");
  for (int i = 1; i <= ntypes; i++)
    for (int j = i + 1; j <= ntypes; j++)
      if (!links(i, j) && comm->me == 0)
        error->warning(FLERR, "Pair mca: write_data keeps 'pair_coeff {} {} link no' only with "
                       "the keyword pair ij", i, j);
}

void McaTypeTable::write_data_line(FILE *fp, int i, int j) const
{
  if (i == j)
    fmt::print(fp, "{} {} {}{}\n", i, i, material[i].words(), links(i, i) ? "" : " link no");
  else
    fmt::print(fp, "{} {} link {}\n", i, j, links(i, j) ? "yes" : "no");
}
