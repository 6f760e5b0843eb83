/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the plastic pass's turn and slide
   of a batch of pair_style mca's links at once.  Each link's stored
   vectors (its tangential stress TAU, last separation DPREV and relative
   rotation ROT) turn by its contact's spin (McaContact::Turn), the
   tangential stress slides with the contact points (McaContact::slide:
   ET, and DTAU = tau~ . du_t) and the rotation advances by
   dt (omega_j - omega_i) (McaLinkedPair::rotate): the same operations in
   the same order, on up to N links side by side, so that the compiler
   takes them as vectors (the links' state is copied into arrays by
   field).  A batch in which some link turns by 1e-2 rad or more in a step
   (|w dt|^2 >= Turn::SERIES: beyond the turn's Taylor series) takes the
   scalar functions link by link.  Holds the batch only; stateless
   otherwise (as spline_laws.h).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_LINK_TURNS_H
#define LMP_CLUSTERDYN_MCA_LINK_TURNS_H

#include "mca_contact.h"
#include "mca_linked_pair.h"
#include "mca_pair_walk.h"

namespace LAMMPS_NS {
namespace ClusterDyn {

  class McaLinkTurns {
    using C = McaContact;

   public:
    static constexpr int N = 16;    // links side by side: two AVX-512 vectors of 8 doubles

    // link v of elements i and j at frame p (oriented), a the stiffness of its halves in
    // series; moving: a step of dynamics (else the link neither turns nor rotates, and its
    // DTAU is 0); true: the batch is full
    bool add(int i, int j, double *v, const McaPairFrame &p, double a, const double *omega_i,
             const double *omega_j, double dt, bool moving)
    {
      const int b = m++;
      atoms[b][0] = i;
      atoms[b][1] = j;
      row[b] = v;
      frame[b] = p;
      double rotation[3] = {0.0, 0.0, 0.0}, step[3] = {0.0, 0.0, 0.0};
      if (moving) {
        p.rotation(omega_i, omega_j, dt, rotation);
        McaLinkedPair::rotation_step(omega_i, omega_j, dt, step);
      }
      for (int k = 0; k < 3; k++) {
        spin[k][b] = rotation[k];
        tau[k][b] = v[C::TAU + k];
        prev[k][b] = v[C::DPREV + k];
        rot[k][b] = v[C::ROT + k];
        d[k][b] = p.d[k];
        n[k][b] = p.n[k];
        steps[k][b] = step[k];
      }
      energy[b] = v[C::ET];
      stiffness[b] = a;
      series = series && C::dot(rotation, rotation) < C::Turn::SERIES;
      turning = moving;
      return m == N;
    }

    // every link of the batch turned and slid; its doubles written back
    void advance()
    {
      if (!series) {
        for (int b = 0; b < m; b++) advance_one(b);
        return;
      }
      for (int b = m; b < N; b++) pad(b);
      lanes();
      for (int b = 0; b < m; b++) {
        double *v = row[b];
        for (int k = 0; k < 3; k++) {
          v[C::TAU + k] = tau[k][b];
          v[C::DPREV + k] = d[k][b];
          if (turning) v[C::ROT + k] = rot[k][b];
        }
        v[C::ET] = energy[b];
        v[C::DTAU] = turning ? slid[b] : 0.0;
      }
    }

    int size() const { return m; }
    int i(int b) const { return atoms[b][0]; }
    int j(int b) const { return atoms[b][1]; }
    double *values(int b) const { return row[b]; }
    const McaPairFrame &pair(int b) const { return frame[b]; }
    void clear()
    {
      m = 0;
      series = true;
    }

   private:
    int m = 0;
    bool series = true, turning = false;
    int atoms[N][2];
    double *row[N];
    McaPairFrame frame[N];
    double spin[3][N], tau[3][N], prev[3][N], rot[3][N], d[3][N], n[3][N], steps[3][N];
    double energy[N], stiffness[N], slid[N];

    // a lane past the batch: no turn, no slide, finite throughout (not written back; what the
    // stack held there could be subnormal or not a number, which the vector unit takes slowly)
    void pad(int b)
    {
      for (int k = 0; k < 3; k++)
        spin[k][b] = tau[k][b] = prev[k][b] = rot[k][b] = d[k][b] = steps[k][b] = 0.0;
      n[0][b] = 1.0;
      n[1][b] = n[2][b] = 0.0;
      energy[b] = stiffness[b] = 0.0;
    }

    // link b by the scalar functions (a turn beyond the series)
    void advance_one(int b)
    {
      double *v = row[b];
      const double rotation[3] = {spin[0][b], spin[1][b], spin[2][b]};
      const C::Turn turn(rotation);
      double dut[3];
      C::slide(v + C::TAU, v + C::DPREV, frame[b].d, frame[b].n, turning ? &turn : nullptr,
               stiffness[b], dut, v + C::ET);
      v[C::DTAU] = turning ? C::dot(v + C::TAU, dut) : 0.0;
      if (!turning) return;
      const double step[3] = {steps[0][b], steps[1][b], steps[2][b]};
      McaLinkedPair::rotate(v + C::ROT, turn, step);
    }

    // the lanes: McaContact::Turn (its series), McaContact::slide and McaLinkedPair::rotate,
    // inlined on each lane's copies
    void lanes()
    {
      for (int b = 0; b < N; b++) {
        const double phi[3] = {spin[0][b], spin[1][b], spin[2][b]};
        double t[3] = {tau[0][b], tau[1][b], tau[2][b]};
        double q[3] = {prev[0][b], prev[1][b], prev[2][b]};
        double r[3] = {rot[0][b], rot[1][b], rot[2][b]};
        const double dd[3] = {d[0][b], d[1][b], d[2][b]}, nn[3] = {n[0][b], n[1][b], n[2][b]};
        const C::Turn turn = C::Turn::in_series(phi);
        const double step[3] = {steps[0][b], steps[1][b], steps[2][b]};
        double dut[3], work = energy[b];
        C::slide(t, q, dd, nn, &turn, stiffness[b], dut, &work);
        McaLinkedPair::rotate(r, turn, step);
        energy[b] = work;
        slid[b] = C::dot(t, dut);
        for (int k = 0; k < 3; k++) {
          tau[k][b] = t[k];
          rot[k][b] = r[k];
        }
      }
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
