#!/usr/bin/env python3
"""Mutation pass: one plausible one-line bug per component, and the tests that must catch it.

For each mutant the tool edits one line of a scratch copy of the tree (a git worktree of HEAD
with the working tree's changes to the files named below copied in), rebuilds the plugin
there when the line is C++, runs the mutant's covering tests (stopping at the first failure),
and restores the line.  A mutant is caught when a covering test fails; one that survives is a
gap in the tests.  Prints a table (component, mutant, caught by) and exits 1 if any survives.
doc/Developer.rst keeps the last result.

    /usr/bin/python3 tools/mutate.py [--only NAME ...] [--keep]

The scratch tree is /tmp/clusterdyn-mutate (built once by tools/bootstrap.sh with LAMMPS from
the cache: a few minutes; each C++ mutant then recompiles the files that include its line).
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCRATCH = "/tmp/clusterdyn-mutate"
PY = "unittest/python/"

# component, file, the line's text as it is, as the mutant has it, covering tests (pytest files,
# or HEADERS: the GoogleTest program of the stateless headers), what it breaks
HEADERS = "test_headers"
MUTANTS = [
    ("Mie law (spline_laws.h)", "src/spline_laws.h",
     "fpair = c.kappa * c.c2 / c.a * x * (xn - xm) / r;",
     "fpair = c.c2 / c.a * x * (xn - xm) / r;",
     [PY + "test_pair_spline_law.py"], "kappa left out of the Mie force"),
    ("lagunov tail (spline_tails.h)", "src/spline_tails.h",
     "fpair = m * (fbase * m + 4.0 * x * c.inv_l2 * e / r);",
     "fpair = m * (fbase * m + 2.0 * x * c.inv_l2 * e / r);",
     [PY + "test_pair_spline_law.py"], "the tail's force term halved"),
    ("pair state (pair_state.cpp)", "src/pair_state.cpp",
     "for (int k = 0; k < nwork; k++) t.work[k] = v[3 + k];",
     "for (int k = 0; k < nwork - 1; k++) t.work[k] = v[3 + k];",
     [PY + "test_pair_state.py"], "the last work total lost at run boundaries and restarts"),
    ("damping (fix_viscous_relative.cpp)", "src/fix_viscous_relative.cpp",
     "removed -= 0.25 * update->dt * power_full;",
     "removed -= 0.5 * update->dt * power_full;",
     [PY + "test_fix_viscous_relative.py"], "the first half kick's energy counted twice"),
    ("compute dust (fragment_sums.h)", "src/fragment_sums.h",
     "return maxsize > 0 ? size <= (double) maxsize : id != body_id;",
     "return maxsize > 0 ? size < (double) maxsize : id != body_id;",
     [PY + "test_compute_dust.py"], "fragments of exactly maxsize atoms not dust"),
    ("MCA material (mca_material.h)", "src/mca_material.h",
     "double volumetric_lambda() const { return (shock() ? 0.0 : bulk) - 2.0 * shear / 3.0; }",
     "double volumetric_lambda() const { return (shock() ? 0.0 : bulk) - shear / 3.0; }",
     [PY + "test_pair_mca.py"], "Lame's lambda = K - G/3"),
    ("MCA response (mca_response.h)", "src/mca_response.h",
     "return sigma > 0.0 ? sqrt(sigma * sigma + 3.0 * tau2) : 0.0;",
     "return sigma > 0.0 ? sqrt(sigma * sigma + tau2) : 0.0;",
     [PY + "test_mca_response.py"], "the equivalent stress without its 3"),
    ("MCA friction (mca_friction.h)", "src/mca_friction.h",
     "return {sqrt(mu_i * mu_j), sqrt(eta_i * eta_j),",
     "return {0.5 * (mu_i + mu_j), sqrt(eta_i * eta_j),",
     [HEADERS, PY + "test_mca_response.py"], "two surfaces' mu by the arithmetic mean"),
    ("MCA plasticity (mca_plasticity.cpp)", "src/mca_plasticity.cpp",
     "out[i][0] = (yield_now + m.hardening * deps) / sint;",
     "out[i][0] = yield_now / sint;",
     [PY + "test_mca_response.py"], "the return ignores this step's hardening"),
    ("MCA element (mca_element.h)", "src/mca_element.h",
     "return 4.0 * M_PI / 3.0 * radius * radius * radius / fraction;",
     "return 4.0 * M_PI / 3.0 * radius * radius * radius;",
     [PY + "test_pair_mca.py"], "the element volume without the packing fraction"),
    ("MCA linking (mca_linking.cpp)", "src/mca_linking.cpp",
     "v[C::AREA] = 0.5 * (si + sj);",
     "v[C::AREA] = si;",
     [PY + "test_pair_mca.py"], "a link's area from one element only"),
    ("MCA many-body (mca_manybody.h)", "src/mca_manybody.h",
     "theta[i][0] += elong * aj / (ai + aj);",
     "theta[i][0] += elong * ai / (ai + aj);",
     [PY + "test_pair_mca.py"], "an element takes its partner's share of the elongation"),
    ("MCA shock law (mca_shock_eos.h)", "src/mca_shock_eos.h",
     "return hugoniot_pressure(eta) + gamma * (u - hugoniot_energy(eta));",
     "return hugoniot_pressure(eta) + gamma * (u + hugoniot_energy(eta));",
     [HEADERS], "the Grueneisen term with the wrong sign of the reference energy"),
    ("MCA element pressure (mca_element_eos.cpp)", "src/mca_element_eos.cpp",
     "u = law.energy_after(u, w0, j1, q, 0.5 * j1 * now);",
     "u = law.energy_after(u, 2.0 * w0, j1, q, 0.5 * j1 * now);",
     [PY + "test_mca_shock.py"], "the internal energy takes the old step's work twice"),
    ("MCA pair frame (mca_pair_walk.h)", "src/mca_pair_walk.h",
     "qi = r * ri / (ri + rj);",
     "qi = r * rj / (ri + rj);",
     [HEADERS, PY + "test_pair_mca.py"], "the arms to the contact point swapped"),
    ("MCA linked pair (mca_linked_pair.h)", "src/mca_linked_pair.h",
     "lost = intact - response.intact(s);",
     "lost = 1.0 - response.intact(s);",
     [PY + "test_mca_response.py"], "damage counted from the undamaged state each time"),
    ("MCA unlinked pair (mca_unlinked_pair.h)", "src/mca_unlinked_pair.h",
     "for (int k = 0; k < 3; k++) visc[k] = eta * (vr[k] - vn * n[k]);",
     "for (int k = 0; k < 3; k++) visc[k] = eta * vr[k];",
     [HEADERS, PY + "test_mca_response.py"], "viscous friction acting along the normal too"),
    ("MCA type table (mca_type_table.cpp)", "src/mca_type_table.cpp",
     "if (m.strength > 0.0 || m.yield > 0.0 || m.weld > 0.0) return true;",
     "if (m.strength > 0.0 || m.yield > 0.0) return true;",
     [PY + "test_mca_response.py"], "welding not followed by the many-body term"),
    ("MCA element stress (mca_element_stress.cpp)", "src/mca_element_stress.cpp",
     "const double scale = to_pressure ? force->nktv2p : 1.0;",
     "const double scale = 1.0;",
     [PY + "test_compute_mca_atom.py"], "compute mca/atom in energy/volume, not pressure"),
    ("column exchange (pair_column_exchange.h)", "src/pair_column_exchange.h",
     "for (int k = 0; k < columns; k++) rows[list[i]][k] += buf[m++];",
     "for (int k = 0; k < columns; k++) rows[list[i]][k] = buf[m++];",
     [PY + "test_pair_mca.py"], "ghost sums overwrite their owners' (newton on, MPI)"),
    ("MCA 2d element (mca_element.h)", "src/mca_element.h",
     "if (dimension == 2) return M_PI * radius * radius / fraction;",
     "if (dimension == 2) return M_PI * radius * radius;",
     [PY + "test_mca_2d.py"], "a disc's area without the packing fraction"),
    ("MCA plane stress (mca_material.h)", "src/mca_material.h",
     "m.lambda = 2.0 * shear * lambda / (lambda + 2.0 * shear);",
     "m.lambda = shear * lambda / (lambda + 2.0 * shear);",
     [PY + "test_mca_2d.py"], "plane stress's lambda without its 2"),
    ("MCA segment law (mca_segment_law.h)", "src/mca_segment_law.h",
     "work = limit * fabs(xi - kept);",
     "work = limit * fabs(xi);",
     [HEADERS, PY + "test_mca_segments.py"], "the slip's work counts the whole spring"),
    ("MCA roughness (mca_roughness.h)", "src/mca_roughness.h",
     "return (integral(x + 0.5 * s) - integral(x - 0.5 * s)) / s;",
     "return value(x);",
     [HEADERS, PY + "test_mca_segments.py"], "a contact reads K_mu at a point, not its mean"),
    ("MCA segment contact (mca_segment_contact.cpp)", "src/mca_segment_contact.cpp",
     "torque[k][2] -= rk * ft;",
     "torque[k][2] -= (h - rk) * ft;",
     [PY + "test_mca_segments.py"], "k turns with the segment's arm"),
    ("pull-back tool (tools/pull_back.py)", "tools/pull_back.py",
     "0.5 * rho0 * c_bulk * (du + delta)",
     "rho0 * c_bulk * (du + delta)",
     [PY + "test_pull_back_tool.py"], "the spall strength without its 1/2"),
    # ---- second round (fresh-eyes review): one-line slips the first list did not try ----
    ("MCA shock viscosity (mca_shock_eos.h) [r2-01]", "src/mca_shock_eos.h",
     "return rho * length * rate * (b1 * c0 + (rate > 0.0 ? b2 * b2 * length * rate : 0.0));",
     "return rho * length * rate * (b1 * c0 + (rate > 0.0 ? b2 * length * rate : 0.0));",
     [HEADERS, PY + "test_mca_shock.py"], "the quadratic viscosity with b2, not b2^2"),
    ("MCA shock energy step (mca_shock_eos.h) [r2-02]", "src/mca_shock_eos.h",
     "return (u0 - w0 - s1 * (ph - gamma * uh + q1)) / (1.0 + gamma * s1);",
     "return (u0 - w0 - s1 * (ph - gamma * uh + q1)) / (1.0 - gamma * s1);",
     [HEADERS, PY + "test_mca_shock.py", PY + "test_mca_energy_budget.py"],
     "the closed-form energy update divides by 1 - Gamma s1"),
    ("MCA element strain midpoint (mca_element_eos.cpp) [r2-03]", "src/mca_element_eos.cpp",
     "j1 = how == MOVED && had_shape ? j0 * stretch(grad0) : j0 * exp(0.5 * (before + now));",
     "j1 = how == MOVED && had_shape ? j0 * stretch(grad0) : j0 * exp(now);",
     [PY + "test_mca_shock_moves.py", PY + "test_mca_shock.py", PY + "test_mca_energy_budget.py"],
     "the volume advances by the new gradient, not the midpoint of old and new"),
    ("MCA element viscosity density (mca_element_eos.cpp) [r2-04]", "src/mca_element_eos.cpp",
     "q = force->mvv2e * law.viscosity(-0.5 * (before + now) / dt, m.rho0 / j1, m.c0,",
     "q = force->mvv2e * law.viscosity(-0.5 * (before + now) / dt, m.rho0, m.c0,",
     [PY + "test_mca_shock.py", PY + "test_mca_energy_budget.py"],
     "the bulk viscosity at the reference density, not the compressed one"),
    ("MCA element shape inverse (mca_element_shape.h) [r2-05]", "src/mca_element_shape.h",
     "inv[4] = (s[3] * s[5] - s[4] * s[1]) / det;",
     "inv[4] = (s[3] * s[5] - s[4] * s[2]) / det;",
     [HEADERS, PY + "test_mca_shock.py"], "K^-1's xz cofactor with zz for yy"),
    ("MCA element heat (mca_element_eos.cpp) [r2-06]", "src/mca_element_eos.cpp",
     "if (laws[atom->type[i]].bulk > 0.0) atom->dvector[energy][i] += heat[i][0] / volume(i);",
     "if (laws[atom->type[i]].bulk > 0.0) atom->dvector[energy][i] += heat[i][0];",
     [PY + "test_mca_energy_budget.py", PY + "test_mca_shock.py", PY + "test_mca_spall.py"],
     "the dissipated heat added as energy, not energy per volume"),
    ("MCA hourglass pressure stiffening (pair_mca.cpp) [r2-07]", "src/pair_mca.cpp",
     "hourglass[i][1] = 4.0 * m.hourglass / atom->radius[i];",
     "hourglass[i][1] = 2.0 * m.hourglass / atom->radius[i];",
     [PY + "test_mca_shock.py", PY + "test_pair_mca.py", PY + "test_mca_spall.py"],
     "the spring's stiffening with pressure 2 H |p| / R per half, not 2 H 2|p| / R"),
    ("MCA hourglass partner (pair_mca.cpp) [r2-08]", "src/pair_mca.cpp",
     "const double bj = hourglass[j][0] + hourglass[j][1] * squeeze;",
     "const double bj = hourglass[i][0] + hourglass[i][1] * squeeze;",
     [PY + "test_mca_shock.py", PY + "test_pair_mca.py"],
     "j's half of the spring takes i's stiffness (two sizes or materials)"),
    ("MCA hourglass energy (pair_mca.cpp) [r2-09]", "src/pair_mca.cpp",
     "return 0.5 * pull * v[C::HG];",
     "return pull * v[C::HG];",
     [PY + "test_mca_energy_budget.py", PY + "test_mca_shock.py"],
     "the spring's energy without its 1/2"),
    ("MCA cutoff of a type pair (pair_mca.cpp) [r2-10]", "src/pair_mca.cpp",
     "(guard.largest_radius(i) + guard.largest_radius(j)),",
     "(2.0 * guard.largest_radius(i)),",
     [PY + "test_pair_mca.py", PY + "test_mca_fracture.py", PY + "test_mca_2d.py"],
     "the cutoff from type i's largest element twice (two sizes)"),
    ("MCA segment normal stiffness (mca_segment_contact.cpp) [r2-11]", "src/mca_segment_contact.cpp",
     "const double kn = 1.5 * s * a;",
     "const double kn = s * a;",
     [PY + "test_mca_segments.py", PY + "test_mca_friction_example.py"],
     "k_n = S a: one contact, not the hollow's two at 30 degrees"),
    ("MCA segment torque share (mca_segment_contact.cpp) [r2-12]", "src/mca_segment_contact.cpp",
     "torque[bi][2] -= (1.0 - t) * (h - rk) * ft;",
     "torque[bi][2] -= t * (h - rk) * ft;",
     [PY + "test_mca_segments.py"], "the segment's near end takes the far end's torque share"),
    ("MCA segment slide velocity (mca_segment_contact.cpp) [r2-13]", "src/mca_segment_contact.cpp",
     "const double vt = e[0] * vrel[0] + e[1] * vrel[1] - rk * omega[k][2] - (h - rk) * wseg;",
     "const double vt = e[0] * vrel[0] + e[1] * vrel[1] - rk * omega[k][2] - h * wseg;",
     [PY + "test_mca_segments.py"], "the segment's spin carries the contact point at the arm h"),
    ("MCA segment rest height (mca_segment_law.h) [r2-14]", "src/mca_segment_law.h",
     "return 0.5 * sqrt(3.0) * (rk + (1.0 - t) * ri + t * rj);",
     "return 0.5 * sqrt(3.0) * (rk + (1.0 - t) * rj + t * ri);",
     [HEADERS, PY + "test_mca_segments.py"], "R_s interpolated from the wrong ends (two sizes)"),
    ("MCA segment junction limit (mca_segment_law.h) [r2-15]", "src/mca_segment_law.h",
     "const double junction = sigma0 / sqrt(3.0) * s;",
     "const double junction = sigma0 * s;",
     [HEADERS, PY + "test_mca_segments.py"], "the junction's shear strength sigma0, not sigma0/sqrt(3)"),
    ("MCA roughness last piece (mca_roughness.h) [r2-16]", "src/mca_roughness.h",
     "if (at + 2.0 * (n + 1) * half > length) {    // the last piece fills the rest",
     "if (at + 2.0 * n * half > length) {    // the last piece fills the rest",
     [HEADERS, PY + "test_mca_segments.py"],
     "the last piece decided one period late: a sliver piece at the period's end"),
    ("MCA roughness last piece count (mca_roughness.h) [r2-17]", "src/mca_roughness.h",
     "n = static_cast<int>(floor((length - at) / (2.0 * half) + 0.5));",
     "n = static_cast<int>(floor((length - at) / (2.0 * half)));",
     [HEADERS, PY + "test_mca_segments.py"], "the last piece's periods rounded down, stretched more"),
    ("MCA unlinked area radius (mca_element.h) [r2-18]", "src/mca_element.h",
     "const double rh = 2.0 * ri * rj / (ri + rj);",
     "const double rh = 0.5 * (ri + rj);",
     [HEADERS, PY + "test_mca_2d.py", PY + "test_pair_mca.py", PY + "test_mca_segments.py"],
     "the unlinked face from the arithmetic mean radius (two sizes)"),
    ("MCA 2d area share (mca_element.h) [r2-19]", "src/mca_element.h",
     "return dimension * volume / (links * radius);",
     "return 3.0 * volume / (links * radius);",
     [PY + "test_mca_2d.py", PY + "test_subsystem_2d.py"], "a link's area share with D = 3 in 2d"),
    ("MCA plasticity shear terms (mca_plasticity.cpp) [r2-20]", "src/mca_plasticity.cpp",
     "2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));",
     "(s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));",
     [PY + "test_mca_response.py", PY + "test_mca_2d.py"],
     "von Mises counts each shear component once (pure shear yields late)"),
    ("MCA plasticity hardening step (mca_plasticity.cpp) [r2-21]", "src/mca_plasticity.cpp",
     "const double deps = (sint - yield_now) / (3.0 * m.shear + m.hardening);",
     "const double deps = (sint - yield_now) / (3.0 * m.shear);",
     [PY + "test_mca_response.py"], "the plastic increment ignores the hardening modulus"),
    ("MCA linked pair damaged return (mca_linked_pair.h) [r2-22]", "src/mca_linked_pair.h",
     "const double back = (intact * sigma - mean) * (1.0 - phi) / intact;",
     "const double back = (sigma - mean) * (1.0 - phi);",
     [HEADERS, PY + "test_mca_response.py"],
     "a damaged pair returns its effective, not transmitted, stress about the mean"),
    ("MCA linked pair damage work (mca_linked_pair.h) [r2-23]", "src/mca_linked_pair.h",
     "if (outcome == DAMAGES) tally.work(WORK_DAMAGE, lost * epair);",
     "if (outcome == DAMAGES) tally.work(WORK_DAMAGE, intact * epair);",
     [PY + "test_mca_energy_budget.py", PY + "test_mca_response.py"],
     "the damage work counts the energy left, not the share lost"),
    ("MCA unlinked viscous arms (mca_unlinked_pair.h) [r2-24]", "src/mca_unlinked_pair.h",
     "for (int k = 0; k < 3; k++) vr[k] = vj[k] - vi[k] - qj * wj[k] - qi * wi[k];",
     "for (int k = 0; k < 3; k++) vr[k] = vj[k] - vi[k] - qi * wj[k] - qj * wi[k];",
     [HEADERS, PY + "test_mca_response.py"], "the contact points' arms swapped (two sizes)"),
    ("MCA link twist (mca_contact.h) [r2-25]", "src/mca_contact.h",
     "const double twist = 2.0 * bend;",
     "const double twist = bend;",
     [HEADERS, PY + "test_pair_mca.py"], "twisting stiffness a I, not a J = 2 a I"),
    ("compute free/surface jump midpoint (compute_free_surface.cpp) [r2-26]",
     "src/compute_free_surface.cpp",
     "const double expected = last.face + sign * 0.5 * (last.velocity + velocity) * interval;",
     "const double expected = last.face + sign * velocity * interval;",
     [PY + "test_compute_free_surface.py"],
     "the face predicted with the new velocity, not the mean of the two (an accelerating face)"),
    ("compute free/surface minsize (compute_free_surface.cpp) [r2-27]",
     "src/compute_free_surface.cpp",
     "return minsize > 0 ? fragment[i][1] >= minsize : fragment[i][2] == 0.0;",
     "return minsize > 0 ? fragment[i][1] > minsize : fragment[i][2] == 0.0;",
     [PY + "test_compute_free_surface.py"], "a piece of exactly minsize atoms not counted"),
    ("compute dust bond distance (compute_dust.cpp) [r2-28]", "src/compute_dust.cpp",
     "if (dx * dx + dy * dy + dz * dz >= cutsq[type[i] * ntp1 + type[j]]) continue;",
     "if (dx * dx + dy * dy + dz * dz >= cutsq[type[i] * ntp1 + type[i]]) continue;",
     [PY + "test_compute_dust.py", PY + "test_dust_thresholds.py"],
     "a bond read at i's own type pair's distance (two types, two cutoffs)"),
    ("compute dust mass fraction (compute_dust.cpp) [r2-29]", "src/compute_dust.cpp",
     "vector[3] = all[3] > 0.0 ? all[2] / all[3] : 0.0;",
     "vector[3] = all[3] > 0.0 ? all[0] / all[3] : 0.0;",
     [PY + "test_compute_dust.py"], "the dust mass fraction from the dust atom count"),
    ("compute mca/atom shear equivalent (compute_mca_atom.cpp) [r2-30]", "src/compute_mca_atom.cpp",
     "3.0 * (v[SXY] * v[SXY] + v[SXZ] * v[SXZ] + v[SYZ] * v[SYZ]));",
     "1.5 * (v[SXY] * v[SXY] + v[SXZ] * v[SXZ] + v[SYZ] * v[SYZ]));",
     [PY + "test_compute_mca_atom.py"], "von Mises with each shear counted once"),
    ("fix viscous/relative second kick (fix_viscous_relative.cpp) [r2-31]",
     "src/fix_viscous_relative.cpp",
     "removed -= 0.25 * update->dt * (power_full + forces.power());",
     "removed -= 0.5 * update->dt * power_full;",
     [PY + "test_fix_viscous_relative.py"],
     "the second half kick's work at v(k) only, not the trapezoid"),
    ("fix viscous/relative pair mass (damping_types.cpp) [r2-32]", "src/damping_types.cpp",
     "c.coef = atom->rmass ? 0.0 : friction(tp, atom->mass[i], atom->mass[j]);",
     "c.coef = atom->rmass ? 0.0 : friction(tp, atom->mass[i], atom->mass[i]);",
     [PY + "test_fix_viscous_relative.py"], "m_ij from type i's mass twice (two masses)"),
    ("fix descent/normalized filling velocity (fix_descent_normalized.cpp) [r2-33]",
     "src/fix_descent_normalized.cpp",
     "v[i][k] = total[k] / nfilled_next * inv_dt;",
     "v[i][k] = total[k] / nmemory * inv_dt;",
     [PY + "test_fix_descent_normalized.py"],
     "the velocity divides by M while the memory fills"),
    ("fix descent/normalized filling inertia (fix_descent_normalized.cpp) [r2-34]",
     "src/fix_descent_normalized.cpp",
     "if (nfilled) d[k] += kinertia * total[k] / nfilled;",
     "if (nfilled) d[k] += kinertia * total[k] / nmemory;",
     [PY + "test_fix_descent_normalized.py"], "the inertia term divides by M while the memory fills"),
    ("harmonic law kappa (spline_laws.h) [r2-35]", "src/spline_laws.h",
     "c.c1 = c.kappa * c.kappa * c.p * c.p * c.d;    // (alpha kappa)^2 D",
     "c.c1 = c.kappa * c.p * c.p * c.d;    // (alpha kappa)^2 D",
     [HEADERS, PY + "test_pair_spline_law.py"], "harmonic stiffness with kappa, not kappa^2"),
    ("Mie third derivative (spline_laws.h) [r2-36]", "src/spline_laws.h",
     "d[3] = k / (c.a * c.a) * x * x * x * ((m + 1.0) * (m + 2.0) * xm - (n + 1.0) * (n + 2.0) * xn);",
     "d[3] = k / (c.a * c.a) * x * x * x * ((m + 1.0) * (m + 1.0) * xm - (n + 1.0) * (n + 2.0) * xn);",
     [HEADERS, PY + "test_compute_pair_params.py", PY + "test_pair_spline_law.py"],
     "Pi''' of Mie with (m+1)^2 for (m+1)(m+2)"),
    ("lagunov tail third derivative (spline_tails.h) [r2-37]", "src/spline_tails.h",
     "const double k3 = 24.0 * x * l * l;",
     "const double k3 = 16.0 * x * l * l;",
     [HEADERS, PY + "test_compute_pair_params.py", PY + "test_pair_spline_law.py"],
     "the smoothing's third derivative 16 x/l^2, not 24"),
    ("wagner bond strength kappa (spline_table.h) [r2-38]", "src/spline_table.h",
     "fstar = c.kappa * fabs(d[1]);",
     "fstar = fabs(d[1]);",
     [PY + "test_pair_spline_law.py", PY + "test_pair_spline_features.py"],
     "f* of the unmodified base: the wagner spline wrong when kappa != 1"),
    ("spline chain reach (spline_kernel.h) [r2-39]", "src/spline_kernel.h",
     "if (nc == 0 || nc > k.chain_n) continue;",
     "if (nc == 0 || nc >= k.chain_n) continue;",
     [PY + "test_chain_1d.py", PY + "test_pair_spline_features.py"],
     "chain N stops one neighbour short"),
    ("pull-back smoothing (tools/pull_back.py) [r2-40]", "tools/pull_back.py",
     "out[k] = v[k] + float(np.sum((d[1:] + d[:-1]) * np.diff(ts))) / (2.0 * (b - a))",
     "out[k] = v[k] + float(np.sum((d[1:] + d[:-1]) * np.diff(ts))) / (b - a)",
     [PY + "test_pull_back_tool.py"],
     "the trapezoid mean without its 1/2 (lines stay straight, peaks do not)"),
    ("pull-back window end (tools/pull_back.py) [r2-41]", "tools/pull_back.py",
     "h = min(half, t[k] - t[0], t[-1] - t[k])",
     "h = min(half, t[k] - t[0])",
     [PY + "test_pull_back_tool.py"], "the window does not shrink at the record's end"),
    ("pull-back rise crossing (tools/pull_back.py) [r2-42]", "tools/pull_back.py",
     "u2 = (upper - lower) / (_crossing(t, vs, b - 1, upper) - _crossing(t, vs, a - 1, lower))",
     "u2 = (upper - lower) / (_crossing(t, vs, b - 1, upper) - _crossing(t, vs, a, lower))",
     [PY + "test_pull_back_tool.py"], "the 10 % crossing of the rise read on the next segment"),
    ("pull-back jump span (tools/pull_back.py) [r2-43]", "tools/pull_back.py",
     "if jumps[k] != jumps[k - 1] and t[k] > first and t[k - 1] < last]",
     "if jumps[k] != jumps[k - 1] and t[k - 1] > first and t[k] < last]",
     [PY + "test_pull_back_tool.py"],
     "a jump refused only where its whole interval lies in the span, not where it overlaps"),
    ("pull-back pulse (tools/pull_back.py) [r2-44]", "tools/pull_back.py",
     "duration = args.pulse if args.pulse else 2.0 * args.flyer / c_bulk",
     "duration = args.pulse if args.pulse else 2.0 * args.flyer / args.c_long",
     [PY + "test_pull_back_tool.py"], "the flyer's pulse at the elastic speed (too short)"),
    ("cd_calibrate bcc stiffness (tools/cd_calibrate.py) [r2-45]", "tools/cd_calibrate.py",
     "\"r0\": r0 * size, \"D\": depth, \"C\": mass * (v0 / (r0 * size)) ** 2, \"kv\": kv, \"v0\": v0,",
     "\"r0\": r0 * size, \"D\": depth, \"C\": mass * (v0 / size) ** 2, \"kv\": kv, \"v0\": v0,",
     [PY + "test_metal_calibration.py", PY + "test_metal_lattices.py"],
     "C from a, not the law's r0 (differs on bcc)"),
    ("cd_calibrate dusting onset (tools/cd_calibrate.py) [r2-46]", "tools/cd_calibrate.py",
     "\"ucr\": 1.35 * (rc * r0 / crystal.model_radius() - 1) * v0,",
     "\"ucr\": 1.35 * (rc / crystal.model_radius() - 1) * v0,",
     [PY + "test_metal_calibration.py", PY + "test_metal_lattices.py"],
     "u_cr with Rc in units of r0 taken as units of a (bcc)"),
    ("cd_calibrate Grueneisen S (tools/cd_calibrate.py) [r2-47]", "tools/cd_calibrate.py",
     "return positive(\"--bulk-speed\", args.bulk_speed), (args.grueneisen + 1) / 2",
     "return positive(\"--bulk-speed\", args.bulk_speed), args.grueneisen / 2",
     [PY + "test_metal_calibration.py", PY + "test_potentials_calibration.py"],
     "--grueneisen G gives S = G/2, not (G + 1)/2"),
    ("MCA material report HEL (mca_material_report.cpp) [r2-48]", "src/mca_material_report.cpp",
     "m.yield, m.yield * (1.0 - nu) / (1.0 - 2.0 * nu));",
     "m.yield, m.yield * (1.0 + nu) / (1.0 - 2.0 * nu));",
     [PY + "test_mca_material_report.py"], "the Hugoniot elastic limit with 1 + nu"),
    ("MCA material report density (mca_material_report.cpp) [r2-49]", "src/mca_material_report.cpp",
     "mine[2 * t + 1] += McaElement::volume(atom->radius[i], fraction, domain->dimension);",
     "mine[2 * t + 1] += McaElement::volume(atom->radius[i], 1.0, domain->dimension);",
     [PY + "test_mca_material_report.py"],
     "a linear-law type's density from the element's sphere, not its cell"),
    ("keyword table message (keyword_set.h) [r2-50]", "src/keyword_set.h",
     "list += (i == 0 ? \"\" : i + 1 == known.size() ? \" or \" : \", \") + std::string(known[i].name);",
     "list += (i == 0 ? \"\" : i == known.size() ? \" or \" : \", \") + std::string(known[i].name);",
     [PY + "test_doc_coverage.py", PY + "test_pair_spline_errors.py",
      PY + "test_compute_free_surface.py", PY + "test_fix_descent_normalized.py",
      PY + "test_compute_dust.py"],
     "the list of expected keywords never says 'or'"),
]


def run(cmd, cwd, log, env=None, timeout=3600):
    with open(log, "a") as out:
        out.write(f"\n$ {cmd}\n")
        out.flush()
        return subprocess.run(cmd, cwd=cwd, shell=True, stdout=out, stderr=subprocess.STDOUT,
                              env=env, timeout=timeout).returncode


def scratch_tree(log):
    """A worktree of HEAD with the working tree's versions of every file git tracks or adds."""
    if os.path.isdir(SCRATCH):
        run(f"git worktree remove --force {SCRATCH}", TOP, log)
        shutil.rmtree(SCRATCH, ignore_errors=True)
    run(f"git worktree add --detach {SCRATCH} HEAD", TOP, log)
    files = subprocess.run("git ls-files -co --exclude-standard", cwd=TOP, shell=True,
                           capture_output=True, text=True, check=True).stdout.split()
    for f in files:
        if os.path.isfile(os.path.join(TOP, f)):
            os.makedirs(os.path.dirname(os.path.join(SCRATCH, f)) or SCRATCH, exist_ok=True)
            shutil.copy2(os.path.join(TOP, f), os.path.join(SCRATCH, f))
    env = dict(os.environ, CLUSTERDYN_BUILD_DIR=f"{SCRATCH}/build")
    if run("bash tools/bootstrap.sh", SCRATCH, log, env) != 0:
        sys.exit(f"mutate.py: the scratch tree does not build (see {log})")


def test_command(test):
    """One covering test: the header tests' program or a pytest file (stops at its first
    failure)."""
    if test == HEADERS:
        return f"cmake --build build -j2 --target {HEADERS} && build/unittest/{HEADERS}"
    return (f". {SCRATCH}/build/env.sh && unset LAMMPS_PLUGIN_PATH && /usr/bin/python3 -m pytest "
            f"-x -q -p no:cacheprovider {test}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--only", nargs="*", help="run only the mutants whose component contains one "
                    "of these words")
    ap.add_argument("--keep", action="store_true", help="keep the scratch tree")
    args = ap.parse_args()
    log = "/tmp/clusterdyn-mutate.log"
    open(log, "w").close()
    mutants = [m for m in MUTANTS if not args.only or any(w in m[0] for w in args.only)]
    for comp, path, line, _, _, _ in mutants:    # every line still stands as written, once
        text = open(os.path.join(TOP, path)).read()
        if text.count(line) != 1:
            sys.exit(f"mutate.py: '{line}' stands {text.count(line)} times in {path} "
                     f"({comp}): update the mutant")
    scratch_tree(log)
    rows, survived = [], 0
    for comp, path, line, bug, tests, what in mutants:
        start = time.time()
        file = os.path.join(SCRATCH, path)
        original = open(file).read()
        open(file, "w").write(original.replace(line, bug))
        built = True
        if not path.startswith("tools/"):
            built = run("cmake --build build -j2 --target clusterdynplugin", SCRATCH, log) == 0
        by = "does not build" if not built else next(
            (os.path.basename(t) for t in tests if run(test_command(t), SCRATCH, log) != 0),
            "SURVIVED")
        caught = by != "SURVIVED"
        open(file, "w").write(original)
        survived += not caught
        rows.append((comp, what, by, time.time() - start))
        print(f"{comp}: {what}: {by} ({time.time() - start:.0f} s)", flush=True)
    run("cmake --build build -j2 --target clusterdynplugin", SCRATCH, log)
    if not args.keep:
        run(f"git worktree remove --force {SCRATCH}", TOP, log)
    print(f"\n{len(rows) - survived} of {len(rows)} mutants caught, {survived} survived "
          f"(log: {log})")
    return 1 if survived else 0


if __name__ == "__main__":
    sys.exit(main())
