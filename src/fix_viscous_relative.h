/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: fix viscous/relative, damping on
   the relative velocities of bonded pairs (doc/fix_viscous_relative.rst).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_FIX_VISCOUS_RELATIVE_H
#define LMP_CLUSTERDYN_FIX_VISCOUS_RELATIVE_H

#include "damping_forces.h"
#include "damping_pairs.h"
#include "fix.h"
#include "viscous_settings.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  class FixViscousRelative : public Fix {
   public:
    FixViscousRelative(class LAMMPS *, int, char **);
    ~FixViscousRelative() override;
    int setmask() override;
    void init() override;
    void init_list(int, class NeighList *) override;
    void setup(int) override;
    void pre_force(int) override;
    void post_force(int) override;
    void post_integrate() override;
    void end_of_step() override;
    double compute_scalar() override;
    void write_restart(FILE *) override;
    void restart(char *) override;
    int pack_reverse_comm(int, int, double *) override;
    void unpack_reverse_comm(int, int *, double *) override;
    double memory_usage() override;

   private:
    ViscousSettings opt;     // the fix's arguments
    DampingTypes types;      // per type pair: range, C, the pass's coefficients
    DampingPass pass;        // the damping in the pair style's force pass (damping_pass.h)
    DampingForces forces;    // fd: damping force per atom (own and ghost), summed to owners
    int fused;               // this run: the pair style took the pass
    int adapting;            // this run has a fix adapt: the tables read before each loop
    double removed;          // energy removed by this proc's kicks
    double power_full;       // sum of fd . v at the last full step (trapezoid rule)
    bigint fd_step;          // the step whose damping forces fd holds (-1: none)
    bigint kick_step;        // the last step with post_force (rerun calls end_of_step alone)
    class NeighList *list;   // our own, without link L
    class PairState *state;  // the pair style's link state (link L): damp the linked pairs

    DampingBonds current_bonds() const;
    int claim_pass();                    // at init: whether the pair style takes the pass
    double compute_forces(int vflag);    // returns the power sum of my atoms
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
