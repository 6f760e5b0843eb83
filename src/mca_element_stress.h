/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the stress of each element of
   pair_style mca by Love's formula (mca_element.h) and its count of linked
   pairs, summed over the pairs of a pass, onto the owners and divided by
   the element's volume: the trial stresses of plasticity (energy/volume)
   and, once compute mca/atom has asked, the stresses of the last force
   evaluation (pressure units, tension positive).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_ELEMENT_STRESS_H
#define LMP_CLUSTERDYN_MCA_ELEMENT_STRESS_H

#include "mca_contact.h"
#include "mca_element.h"
#include "mca_exchange.h"
#include "mca_pair_halves.h"
#include "mca_pair_walk.h"
#include "pointers.h"

#include <cstdint>

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaElementStress : protected Pointers {
   public:
    // xx yy zz xy xz yz, the linked pairs, then (plasticity's trial pass) the sums of the
    // linked pairs' weighted normal stresses and of their weights (add_mean)
    enum { LINKS = 6, MEAN_SUM = 7, MEAN_WEIGHT = 8, COLUMNS = 9 };

    McaElementStress(LAMMPS *lmp, McaExchange &exchange) :
        Pointers(lmp), exchange(exchange), rows(nullptr), nmax(0), wanted_flag(false),
        fraction(1.0), step(-1), atoms(0)
    {
    }
    ~McaElementStress() override;
    void init(double packing_fraction) { fraction = packing_fraction; }
    void grow(int nmax_atoms);
    double memory_usage() const;

    void request() { wanted_flag = true; }
    bool wanted() const { return wanted_flag; }

    void zero(int nall);
    // a pair's share: q sym(n (x) f) (McaElement::dyad) and whether it is linked
    void add(int i, double q, const double *sym, int linked)
    {
      McaElement::add_love(rows[i], q, sym);
      rows[i][LINKS] += linked;
    }
    // a linked pair's normal stress with its weight in the mean its element's pairs return
    // about (McaPlasticity)
    void add_mean(int i, double weight, double sigma)
    {
      rows[i][MEAN_SUM] += weight * sigma;
      rows[i][MEAN_WEIGHT] += weight;
    }
    // a linked pair's trial stresses (v: its state, SIG and TAU; intact: 1 - D; halves: its
    // elements' half stiffnesses) on element i and, where jown, j: its share of Love's sum, and its
    // normal stress in the mean its elements' pairs return about, weighted by S w / ((1 - D)
    // a), w the element's share of the pair's elongation, so that a return by one phi about it
    // keeps the element's volume theta and does work sum S sigma dp >= 0
    void add_trial(int i, int j, const McaPairFrame &p, const double *v, double intact,
                   const McaPairHalves &halves, bool jown)
    {
      using C = McaContact;
      const double s = intact * v[C::AREA];
      const double *tau = v + C::TAU;
      double fi[3], sym[6];
      for (int k = 0; k < 3; k++) fi[k] = s * (v[C::SIG] * p.n[k] + tau[k]);
      McaElement::dyad(p.n, fi, sym);
      add(i, p.qi, sym, 0);
      // S w_i / ((1 - D) a) = S / ((1 - D) a_i a_j) a_j
      const double weight = v[C::AREA] / (intact * halves.ai * halves.aj);
      add_mean(i, weight * halves.aj, intact * v[C::SIG]);
      if (jown) {
        add(j, p.qj, sym, 0);
        add_mean(j, weight * halves.ai, intact * v[C::SIG]);
      }
    }
    // the sums onto their owners, divided by the volume (energy/volume; in pressure units if
    // asked, and then marked as the stresses of this step's atoms)
    void to_owners(bool to_pressure);
    double *const *trial() const { return rows; }
    // the stresses of my atoms, or null unless they belong to the current atoms (this step,
    // and the same atoms in the same slots)
    double **current() const;

   private:
    McaExchange &exchange;
    double **rows;
    int nmax;
    bool wanted_flag;
    double fraction;
    bigint step;
    std::uint64_t atoms;    // atoms_fingerprint() when the stresses were made
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
