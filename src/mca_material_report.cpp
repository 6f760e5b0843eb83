/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: pair_style mca's materials in the log
   (see mca_material_report.h).
------------------------------------------------------------------------- */

#include "mca_material_report.h"

#include "mca_element.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "force.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;
using namespace ClusterDyn;

namespace {
// the unit a person reads a density in, for the unit styles whose mass/volume is not it
// (LAMMPS's force->mv2d converts to it, as thermo's density does)
const char *density_unit(const char *style)
{
  if (strcmp(style, "si") == 0) return "kg/m^3";
  if (strcmp(style, "lj") == 0) return "";
  if (strcmp(style, "electron") == 0) return "amu/bohr^3";
  if (strcmp(style, "micro") == 0) return "picogram/micrometer^3";
  if (strcmp(style, "nano") == 0) return "attogram/nanometer^3";
  return "g/cm^3";
}
}    // namespace

// mass / volume of each type's elements (0 where a type has none here)
std::vector<double> McaMaterialReport::densities(const McaTypeTable &types,
                                                 double fraction) const
{
  const int ntypes = atom->ntypes;
  std::vector<double> mine(2 * (ntypes + 1), 0.0), all(2 * (ntypes + 1), 0.0);
  if (atom->rmass)
    for (int i = 0; i < atom->nlocal; i++) {
      const int t = atom->type[i];
      mine[2 * t] += atom->rmass[i];
      mine[2 * t + 1] += McaElement::volume(atom->radius[i], fraction, domain->dimension);
    }
  MPI_Allreduce(mine.data(), all.data(), (int) all.size(), MPI_DOUBLE, MPI_SUM, world);
  std::vector<double> rho(ntypes + 1, 0.0);
  for (int t = 1; t <= ntypes; t++) {
    const McaMaterial &m = types.as_given()[t];
    if (m.shock()) rho[t] = m.rho0;
    else if (all[2 * t + 1] > 0.0) rho[t] = all[2 * t] / all[2 * t + 1];
  }
  return rho;
}

void McaMaterialReport::print(const McaTypeTable &types, double fraction)
{
  const std::vector<double> rho = densities(types, fraction);
  const char *style = update->unit_style;
  const char *person = density_unit(style);
  // velocity^2 = (pressure / nktv2p) / density / mvv2e
  const double to_speed2 = 1.0 / (force->nktv2p * force->mvv2e);
  std::string text = fmt::format("Pair mca materials (units {}: moduli and stresses in pressure "
                                 "units, speeds in velocity units):\n", style);
  for (int t = 1; t <= atom->ntypes; t++) {
    if (!types.has_material(t)) continue;
    const McaMaterial &m = types.as_given()[t];
    const double nu = m.poisson();
    text += fmt::format("  type {}: {} K {:.6g} G {:.6g} E {:.6g} nu {:.4g}", t,
                        m.shock() ? "shock law," : "linear law,", m.bulk, m.shear, m.young(), nu);
    if (m.yield > 0.0)
      text += fmt::format(", yield {:.6g}: Hugoniot elastic limit Y (1 - nu)/(1 - 2 nu) = {:.6g}",
                          m.yield, m.yield * (1.0 - nu) / (1.0 - 2.0 * nu));
    text += "\n";
    if (m.kinetic())
      text += fmt::format("    spall kinetics: {:.6g} at the strain rate {:.6g} per time unit{}, "
                          "m {:.4g}: {:.6g} at ten times the rate\n", m.spall, m.spall_rate,
                          strcmp(style, "lj") == 0
                              ? std::string()
                              : fmt::format(" ({:.6g} /s)",
                                            m.spall_rate * force->femtosecond * 1.0e15),
                          m.spall_m, m.spall * pow(10.0, m.spall_m));
    if (rho[t] > 0.0) {
      const double cl = sqrt((m.bulk + 4.0 * m.shear / 3.0) / rho[t] * to_speed2);
      const double cs = sqrt(m.shear / rho[t] * to_speed2);
      const double cb = sqrt(m.bulk / rho[t] * to_speed2);
      text += fmt::format("    density {:.6g}{}{}: longitudinal c_L {:.6g}, shear c_S {:.6g}, "
                          "bulk c0 = sqrt(K/rho) {:.6g}\n",
                          rho[t], m.shock() ? " (rho0)" : " (the elements' mass / volume)",
                          *person ? fmt::format(" = {:.6g} {}", rho[t] * force->mv2d, person)
                                  : std::string(),
                          cl, cs, cb);
    } else
      text += "    no elements of this type here yet: no density, no wave speeds\n";
  }
  if (text != last && comm->me == 0) utils::logmesg(lmp, text);
  last = text;
}
