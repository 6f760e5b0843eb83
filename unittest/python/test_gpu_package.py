"""The GPU package of the LAMMPS build (OpenCL, mixed precision; on these machines the device is
the CPU through pocl, Debian's pocl-opencl-icd): stock pair_style morse/gpu against morse on
the same scenes, with host-built neighbour lists (package gpu 1 neigh no: pocl's device-built
lists give wrong forces, doc/Build.rst "GPUs").  Oracle: the CPU style.  Mixed precision
computes each pair in single precision and sums in double: forces agree within the rounding of
the coordinates to single precision (bounded with the Morse stiffness), energy and pressure to
1e-6 and 1e-5, and a 200-step run keeps the energy to 1e-6.  500
atoms: an inum that is not a multiple of 32, where the package, treating pocl's device as one
that shares the host's memory, stopped with a misaligned sub-buffer (CL error -13); the build
sets GERYON_FORCE_SHARED_MAIN_MEM_OFF (doc/Build.rst).  Per-atom energy and virial (pe/atom,
stress/atom) within the force bound times the cutoff.  On a real GPU the same test runs with
device-built lists: CLUSTERDYN_GPU_NEIGH=yes."""
import math
import os
import re

import numpy as np
import pytest
from conftest import morse_fcc, run_lmp

# a warm fcc block of 500 atoms (lj) and the same in units metal (copper-like Morse: D 0.3429
# eV, alpha 1.3588 / A, r0 2.866 A, fcc at 3.615 A)
SCENES = {
    "lj": (morse_fcc(5, "morse 2.5", noise=0.05, skin=0.3)[:-2] +
           ["pair_coeff * * 1.0 6.0 1.0", "neighbor 0.3 bin",
            "velocity all create 0.3 4711 loop geom", "timestep 0.002"]),
    "metal": ["units metal", "atom_modify map array", "lattice fcc 3.615",
              "region box block 0 5 0 5 0 5", "create_box 1 box", "create_atoms 1 box",
              "mass 1 63.546", "displace_atoms all random 0.05 0.05 0.05 4711 units box",
              "pair_style morse 6.0", "pair_coeff * * 0.3429 1.3588 2.866", "neighbor 1.0 bin",
              "velocity all create 300 4711 loop geom", "timestep 0.001"],
}
# each scene's Morse D, alpha, box side (its coordinates' largest magnitude) and cutoff
MORSE = {"lj": (1.0, 6.0, 5 * 1.41421356, 2.5), "metal": (0.3429, 1.3588, 5 * 3.615, 6.0)}
# LAMMPS's force->nktv2p (update.cpp): stress/atom is a virial times it
NKTV2P = {"lj": 1.0, "metal": 1.6021765e6}
# package gpu's neighbour lists: host-built (no) unless told (yes, on a real GPU)
NEIGH = os.environ.get("CLUSTERDYN_GPU_NEIGH", "no")
REPORT = ["compute pe all pe/atom", "compute s all stress/atom NULL pair",
          "thermo_style custom step pe press etotal", "thermo_modify norm no format float %.15g",
          "run 0", "write_dump all custom forces.dump id fx fy fz c_pe c_s[1] c_s[4] "
          "modify sort id format float %.17g",
          'print "RESULT pe $(pe:%.17g) press $(press:%.17g)"',
          "fix nve all nve", "run 200", 'print "RESULT pe200 $(pe:%.17g) etotal200 $(etotal:%.17g)"']


def run(tmp_path, units, gpu):
    """The scene under morse (gpu False) or morse/gpu on the OpenCL device: screen, forces."""
    lines = list(SCENES[units])
    if gpu:
        lines = [x.replace("pair_style morse", "pair_style morse/gpu") for x in lines]
    folder = tmp_path / ("gpu" if gpu else "cpu")
    folder.mkdir()
    args = ["-pk", "gpu", "1", "neigh", NEIGH] if gpu else []
    out = run_lmp(folder, "\n".join(lines + REPORT) + "\n", args=args)
    return out, np.loadtxt(folder / "forces.dump", skiprows=9)[:, 1:]


def results(out):
    """The name value pairs of the RESULT lines."""
    words = " ".join(re.findall(r"^RESULT (.*)$", out, re.M)).split()
    return {words[k]: float(words[k + 1]) for k in range(0, len(words), 2)}


@pytest.mark.parametrize("units", ["lj", "metal"])
def test_stock_morse_gpu_on_opencl_equals_morse_to_mixed_precision(tmp_path, units):
    cpu_out, cpu_atoms = run(tmp_path, units, False)
    gpu_out, gpu_atoms = run(tmp_path, units, True)
    f_cpu, f_gpu = cpu_atoms[:, :3], gpu_atoms[:, :3]
    # it ran on the OpenCL device, with the GPU package's morse
    assert re.search(r"Device 0: .*", gpu_out), gpu_out[-2000:]
    assert "Using acceleration for morse:" in gpu_out
    cpu, gpu = results(cpu_out), results(gpu_out)
    assert np.abs(f_cpu).max() > 0.0
    # mixed precision rounds the coordinates to single precision, 2^-24 of up to the box side
    # L: each pair's force is off by that times the Morse stiffness 2 alpha^2 D, a random sum
    # over the n neighbours (LAMMPS's count of the half list, twice): bound 4x that
    d, alpha, side, cut = MORSE[units]
    n = 2.0 * float(re.search(r"Ave neighs/atom = (\S+)", cpu_out).group(1))
    bound = 4.0 * 2.0 ** -24 * side * 2.0 * alpha ** 2 * d * math.sqrt(n)
    assert np.abs(f_gpu - f_cpu).max() < bound
    assert np.abs(gpu_atoms[:, 3] - cpu_atoms[:, 3]).max() < bound * cut
    assert np.abs(gpu_atoms[:, 4:6] - cpu_atoms[:, 4:6]).max() < bound * cut * NKTV2P[units]
    assert gpu["pe"] == pytest.approx(cpu["pe"], rel=1e-6)
    assert gpu["press"] == pytest.approx(cpu["press"], rel=1e-5, abs=1e-5 * abs(cpu["pe"]))
    assert gpu["pe200"] == pytest.approx(cpu["pe200"], rel=1e-6)
    assert gpu["etotal200"] == pytest.approx(cpu["etotal200"], rel=1e-6)
