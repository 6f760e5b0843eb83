"""Test harness for the cluster-dynamics plugin (pytest, Debian's /usr/bin/python3).

Run through ctest after `source build/env.sh`: CLUSTERDYN_PLUGIN names the plugin,
CLUSTERDYN_LMP the lmp executable; LAMMPS_PLUGIN_PATH is unset so that every test
loads the plugin by path.  LAMMPS keeps one plugin registry per process, so only
one LAMMPS instance with the plugin may be open at a time: `session()` unloads
it ("plugin clear") when it closes.

Shared by the test files: input templates (fcc_block(), morse_fcc(), morse_dimer(),
SI_CLUSTERS, MCA_FCC_BLOCK), each style's table of hostile input (InputTable, check_input(),
the scenes scene_*() and SCENE_*), and the check of cumulative totals across run boundaries
and restart files (carried_totals()).
"""
import contextlib
import json
import math
import os
import re
import subprocess
import sys

import numpy as np
import pytest
from lammps import lammps

HERE = os.path.dirname(os.path.abspath(__file__))
PLUGIN = os.environ["CLUSTERDYN_PLUGIN"]
LMP = os.environ["CLUSTERDYN_LMP"]
# the plugin built for a CPU without AVX-512 (-march=x86-64-v3: its spline kernels and pair mca's
# passes; unittest/CMakeLists.txt)
AVX2_PLUGIN = os.path.join(os.path.dirname(PLUGIN), "unittest", "clusterdyn_avx2.so")
PAIR_STYLES = [s + v for s in ("morse/spline", "lj/spline", "mie/spline", "harmonic/spline")
               for v in ("", "/omp", "/gpu")]
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


def run_lmp(tmp_path, script, nprocs=1, name="in.test", env=None, args=(), lmp=None):
    """Run the lmp executable (or lmp, another LAMMPS build's; under mpirun for nprocs > 1) on
    script; return stdout."""
    infile = tmp_path / name
    infile.write_text(script)
    cmd = [lmp or LMP, "-in", str(infile), "-log", "none", "-nocite", *args]
    if nprocs > 1:
        cmd = ["mpirun", "-np", str(nprocs), "--oversubscribe"] + cmd
    run_env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    run_env.update(env or {})
    out = subprocess.run(cmd, cwd=tmp_path, env=run_env, capture_output=True, text=True,
                         timeout=600)
    assert out.returncode == 0, f"{' '.join(cmd)} failed:\n{out.stdout[-3000:]}\n{out.stderr[-3000:]}"
    return out.stdout


def lmp_error(tmp_path, lines, name="in.error"):
    """The whole error message of an input that must stop (the lmp executable: the library's
    message is cut at 100 characters); the plugin loaded by path."""
    infile = tmp_path / name
    infile.write_text("\n".join([f"plugin load {PLUGIN}"] + list(lines)) + "\n")
    env = {k: v for k, v in os.environ.items() if k != "LAMMPS_PLUGIN_PATH"}
    out = subprocess.run([LMP, "-in", str(infile), "-log", "none", "-nocite"], cwd=tmp_path,
                         env=env, capture_output=True, text=True, timeout=120)
    assert out.returncode != 0, f"{name} did not stop:\n{out.stdout[-2000:]}"
    return out.stdout + out.stderr


def worst_energy_error(lmp, dt, chunks, span, variable="etot"):
    """After a run 0: the largest |E - E0| of the equal-style variable over `chunks` runs of
    span/dt steps each (velocity Verlet's energy error, for its dt^2 scaling)."""
    lmp.command("run 0")
    e0 = lmp.extract_variable(variable)
    worst = 0.0
    for _ in range(chunks):
        lmp.command(f"run {int(round(span / dt))} pre no post no")
        worst = max(worst, abs(lmp.extract_variable(variable) - e0))
    return worst, e0


def energy_error_spread(script_for_dt, dts=(0.04, 0.02, 0.01)):
    """The relative worst energy error of the input script_for_dt(dt) (its equal-style
    variable etot) at each dt, in one session; velocity Verlet's falls as dt^2."""
    spread = []
    with session() as lmp:
        for dt in dts:
            lmp.command("clear")
            load_plugin(lmp)
            lmp.commands_string(script_for_dt(dt))
            worst, e0 = worst_energy_error(lmp, dt, 20, 0.4)
            spread.append(worst / e0)
    return spread


def assert_falls_as_dt2(spread, first=1e-2):
    """The first error below `first`, each halving of dt dividing it by 3 to 5.5."""
    assert spread[0] < first
    for coarse, fine in zip(spread, spread[1:]):
        assert 3.0 < coarse / fine < 5.5, spread


def thermo_rows(stdout):
    """The rows of the last thermo block (after the last header starting with 'Step'), as an
    array."""
    lines = stdout.splitlines()
    head = [i for i, l in enumerate(lines) if l.split()[:1] == ["Step"]][-1]
    rows = []
    for line in lines[head + 1:]:
        words = line.split()
        if not words or not words[0].isdigit():
            break
        rows.append([float(w) for w in words])
    return np.array(rows)


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


def morse_fcc(n=3, pair="morse/spline cut 1.3", noise=0.05, skin=0.3, atom_map=True):
    """Input lines of a periodic fcc block of n x n x n cells (units lj, nearest neighbours at
    a = 1, mass 1), displaced at random by noise (seed 4711, independent of the decomposition),
    Morse D = 1, alpha a = 6 under `pair`, with a neighbor skin."""
    shake = [f"displace_atoms all random {noise} {noise} {noise} 4711 units box"] if noise else []
    return ["units lj", *(["atom_modify map array"] if atom_map else []),
            "lattice fcc 1.41421356", f"region box block 0 {n} 0 {n} 0 {n}", "create_box 1 box",
            "create_atoms 1 box", "mass 1 1.0", *shake, f"pair_style {pair}",
            "pair_coeff * * 1.0 6.0 1.0", f"neighbor {skin} bin"]


def morse_dimer(r=1.0, pair="morse/spline cut 1.3 link 1.05", atom_map=False):
    """Input lines of two atoms r apart along x, from the origin, in a box -4..4 (units lj,
    mass 1), Morse D = 1, alpha a = 6, a = 1 under `pair`."""
    return ["units lj", *(["atom_modify map array"] if atom_map else []),
            "region box block -4 4 -4 4 -4 4", "create_box 1 box", "mass 1 1.0",
            "create_atoms 1 single 0 0 0 units box", f"create_atoms 1 single {r} 0 0 units box",
            f"pair_style {pair}", "pair_coeff * * 1.0 6.0 1.0", "neighbor 0.3 bin"]


# a simple cubic block of 64 aluminium clusters of 10 um (units si, the dusting paper's), no
# pair style, LAMMPS's default skin (1 mm)
SI_CLUSTERS = ["units si", "lattice sc 1e-5", "region box block 0 4 0 4 0 4", "create_box 1 box",
               "create_atoms 1 box", "mass 1 2.338e-12"]

# pair_style mca on a periodic fcc block of 256 elements of diameter 1 (units lj), shaken by
# 0.01 and barely warm, integrated by fix nve/sphere; {newton} and {dt} to fill in
MCA_FCC_BLOCK = """
units lj
atom_style sphere
boundary p p p
comm_modify vel yes
newton {newton}
lattice fcc $(sqrt(2.0))
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
reset_atoms id sort yes
set group all diameter 1.0
variable phi equal PI/sqrt(18.0)
pair_style mca fraction ${{phi}} tolerance 0.02
pair_coeff 1 1 young 1.0 poisson 0.4
set group all density $(1.0/v_phi)
displace_atoms all random 0.01 0.01 0.01 4711 units box
velocity all create 1.0e-4 4712 loop geom
set group all omega 0.0 0.0 0.0
neighbor 0.2 bin
fix move all nve/sphere
compute rot all erotate/sphere
variable etot equal pe+ke+c_rot
timestep {dt}
thermo_style custom step pe ke c_rot v_etot
thermo_modify norm no format float %.15g
"""


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


# ---------------------------------------------------------------- tables of input rows

OK = "ok"


class InputTable:
    """Bad, hostile and edge-case input of one style, a row each: (setup commands, the commands
    under test, the expected outcome), run by check_input().  The commands run one after another
    after the setup in a LAMMPS instance with the plugin loaded, then `run 0`:
      * expected an error regex: some command (or the final `run 0`) must stop with a LAMMPS
        error whose message (the first ~99 characters the Python exception carries) matches; the
        same instance must then still take commands (`variable alive equal 1`);
      * expected OK: no error, and the thermo pe and press of the final `run 0` are finite
        (thermo_modify norm no), as is every other thermo value (the computes').
    A clear error names the offending argument or keyword (a parameter name, or the plugin's own
    words for it) and what is wrong.  Generic LAMMPS messages raised from inside the plugin's
    parsers (utils::numeric/inumeric/bnumeric/logical/bounds: "Expected floating point parameter
    instead of 'abc'", "Numeric index 3 is out of bounds", "Invalid range string") do not say
    which parameter of the command is wrong and count as unclear, as do messages that mislead.

    A row that shows a defect keeps the behaviour it should have and is a strict xfail with what
    it does now (defect).  Rows flagged isolate (NaN, huge values) run in a child process, so
    that a crash or a hang could not take the test runner down."""

    def __init__(self):
        self.rows = []

    def row(self, rid, setup, cmds, expect, defect=None, isolate=False):
        if isinstance(cmds, str):
            cmds = [cmds]
        if any(r.id == rid for r in self.rows):
            raise ValueError(f"input row {rid} is in the table twice")
        marks = [pytest.mark.xfail(reason=defect, strict=True)] if defect else []
        self.rows.append(pytest.param(list(setup), list(cmds), expect, isolate, id=rid,
                                      marks=marks))


def observe_input(setup, cmds):
    """('error', message, command) or ('ok', pe, press, {thermo keyword: value}) of one row, in
    this process."""
    with session() as lmp:
        lmp.commands_list(setup)
        for cmd in cmds + ["run 0 post no"]:
            try:
                lmp.command(cmd)
            except Exception as e:    # LAMMPS's error, as the library reports it
                lmp.command("variable alive equal 1")    # the instance still takes commands
                return ["error", str(e), cmd]
        return ["ok", lmp.get_thermo("pe"), lmp.get_thermo("press"), lmp.last_thermo()]


def observe_input_isolated(setup, cmds, timeout=120):
    """observe_input() in a child process: a crash or a hang is an outcome too."""
    code = ("import json, sys, conftest; print('RESULT', "
            "json.dumps(conftest.observe_input(*json.loads(sys.argv[1]))))")
    env = dict(os.environ)
    env.pop("LAMMPS_PLUGIN_PATH", None)
    try:
        out = subprocess.run([sys.executable, "-c", code, json.dumps([setup, cmds])], cwd=HERE,
                             env=env, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return ["hang", timeout]
    for line in out.stdout.splitlines():
        if line.startswith("RESULT "):
            return json.loads(line[len("RESULT "):])
    return ["crash", out.returncode, (out.stdout + out.stderr)[-2000:]]


def check_input(setup, cmds, expect, isolate=False):
    """Run one row of an InputTable and check its outcome."""
    got = observe_input_isolated(setup, cmds) if isolate else observe_input(setup, cmds)
    if expect == OK:
        assert got[0] == "ok", got
        assert math.isfinite(got[1]) and math.isfinite(got[2]), got
        assert all(math.isfinite(v) for v in got[3].values()), got    # the computes' too
    else:
        assert got[0] == "error", got
        assert re.search(expect, got[1]), got


# the scenes of the input rows: the four spline laws (a = 1) and their default tails
SCENE_LAW = {"morse/spline": "1.0 6.0 1.0", "lj/spline": "1.0 1.0",
             "mie/spline": "1.0 1.0 12 6", "harmonic/spline": "1.0 6.0 1.0"}
SCENE_TAIL = {"morse/spline": "cut 1.3", "lj/spline": "wagner", "mie/spline": "lagunov 1.4",
              "harmonic/spline": "lagunov 1.3 start 1.1"}


def scene_box(units="lj", ntypes=2, omp=False):
    """An empty periodic box of ntypes types (units lj: -3..3), thermo not normalised."""
    return (["package omp 2"] if omp else []) + [
        f"units {units}", "atom_modify map array", "region box block -3 3 -3 3 -3 3",
        f"create_box {ntypes} box", "mass * 1.0", "thermo_modify norm no"]


def scene_dimer(r=1.05, omp=False, ntypes=2):
    """Two type-1 atoms r apart along x (a = 1) in scene_box()."""
    return scene_box(omp=omp, ntypes=ntypes) + ["create_atoms 1 single 0 0 0",
                                                f"create_atoms 1 single {r!r} 0 0"]


def scene_pair(style="morse/spline", tail=None, law=None, omp=False):
    return [f"pair_style {style}{'/omp' if omp else ''} {tail or SCENE_TAIL[style]}",
            f"pair_coeff * * {law or SCENE_LAW[style]}"]


SCENE_NOBOX = ["units lj"]
SCENE_BOX = scene_box()
SCENE_MORSE = scene_dimer() + scene_pair("morse/spline", "cut 1.3")
SCENE_LINKED = scene_dimer() + scene_pair("morse/spline", "cut 1.3 link 1.1")
# an empty box -2..2 of one type
SCENE_EMPTY = ["units lj", "region box block -2 2 -2 2 -2 2", "create_box 1 box", "mass 1 1.0"]

# unit styles: (units, a, D, alpha, mass, skin) of scene_unit_dimer()
SCENE_UNITS = {
    "metal": ("metal", 2.5, 0.3, 1.5, 63.5, 1.0),
    "real": ("real", 3.0, 0.2, 2.0, 27.0, 1.0),
    "si": ("si", 1.0e-5, 2.46e-6, 3.76e5, 1.0e-12, 2.0e-6),
}


def scene_unit_dimer(name, style):
    """A dimer 1.05 a apart of the spline style in the unit style name (SCENE_UNITS)."""
    units, a, d, alpha, mass, skin = SCENE_UNITS[name]
    law = {"morse/spline": f"{d} {alpha} {a}", "harmonic/spline": f"{d} {alpha} {a}",
           "lj/spline": f"{d} {a}", "mie/spline": f"{d} {a} 9 6"}[style]
    tail = "lagunov 1.3 start 1.1" if style == "harmonic/spline" else "cut 1.3"
    return [f"units {units}", "atom_modify map array",
            f"region box block {-4 * a} {4 * a} {-4 * a} {4 * a} {-4 * a} {4 * a}",
            "create_box 1 box", f"mass 1 {mass}", f"neighbor {skin} bin",
            "thermo_modify norm no", "create_atoms 1 single 0 0 0",
            f"create_atoms 1 single {1.05 * a!r} 0 0", f"pair_style {style} {tail}",
            f"pair_coeff 1 1 {law}"]


def scene_mca(style="sphere", units="lj", zlo=-3.0, zhi=3.0):
    """Two touching elements of diameter 1 for pair mca (types 1 and 2 exist, both atoms type
    1), without the pair style."""
    return [f"units {units}", f"atom_style {style}", "atom_modify map array",
            "comm_modify vel yes", f"region box block -3 3 -3 3 {zlo} {zhi}", "create_box 2 box",
            "create_atoms 1 single 0 0 0", "create_atoms 1 single 1.0 0 0",
            "thermo_modify norm no"] + (["set group all diameter 1.0"] if style == "sphere" else [])


# ---------------------------------------------------------------- cumulative totals

def carried_totals(tmp_path, scene, values, again, n, m, nprocs=1, restart=True):
    """A scene's cumulative totals (values: LAMMPS references, c_ID[k], f_ID ...) across run
    boundaries and restart files, from one lmp process on nprocs ranks (each part after a
    `clear`), as arrays by name:
      straight_n, straight_nm: `run N+M` uninterrupted, at step N (fix vector) and at its end;
      split_n, split_nm, boundary: `run N`, `run M pre no` (no setup between: the straight run,
        to the bit, where nothing changed), `run 0` (a setup at the same step);
      read_nm: a restart file written after that, read in a fresh instance, `run 0`;
      mid_nm: `run N+M` writing a restart file at step N (`restart N`), at its end;
      read_n, resumed_nm: that file read in a fresh instance, `run 0`, then `run M`.
    scene: the input after `plugin load` up to the run (its computes and fixes defined); again:
    what a restart file does not carry (fixes, computes, neighbor and comm settings)."""
    refs = " ".join(values)
    head = f"plugin load {PLUGIN}\n"
    outputs = f"thermo_style custom step {refs}\nthermo_modify norm no\n"

    def show(tag, refs=values):
        return f'print "RESULT {tag} ' + " ".join(f"$({v}:%.17g)" for v in refs) + '"\n'

    def row(k):
        return [f"f_rec[{k}]" if len(values) == 1 else f"f_rec[{k}][{j + 1}]"
                for j in range(len(values))]

    def read(name):
        return f"clear\n{head}read_restart {name}\n{again}\n{outputs}run 0 post no\n"

    script = (head + scene + "\n" + outputs + f"fix rec all vector {n} {refs}\nrun {n + m}\n" +
              show("straight_n", row(2)) + show("straight_nm") +
              f"clear\n{head}{scene}\n{outputs}run {n}\n" + show("split_n") +
              f"run {m} pre no\n" + show("split_nm") + "run 0 post no\n" + show("boundary"))
    if restart:
        script += ("write_restart between.restart\n" + read("between.restart") +
                   show("read_nm") +
                   f"clear\n{head}{scene}\n{outputs}restart {n} mid.*\nrun {n + m}\n" +
                   show("mid_nm") + read(f"mid.{n}") + show("read_n") + f"run {m}\n" +
                   show("resumed_nm"))
    out = run_lmp(tmp_path, script, nprocs)
    return {m_.group(1): np.array([float(v) for v in m_.group(2).split()])
            for m_ in re.finditer(r"^RESULT (\S+) (.+)$", out, re.M)}
