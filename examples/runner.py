"""Running the examples' LAMMPS input scripts: the one runner module of every example script
(examples/*/run_*.py and the other drivers) and of the studies in bench/.

- an input script run in this process with -var settings (the lammps module): script(), with
  a fix's global array read by global_array();
- the same as an lmp command, for MPI ranks and OpenMP threads: lmp_command();
- a run's folder named by its settings (tag()) and its result kept there as result.json, so
  that a second call only reads it (keep(), kept()); delete the folder to run it again;
- runs in parallel, one per core (parallel()), and the command line of the sweeps
  (arguments(): --jobs, --report);
- what LAMMPS's output and logs say: loop times (loops()), thermo rows (thermo()), whether a
  run finished and its wall time (finished(), wall_time());
- the tables the drivers write: mean ± sd of an ensemble (mean_sd()), markdown tables
  (table()).

The records of the shock scenes (x-t data, histograms, the pull-back of a spall signal) are
read by shock_records.py."""
import argparse
import contextlib
import json
import multiprocessing
import os
import re
import subprocess

import numpy as np
from lammps import LMP_SIZE_COLS, LMP_SIZE_ROWS, LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY, lammps


def var_args(var):
    """The -var arguments of the settings `var` (a dict: name, value)."""
    args = []
    for key, value in var.items():
        args += ["-var", key, str(value)]
    return args


@contextlib.contextmanager
def script(path, var, workdir=None, log="none"):
    """Run the input script `path` with the -var settings `var` in `workdir` (default: the
    script's folder) and yield the LAMMPS instance.  On exit the plugin is unloaded (LAMMPS
    keeps one plugin registry per process) and the instance closed."""
    args = ["-log", log, "-screen", "none", "-nocite"] + var_args(var)
    cwd = os.getcwd()
    os.chdir(workdir or os.path.dirname(os.path.abspath(path)))
    lmp = lammps(cmdargs=args)
    try:
        lmp.file(os.path.abspath(os.path.join(cwd, path)))
        yield lmp
    finally:
        lmp.command("plugin clear")
        lmp.close()
        os.chdir(cwd)


def global_array(lmp, fix):
    """A fix's global array (the library hands it out element by element)."""
    rows = lmp.extract_fix(fix, LMP_STYLE_GLOBAL, LMP_SIZE_ROWS)
    cols = lmp.extract_fix(fix, LMP_STYLE_GLOBAL, LMP_SIZE_COLS)
    return np.array([[lmp.extract_fix(fix, LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY, i, j)
                      for j in range(cols)] for i in range(rows)])


def lmp_command(path, var, cwd, args=(), nprocs=1, env=None):
    """Run the input script `path` with the lmp executable (CLUSTERDYN_LMP, else lmp on PATH)
    and the -var settings `var` in the folder `cwd`, under mpirun for nprocs > 1, with the
    environment `env` (default: this one); its screen output.  A failed run raises
    subprocess.CalledProcessError."""
    cmd = [os.environ.get("CLUSTERDYN_LMP", "lmp"), "-in", path, "-log", "none", "-nocite",
           *var_args(var), *args]
    if nprocs > 1:
        cmd = ["mpirun", "-np", str(nprocs)] + cmd
    return subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True,
                          check=True).stdout


def tag(var):
    """The name of a run's folder: its settings, sorted by name (u2000-rc1.1 style)."""
    return "-".join(f"{k}{v}" for k, v in sorted(var.items()))


def kept(workdir):
    """The result kept in workdir/result.json, or None if the run has not finished."""
    path = os.path.join(workdir, "result.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def keep(workdir, make):
    """The result kept in workdir, or else make(workdir)'s (run in the folder, made first),
    kept there as result.json for the next call."""
    result = kept(workdir)
    if result is not None:
        return result
    os.makedirs(workdir, exist_ok=True)
    result = make(workdir)
    with open(os.path.join(workdir, "result.json"), "w") as f:
        json.dump(result, f)
    return result


def parallel(function, items, jobs=2):
    """function(item) for every item, `jobs` processes at a time (one item each in turn), in
    the order of the items.  Each process runs its own LAMMPS instances (one plugin registry
    per process)."""
    with multiprocessing.Pool(jobs) as pool:
        return pool.map(function, items, chunksize=1)


def arguments(doc, report=False):
    """The command line of a sweep: --jobs N (runs at a time, default 2: one per core) and,
    with report, --report (tables and plots from the kept runs only).  `doc`: the script's
    docstring, whose first line describes it."""
    ap = argparse.ArgumentParser(description=doc.strip().split("\n")[0])
    ap.add_argument("--jobs", type=int, default=2)
    if report:
        ap.add_argument("--report", action="store_true")
    return ap.parse_args()


LOOP = re.compile(r"^Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms", re.M)


def loops(text):
    """Every run of a LAMMPS screen output or log text: [(loop time in s, procs, steps,
    atoms)] from its "Loop time of" lines."""
    return [(float(t), int(p), int(s), int(a)) for t, p, s, a in LOOP.findall(text)]


def thermo(log):
    """The thermo rows of a log file (the runs with the last run's columns, one after
    another), as an array."""
    rows, keys, header = [], None, None
    for line in open(log):
        words = line.split()
        if words[:1] == ["Step"]:
            rows = rows if words == header else []
            keys = header = words
        elif keys and len(words) == len(keys):
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                keys = None
        elif words[:2] == ["Loop", "time"]:
            keys = None
    return np.array(rows)


def finished(log):
    """Whether the log file exists and its run finished ("Total wall time")."""
    return os.path.exists(log) and "Total wall time" in open(log).read()


def wall_time(log):
    """LAMMPS's total wall time of a log file (s; 0 if it has none)."""
    wall = 0.0
    for line in open(log):
        if line.startswith("Total wall time:"):
            h, m, sec = line.split()[-1].split(":")
            wall = 3600 * int(h) + 60 * int(m) + int(sec)
    return wall


def mean_sd(values, digits=2, scale=1.0):
    """The mean ± sample standard deviation of values / scale, with `digits` decimals."""
    values = np.asarray(values, dtype=float) / scale
    return f"{values.mean():.{digits}f} ± {values.std(ddof=1):.{digits}f}"


def table(header, rows):
    """A markdown table: the header's cells and rows of cells (any values), as lines."""
    return ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)] + \
           ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
