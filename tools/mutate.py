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
     "u = law.energy_after(u, w0, j1, q, 0.5 * j1 * trace);",
     "u = law.energy_after(u, 2.0 * w0, j1, q, 0.5 * j1 * trace);",
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
