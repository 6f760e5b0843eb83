"""The /gpu variants of the spline pair styles (morse/spline/gpu, harmonic/spline/gpu,
lj/spline/gpu, mie/spline/gpu; clusterdyn_gpu.so, doc/pair_spline.rst "GPU variants") on the
GPU package's OpenCL device, here the CPU through pocl, with host-built neighbour lists
(package gpu 1 neigh no: pocl's device-built lists crash the stock styles too, doc/Build.rst).
Oracle: the CPU style on the same scene, picked by the same input (`-sf gpu` picks the
variant).  Mixed precision computes each pair in single precision and sums in double: a
pair's force is off by the rounding of the coordinates to single precision (2^-24 of up to the
box side L) times the law's stiffness at the closest pair, plus its own rounding (2^-24 of the
largest pair force), a random sum over the n neighbours: the forces must agree within 4x that.
Energy within 1e-6, pressure 1e-5, per-atom energy and virial within the same bound as forces
times the pair distance, a 100-step run keeps the total energy to 1e-6.  Every law, every
tail, kappa on and off, in units lj and metal; the host's share of the atoms (package gpu
split), 2 MPI ranks, fix viscous/relative beside the pair, and the refusals.
On a real GPU the same tests run with device-built lists: CLUSTERDYN_GPU_NEIGH=yes.
In double precision (a second LAMMPS build with GPU_PREC=double and the plugin built against it,
made by tools/bootstrap.sh: CLUSTERDYN_GPU_DOUBLE_LAMMPS, CLUSTERDYN_GPU_DOUBLE_PLUGIN) the same
scenes agree to round-off: each pair's force within 32 ulp (the device's exp and pow against
glibc's, OpenCL's own bound for pow being 16 ulp), summed without cancellation over the
neighbours."""
import math
import os
import re

import numpy as np
import pytest
from pathlib import Path

from conftest import PLUGIN, fcc_density, lmp_error, run_lmp
from spec_laws import Law

# package gpu's neighbour lists: host-built (no) unless told (yes, on a real GPU)
NEIGH = os.environ.get("CLUSTERDYN_GPU_NEIGH", "no")

# (units, a, D, mass) of the scenes: a two-type fcc block, nearest neighbours at a, 5 x 5 x 5
# cells (500 atoms: an inum that is not a multiple of 32), skin 0.3 a
UNITS = {"lj": ("lj", 1.0, 1.0, 1.0), "metal": ("metal", 2.5, 0.3, 63.5)}
# LAMMPS's force->nktv2p of each (force.cpp, update.cpp): pressure times volume per energy
NKTV2P = {"lj": 1.0, "metal": 1.6021765e6}

# (style, tail, {type pair: (law args in units of a and D, kappa)}): every law and tail, kappa
# on some pairs (lj and mie: the kappa kernel, kappa <= 1 as the /gpu styles require; morse and
# harmonic fold it into the constants)
CASES = {
    "morse-cut-kappa": ("morse", "cut 1.6", {"1 1": ("morse", 6.0, 1.3), "1 2": ("morse", 5.0, 1.0),
                                             "2 2": ("morse", 7.0, 1.0)}),
    "morse-wagner": ("morse", "wagner", {"1 1": ("morse", 6.0, 1.0), "1 2": ("morse", 5.0, 1.2),
                                         "2 2": ("morse", 7.0, 1.0)}),
    "morse-lagunov": ("morse", "lagunov 1.6", {"1 1": ("morse", 6.0, 1.1),
                                               "1 2": ("morse", 5.0, 1.0),
                                               "2 2": ("morse", 7.0, 1.0)}),
    "harmonic-lagunov": ("harmonic", "lagunov 1.3 start 1.1",
                         {"1 1": ("harmonic", 3.0, 1.0), "1 2": ("harmonic", 2.5, 1.2),
                          "2 2": ("harmonic", 3.5, 1.0)}),
    "lj-cut-kappa": ("lj", "cut 1.6", {"1 1": ("lj", None, 0.9), "1 2": ("lj", None, 1.0),
                                       "2 2": ("lj", None, 1.0)}),
    "lj-wagner": ("lj", "wagner", {"1 1": ("lj", None, 1.0), "1 2": ("lj", None, 1.0),
                                   "2 2": ("lj", None, 1.0)}),
    "mie-lagunov-kappa": ("mie", "lagunov 1.6", {"1 1": ("mie", None, 0.9),
                                                 "1 2": ("mie", None, 1.0),
                                                 "2 2": ("mie", None, 1.0)}),
    "mie-cut": ("mie", "cut 1.6", {"1 1": ("mie", None, 1.0), "1 2": ("mie", None, 1.0),
                                   "2 2": ("mie", None, 1.0)}),
}
# the depth of each type pair's well relative to D (two types that differ)
DEPTH = {"1 1": 1.0, "1 2": 0.8, "2 2": 1.2}


def laws(case, units):
    """spec_laws.Law of each type pair of a case in a unit style."""
    _, a, d, _ = UNITS[units]
    out = {}
    for pair, (base, alpha_a, kappa) in CASES[case][2].items():
        law = Law(base, D=d * DEPTH[pair], a=a, kappa=kappa)
        if alpha_a is not None:
            law.alpha = alpha_a / a
        if base == "mie":
            law.n, law.m = 9.0, 6.0
        out[pair] = law
    return out


def scene(case, units, extra=()):
    name, a, _, mass = UNITS[units]
    style, tail, _ = CASES[case]
    lattice = fcc_density(a) if name == "lj" else a * math.sqrt(2.0)
    lines = [f"units {name}", "atom_modify map array", f"lattice fcc {lattice!r}",
             "region box block 0 5 0 5 0 5", "create_box 2 box", "create_atoms 1 box",
             f"mass * {mass}", "reset_atoms id sort yes",
             "set type 1 type/fraction 2 0.4 4711",
             f"displace_atoms all random {0.04 * a} {0.04 * a} {0.04 * a} 4712 units box",
             f"velocity all create {0.02 if name == 'lj' else 200.0} 4713 loop geom",
             f"neighbor {0.3 * a} bin", f"pair_style {style}/spline {tail}"]
    for pair, law in laws(case, units).items():
        lines.append(f"pair_coeff {pair} {law.coeff()}")
    return lines + list(extra)


REPORT = ["compute pe all pe/atom", "compute s all stress/atom NULL pair",
          "thermo_style custom step pe press etotal",
          "thermo_modify norm no format float %.15g", "run 0",
          "write_dump all custom forces.dump id fx fy fz c_pe c_s[1] c_s[4] x y z "
          "modify sort id format float %.17g",
          'print "RESULT pe $(pe:%.17g) press $(press:%.17g) pxy $(pxy:%.17g)"',
          "fix nve all nve", "run 100", 'print "RESULT etotal100 $(etotal:%.17g)"']


# the double-precision build (tools/bootstrap.sh); the tests that need it skip without it
DOUBLE_LAMMPS = os.environ.get("CLUSTERDYN_GPU_DOUBLE_LAMMPS", "")
DOUBLE_PLUGIN = os.environ.get("CLUSTERDYN_GPU_DOUBLE_PLUGIN", "")
needs_double = pytest.mark.skipif(not (DOUBLE_PLUGIN and os.path.exists(DOUBLE_PLUGIN)),
                                  reason="no LAMMPS with the GPU package in double precision "
                                  "(tools/bootstrap.sh makes it)")


def run(tmp_path, lines, folder, gpu=None, nprocs=1, double=False):
    """The scene on the CPU style (gpu None) or with -sf gpu and package gpu's options; double:
    in the double-precision build (its lmp, its liblammps first on the library path)."""
    path = tmp_path / folder
    path.mkdir()
    args = ["-sf", "gpu", "-pk", "gpu", "1", "neigh", NEIGH, *gpu] if gpu is not None else []
    plugin, lmp, env = PLUGIN, None, None
    if double:
        plugin, lmp = DOUBLE_PLUGIN, os.path.join(DOUBLE_LAMMPS, "lmp")
        env = {"LD_LIBRARY_PATH": DOUBLE_LAMMPS + ":" + os.path.dirname(DOUBLE_PLUGIN)}
    out = run_lmp(path, "\n".join([f"plugin load {plugin}"] + list(lines)) + "\n", args=args,
                  nprocs=nprocs, lmp=lmp, env=env)
    return out, np.loadtxt(path / "forces.dump", skiprows=9)


def results(out):
    words = " ".join(re.findall(r"^RESULT (.*)$", out, re.M)).split()
    return {words[k]: float(words[k + 1]) for k in range(0, len(words), 2)}


def closest(dump, side):
    """The shortest distance between two atoms of the periodic cube of side `side`."""
    x = dump[:, 7:10]
    d = x[:, None, :] - x[None, :, :]
    d -= side * np.round(d / side)
    r = np.sqrt((d ** 2).sum(axis=2))
    np.fill_diagonal(r, np.inf)
    return r.min()


def force_bound(case, units, dump, out):
    """4x the mixed-precision error of a force (module docstring): the stiffness |f'| of the
    stiffest type pair at the closest distance (a central difference of the law's f), the box
    side, the largest pair force at that distance, and sqrt(n) for n neighbours."""
    a = UNITS[units][1]
    side = 5 * a * math.sqrt(2.0)
    r = closest(dump, side)
    h = 1e-6 * a
    stiff = max(abs(law.f(r + h) - law.f(r - h)) / (2 * h) for law in laws(case, units).values())
    fmax = max(abs(law.f(r)) for law in laws(case, units).values())
    n = 2.0 * float(re.search(r"Ave neighs/atom = (\S+)", out).group(1))
    return 4.0 * 2.0 ** -24 * (side * stiff + fmax) * math.sqrt(n), side


def virial_scale(dump, side):
    """The absolute sum of the pair virial's xx terms over the volume (a pressure): the scale
    of the rounding in the pressure, whose terms cancel."""
    return np.abs(dump[:, 5]).sum() / side ** 3


@pytest.mark.parametrize("units", ["lj", "metal"])
@pytest.mark.parametrize("case", list(CASES))
def test_gpu_variant_equals_the_cpu_style_to_mixed_precision(tmp_path, case, units):
    lines = scene(case, units) + REPORT
    cpu_out, cpu = run(tmp_path, lines, "cpu")
    gpu_out, gpu = run(tmp_path, lines, "gpu", gpu=[])
    style = CASES[case][0]
    # the variant ran on the OpenCL device (the GPU library's own message at its init)
    assert f"Using acceleration for {style}/spline:" in gpu_out, gpu_out[-2000:]
    assert re.search(r"Device 0: .*", gpu_out), gpu_out[-2000:]
    bound, side = force_bound(case, units, cpu, cpu_out)
    f_cpu, f_gpu = cpu[:, 1:4], gpu[:, 1:4]
    assert np.abs(f_cpu).max() > 1e3 * bound    # a scene with forces well above the bound
    assert np.abs(f_gpu - f_cpu).max() < bound
    # per-atom energy and virial (the device's eatom and vatom): a pair's error is its force's
    # times the pair distance (every tail here ends before 2 a)
    cut = 2.0 * UNITS[units][1]
    assert np.abs(gpu[:, 4] - cpu[:, 4]).max() < bound * cut + 1e-6 * np.abs(cpu[:, 4]).max()
    nktv2p = NKTV2P[units]    # stress/atom is a virial times LAMMPS's nktv2p
    assert np.abs(gpu[:, 5:7] - cpu[:, 5:7]).max() < bound * cut * nktv2p
    c, g = results(cpu_out), results(gpu_out)
    assert g["pe"] == pytest.approx(c["pe"], rel=1e-6)
    # pressure: a sum of terms of both signs, within 1e-5 of the terms' absolute sum
    scale = virial_scale(cpu, side)
    assert g["press"] == pytest.approx(c["press"], abs=1e-5 * scale)
    assert g["pxy"] == pytest.approx(c["pxy"], abs=1e-5 * scale)
    assert g["etotal100"] == pytest.approx(c["etotal100"], rel=1e-6)


@needs_double
@pytest.mark.parametrize("units", ["lj", "metal"])
@pytest.mark.parametrize("case", list(CASES))
def test_gpu_variant_in_double_precision_equals_the_cpu_style_to_round_off(tmp_path, case, units):
    lines = scene(case, units) + REPORT
    cpu_out, cpu = run(tmp_path, lines, "cpu", double=True)
    gpu_out, gpu = run(tmp_path, lines, "gpu", gpu=[], double=True)
    assert "(Double Precision)" in gpu_out
    assert f"Using acceleration for {CASES[case][0]}/spline:" in gpu_out
    n = 2.0 * float(re.search(r"Ave neighs/atom = (\S+)", cpu_out).group(1))
    fmax = np.abs(cpu[:, 1:4]).max()    # at least the largest pair force's component
    a = UNITS[units][1]
    side = 5 * a * math.sqrt(2.0)
    r = closest(cpu, side)
    fpair = max(abs(law.f(r)) for law in laws(case, units).values())
    bound = 32 * 2.0 ** -52 * fpair * n
    assert fmax > 1e6 * bound
    assert np.abs(gpu[:, 1:4] - cpu[:, 1:4]).max() < bound
    cut = 2.0 * a
    assert np.abs(gpu[:, 4] - cpu[:, 4]).max() < bound * cut + 1e-14 * np.abs(cpu[:, 4]).max()
    assert np.abs(gpu[:, 5:7] - cpu[:, 5:7]).max() < bound * cut * NKTV2P[units]
    c, g = results(cpu_out), results(gpu_out)
    assert g["pe"] == pytest.approx(c["pe"], rel=1e-13)
    assert g["press"] == pytest.approx(c["press"], abs=1e-13 * virial_scale(cpu, side))
    assert g["etotal100"] == pytest.approx(c["etotal100"], rel=1e-12)


@pytest.mark.parametrize("case", ["morse-lagunov", "lj-cut-kappa"])
def test_host_share_of_the_atoms_equals_the_cpu_style(tmp_path, case):
    """package gpu split 0.5 (which needs newton off): half of the atoms' forces on the host
    (full lists, the style's own law and tail in double precision), the rest on the device."""
    lines = ["newton off"] + scene(case, "metal") + REPORT
    cpu_out, cpu = run(tmp_path, lines, "cpu")
    gpu_out, gpu = run(tmp_path, lines, "gpu", gpu=["newton", "off", "split", "0.5"])
    bound, side = force_bound(case, "metal", cpu, cpu_out)
    assert np.abs(gpu[:, 1:4] - cpu[:, 1:4]).max() < bound
    c, g = results(cpu_out), results(gpu_out)
    assert g["pe"] == pytest.approx(c["pe"], rel=1e-6)
    assert g["press"] == pytest.approx(c["press"], abs=1e-5 * virial_scale(cpu, side))
    assert g["etotal100"] == pytest.approx(c["etotal100"], rel=1e-6)


def test_more_types_than_local_memory_holds(tmp_path):
    """12 types (13 rows with type 0: beyond MAX_SHARED_TYPES = 11): the kernel that reads the
    type table from global memory (k_spline), each type pair its own depth and stiffness."""
    lines = [x for x in scene("morse-lagunov", "lj") if not x.startswith("pair_coeff")]
    lines = [x.replace("create_box 2 box", "create_box 12 box") for x in lines]
    at = lines.index("set type 1 type/fraction 2 0.4 4711")
    lines[at:at + 1] = [f"set type 1 type/fraction {t} {1.0 / (14 - t)!r} {4700 + t}"
                        for t in range(2, 13)]
    laws = {}
    for i in range(1, 13):
        for j in range(i, 13):
            laws[(i, j)] = Law("morse", D=1.0 + 0.05 * (i + j), a=1.0, alpha=5.0 + 0.1 * abs(i - j))
            lines.append(f"pair_coeff {i} {j} {laws[(i, j)].coeff()}")
    lines += REPORT
    cpu_out, cpu = run(tmp_path, lines, "cpu")
    gpu_out, gpu = run(tmp_path, lines, "gpu", gpu=[])
    assert "Using acceleration for morse/spline:" in gpu_out
    side = 5 * math.sqrt(2.0)
    r = closest(cpu, side)
    h = 1e-6
    stiff = max(abs(law.f(r + h) - law.f(r - h)) / (2 * h) for law in laws.values())
    fmax = max(abs(law.f(r)) for law in laws.values())
    n = 2.0 * float(re.search(r"Ave neighs/atom = (\S+)", cpu_out).group(1))
    bound = 4.0 * 2.0 ** -24 * (side * stiff + fmax) * math.sqrt(n)
    assert np.abs(gpu[:, 1:4] - cpu[:, 1:4]).max() < bound
    c, g = results(cpu_out), results(gpu_out)
    assert g["pe"] == pytest.approx(c["pe"], rel=1e-6)
    assert g["etotal100"] == pytest.approx(c["etotal100"], rel=1e-6)


def test_special_bonds_with_a_shifted_cut_tail(tmp_path):
    """Bonded nearest neighbours (atom_style bond, bond_style zero) with special_bonds lj 0 0.5
    0.8 and pair_modify shift yes: each special pair's energy is its factor times the shifted
    law, e - offset, as the CPU style tallies it."""
    lines = ["units lj", "atom_style bond", "atom_modify map array", "lattice fcc 1.41421356",
             "region box block 0 4 0 4 0 4",
             "create_box 1 box bond/types 1 extra/bond/per/atom 12 extra/special/per/atom 200",
             "create_atoms 1 box", "mass 1 1.0", "reset_atoms id sort yes",
             "displace_atoms all random 0.03 0.03 0.03 4712 units box",
             "velocity all create 0.02 4713 loop geom", "bond_style zero", "bond_coeff 1 1.0",
             "pair_style zero 1.6", "pair_coeff * *", "create_bonds many all all 1 0.9 1.1",
             "special_bonds lj 0.0 0.5 0.8", "pair_style morse/spline cut 1.6",
             "pair_coeff 1 1 1.0 6.0 1.0", "pair_modify shift yes", "neighbor 0.3 bin"] + REPORT
    cpu_out, cpu = run(tmp_path, lines, "cpu")
    gpu_out, gpu = run(tmp_path, lines, "gpu", gpu=[])
    assert "Using acceleration for morse/spline:" in gpu_out
    law = Law("morse", D=1.0, a=1.0, alpha=6.0)
    side = 4 * math.sqrt(2.0)
    r = closest(cpu, side)
    h = 1e-6
    n = 2.0 * float(re.search(r"Ave neighs/atom = (\S+)", cpu_out).group(1))
    bound = (4.0 * 2.0 ** -24 * (side * abs(law.f(r + h) - law.f(r - h)) / (2 * h) + abs(law.f(r)))
             * math.sqrt(n))
    assert np.abs(gpu[:, 1:4] - cpu[:, 1:4]).max() < bound
    c, g = results(cpu_out), results(gpu_out)
    assert g["pe"] == pytest.approx(c["pe"], rel=1e-6, abs=1e-6 * abs(law.pi(1.6)))
    assert g["etotal100"] == pytest.approx(c["etotal100"], rel=1e-6)


def test_a_new_kappa_between_runs_recompiles_the_kernel(tmp_path):
    """lj with every kappa 1 (the kernel without kappa's path), then pair_coeff sets kappa 0.9
    and a second run needs the kappa kernel: the same two runs as the CPU style."""
    lines = scene("lj-wagner", "lj") + ["fix nve all nve", "thermo_modify format float %.15g",
                                        "run 50",
                                        f"pair_coeff 1 1 {laws('lj-wagner', 'lj')['1 1'].coeff()}"
                                        .replace("kappa 1.0", "kappa 0.9"),
                                        "run 50", 'print "RESULT pe $(pe:%.17g)"',
                                        "write_dump all custom forces.dump id fx fy fz "
                                        "modify sort id format float %.17g"]
    cpu_out, cpu = run(tmp_path, lines, "cpu")
    gpu_out, gpu = run(tmp_path, lines, "gpu", gpu=[])
    assert gpu_out.count("Using acceleration for lj/spline:") == 2
    assert results(gpu_out)["pe"] == pytest.approx(results(cpu_out)["pe"], rel=1e-6)
    # mixed precision: about 1e-6 of the largest force on these scenes (the bound of the first
    # test); a kernel left without kappa's path is off by some 10 % on the 1 1 pairs
    assert np.abs(gpu[:, 1:4] - cpu[:, 1:4]).max() < 1e-4 * np.abs(cpu[:, 1:4]).max()


def test_two_ranks_share_the_device_and_give_the_same_run(tmp_path):
    lines = scene("morse-wagner", "lj") + REPORT
    one, _ = run(tmp_path, lines, "one", gpu=[])
    two, f2 = run(tmp_path, lines, "two", gpu=[], nprocs=2)
    cpu_out, cpu = run(tmp_path, lines, "cpu")
    bound, _ = force_bound("morse-wagner", "lj", cpu, cpu_out)
    assert np.abs(f2[:, 1:4] - cpu[:, 1:4]).max() < bound
    r1, r2 = results(one), results(two)
    assert r2["pe"] == pytest.approx(r1["pe"], rel=1e-6)
    assert r2["etotal100"] == pytest.approx(r1["etotal100"], rel=1e-6)


def test_fix_viscous_relative_beside_the_gpu_pair(tmp_path):
    """The fix damps in its own host pass (the device kernel has no damping stage; on the CPU
    the pair's force pass sums it): the same damped run within mixed precision, units metal."""
    damp = ["fix damp all viscous/relative gamma 0.5", "fix_modify damp energy yes"]
    lines = scene("morse-cut-kappa", "metal", damp) + REPORT
    cpu_out, _ = run(tmp_path, lines, "cpu")
    gpu_out, _ = run(tmp_path, lines, "gpu", gpu=[])
    assert "damping summed in pair morse/spline's force pass" in cpu_out
    assert "damping summed in pair" not in gpu_out
    c, g = results(cpu_out), results(gpu_out)
    assert g["etotal100"] == pytest.approx(c["etotal100"], rel=1e-6)


@pytest.mark.parametrize("setting, word", [("cut 1.6 link 1.1", "link L"),
                                           ("cut 1.6 chain 2", "chain N")])
def test_link_and_chain_are_refused_on_the_gpu(tmp_path, setting, word):
    lines = scene("morse-cut-kappa", "lj")
    lines = [x.replace("pair_style morse/spline cut 1.6", f"pair_style morse/spline/gpu {setting}")
             for x in lines]
    text = lmp_error(tmp_path, ["package gpu 1 neigh no"] + lines + ["run 0"])
    assert f"Pair morse/spline/gpu: {word} is not supported on the GPU" in text
    assert "use morse/spline without the gpu suffix" in text


@pytest.mark.parametrize("style, law", [("lj", "1.0 1.0"), ("mie", "1.0 1.0 9 6")])
def test_a_singular_law_with_kappa_above_one_is_refused(tmp_path, style, law):
    """lj and mie with kappa > 1 are singular at a (1 - 1/kappa): the CPU style stops there
    with an error, which the device kernel cannot do."""
    text = lmp_error(tmp_path, ["package gpu 1 neigh no", "units lj",
                                "region box block -3 3 -3 3 -3 3", "create_box 1 box",
                                "mass 1 1.0", "create_atoms 1 single 0 0 0",
                                f"pair_style {style}/spline/gpu cut 1.5",
                                f"pair_coeff 1 1 {law} kappa 1.2", "run 0"])
    assert (f"Pair {style}/spline/gpu: kappa 1.2 > 1 for types 1 1 makes the law singular"
            in text)
    assert f"use {style}/spline without the gpu suffix (kappa <= 1 runs on the GPU)" in text


def test_fix_adapt_is_refused_under_the_gpu_pair(tmp_path):
    lines = scene("morse-cut-kappa", "lj")
    lines = [x.replace("pair_style morse/spline", "pair_style morse/spline/gpu") for x in lines]
    text = lmp_error(tmp_path, ["package gpu 1 neigh no"] + lines +
                     ["variable d equal 1.1", "fix a all adapt 1 pair morse/spline/gpu D 1 1 v_d",
                      "run 1"])
    assert "Fix adapt interface to this pair style not supported" in text


def test_gpu_style_needs_package_gpu(tmp_path):
    lines = scene("morse-cut-kappa", "lj")
    lines = [x.replace("pair_style morse/spline", "pair_style morse/spline/gpu") for x in lines]
    text = lmp_error(tmp_path, lines)
    assert "The package gpu command is required for gpu styles" in text


def test_the_gpu_plugin_file_is_built_beside_the_plugin():
    assert (Path(PLUGIN).parent / "clusterdyn_gpu.so").exists()
