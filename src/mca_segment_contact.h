/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the contact of two bodies of
   movable cellular automata by the method of segments (dimension 2), for
   pairs of element types given as
     pair_coeff I J segments mu0 [viscous eta0] [limit sigma0]
                [roughness A1 l1 d1 A2 l2 d2 seed]
   Elements of type I, the lower of the two (LAMMPS's pair_coeff puts the
   lower type first), make the surface: any two of them in contact
   (closer than (1 + T)(R_i + R_j)) are a segment, and the segments form
   the polyline of their centres.  An element k of type J meets the
   polyline at its nearest point (McaSegmentLaw): normal force, friction
   with the micro-roughness K_mu of the point's reference x (McaRoughness),
   shared between the segment's two elements.  Elements of types I and J do
   not link and have no other contact.  Each element k keeps its tangential
   spring xi (d_mca_slip), each element its reference x, its unwrapped x
   when a run first met it (d_mca_x0, set in i_mca_x0_set), so that the
   roughness moves with the surface's body: fix property/atom
   MCA_SEGMENT_STATE (with ghosts; moves with the elements, goes into
   restart files, not into data files).  Needs newton on: the forces on ghost elements of the
   surface are summed onto their owners.  Formulas: doc/pair_mca.rst.
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_SEGMENT_CONTACT_H
#define LMP_CLUSTERDYN_MCA_SEGMENT_CONTACT_H

#include "mca_element_stress.h"
#include "mca_roughness.h"
#include "mca_segment_law.h"

#include "pair_state.h"
#include "pointers.h"

#include <cstdio>
#include <vector>

namespace LAMMPS_NS {
class NeighList;
class Pair;
namespace ClusterDyn {

  class McaSegmentContact : protected Pointers {
   public:
    static constexpr const char *FIX_ID = "MCA_SEGMENT_STATE";

    explicit McaSegmentContact(LAMMPS *lmp) : Pointers(lmp) {}
    void allocate(int ntypes);
    // pair_coeff I J segments ... (arg: all of pair_coeff's words)
    void coeff(int narg, char **arg);
    // pair_coeff I J ... link yes|no (arg: I J ...; the value last) for types that meet by
    // segments: an error (they never link, the line would not apply)
    void refuse_link(char **arg) const;
    bool active() const { return any; }
    // types it and jt meet by segments (either order)
    bool between(int it, int jt) const
    {
      return side[index(it, jt)] != 0 || side[index(jt, it)] != 0;
    }
    // init_style(): the checks, the state, the roughness profiles over the box
    void init();
    // the cutoff a segment type pair needs (largest radii of the types; 0: not one)
    double cutoff(int it, int jt, double ri, double rj, double tolerance) const;
    // the forces of every element k on the surfaces it meets; stiffness: a_i = 2 G_i / R_i;
    // moving: a step of dynamics (the springs slide); the friction's work into changes
    // (love: the elements' stresses, null where not wanted: each of the three takes
    // sym((c - x) (x) F) of its force F, c the contact point on k's surface)
    void compute(const NeighList *full, const double *stiffness, double tolerance, bool moving,
                 double dt, StateTally &changes, Pair &pair, McaElementStress *love);
    void write_restart(FILE *) const;
    void read_restart(FILE *);
    // the pair_coeff line of types i and j (either order) for write_data pair ij; false: none
    bool write_data_line(FILE *, int i, int j) const;

   private:
    struct Given {
      double mu0 = 0.0, eta0 = 0.0, sigma0 = 0.0;
      McaRoughness::Wave waves[2];
      int seed = 0;
    };
    enum { NGIVEN = 10 };
    int ntypes = 0;
    bool any = false;
    std::vector<int> side;          // (I, J): 1 where I's segments meet J's elements
    std::vector<Given> given;       // as pair_coeff gave them (pressure units)
    std::vector<McaSegmentLaw> law; // in energy/volume
    std::vector<McaRoughness> rough;

    int index(int it, int jt) const { return it * (ntypes + 1) + jt; }
    double *dvector(const char *name) const;
    int *set_flags() const;
    // the reference x of the foot at t of segment (i, j): its elements' reference x (their
    // difference by the minimum image in a periodic x), or their x where not set yet
    double reference_x(int i, int j, double t, const double *x0, const int *set) const;
    // k is below half its rest height over segment (bi, bj): an error naming it, its closing
    // speed and the largest the contact stops
    void refuse_passage(int k, int bi, int bj, double h, double h0, double kn,
                        double closing) const;
    static void pack(const Given &g, double *v);
    static void unpack(const double *v, Given &g);
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
