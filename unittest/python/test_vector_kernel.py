"""The vectorized force kernel (src/spline_block.h, src/vector_math.h): glibc's vector exp and
pow in a `#pragma omp simd` loop, the instruction set chosen at build time
(CLUSTERDYN_SIMD_ARCH, default native).  The plugin built for a CPU without AVX-512
(unittest's clusterdyn_avx2.so, -march=x86-64-v3) gives the same forces, energies and virials
as the native build to 1e-12 on a hot block for every law, tail and mode, and holds no
AVX-512 instruction; both equal stock morse to 1e-12 (more stock comparisons:
test_pair_spline_stock.py).  Every instance of its vector stage is vectorized in both builds
(no scalar root, exp or pow: a disassembly check)."""
import os
import re
import subprocess

import numpy as np
import pytest
from conftest import AVX2_PLUGIN as AVX2
from conftest import LMP, PLUGIN

D, ALPHA, A = 1.3, 5.5, 1.0

# a hot fcc block with two atom types (the kernel's per-type path) or one (its uniform path)
BLOCK = """
plugin load {plugin}
units lj
atom_modify map array
lattice fcc {density}
region box block 0 6 0 6 0 6
create_box {ntypes} box
create_atoms 1 box
{types}
mass * 1.0
displace_atoms all random 0.06 0.06 0.06 4711 units box
velocity all create 0.5 12345 loop geom
pair_style {pair}
pair_coeff * * {coeff}
neighbor 0.3 bin
compute epa all pe/atom
compute spa all stress/atom NULL pair
thermo_style custom step pe press pxx pyy pzz pxy pxz pyz
thermo_modify format float %.17g
dump d all custom 1 forces.dump id fx fy fz c_epa c_spa[1] c_spa[2] c_spa[3] c_spa[4]
dump_modify d sort id format float %.17g
fix nve all nve
timestep 0.002
run {steps}
"""

CASES = {
    "morse cut": ("morse/spline cut 1.4", f"{D} {ALPHA} {A}"),
    "morse lagunov": ("morse/spline lagunov 1.4", f"{D} {ALPHA} {A}"),
    "morse wagner": ("morse/spline wagner", f"{D} {ALPHA} {A}"),
    "lj cut kappa": ("lj/spline cut 1.4", f"{D} {A} kappa 1.1"),
    "mie lagunov": ("mie/spline lagunov 1.4", f"{D} {A} 10 5"),
    "harmonic cut": ("harmonic/spline cut 1.2", f"{D} {ALPHA} {A}"),
    "morse link": ("morse/spline cut 1.4 link 1.05", f"{D} {ALPHA} {A}"),
    "lj chain": ("lj/spline cut 1.4 chain 3", f"{D} {A}"),
}


def run(tmp_path, plugin, pair, coeff, ntypes=1, steps=0):
    tmp_path.mkdir(exist_ok=True)
    types = "set type 1 type/fraction 2 0.5 99" if ntypes == 2 else ""
    script = BLOCK.format(plugin=plugin, density=2 ** 0.5 / A ** 3 * 0.98, ntypes=ntypes,
                          types=types, pair=pair, coeff=coeff, steps=steps)
    (tmp_path / "in.block").write_text(script)
    out = subprocess.run([LMP, "-in", "in.block", "-log", "none", "-nocite"], cwd=tmp_path,
                         capture_output=True, text=True, timeout=300,
                         env=dict(os.environ, OMP_NUM_THREADS="1"))
    assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-2000:]
    thermo = [line.split() for line in out.stdout.splitlines()
              if re.match(r"^\s+\d+\s+-?\d", line)]
    dump = open(tmp_path / "forces.dump").read().split("ITEM: ATOMS")[-1].splitlines()[1:]
    return np.array(thermo[-1][1:], float), np.array([line.split()[1:] for line in dump], float)


def assert_close(a, b, rel):
    scale = np.max(np.abs(a), axis=0)
    assert np.all(np.abs(a - b) <= rel * np.maximum(scale, 1e-300)), np.max(np.abs(a - b) / scale)


@pytest.mark.skipif(not os.path.isfile(AVX2), reason="clusterdyn_avx2.so not built")
@pytest.mark.parametrize("case", sorted(CASES))
def test_avx2_build_equals_native(tmp_path, case):
    pair, coeff = CASES[case]
    ntypes = 2 if case in ("morse cut", "lj cut kappa") else 1
    native = run(tmp_path / "native", PLUGIN, pair, coeff, ntypes)
    avx2 = run(tmp_path / "avx2", AVX2, pair, coeff, ntypes)
    assert_close(native[0], avx2[0], 1e-12)           # pe, pressure tensor
    assert_close(native[1], avx2[1], 1e-12)           # forces, per-atom energy and virial


@pytest.mark.skipif(not os.path.isfile(AVX2), reason="clusterdyn_avx2.so not built")
@pytest.mark.parametrize("plugin", [PLUGIN, AVX2], ids=["native", "avx2"])
def test_both_builds_equal_stock_morse(tmp_path, plugin):
    """Each build against LAMMPS's scalar morse on the same hot block (two atom types): the
    oracle that is not this package's code."""
    ours = run(tmp_path / "ours", plugin, *CASES["morse cut"], ntypes=2)
    stock = run(tmp_path / "stock", plugin, f"morse {1.4 * A}", f"{D} {ALPHA} {A}", ntypes=2)
    assert_close(stock[0], ours[0], 1e-12)
    assert_close(stock[1], ours[1], 1e-12)


@pytest.mark.skipif(not os.path.isfile(AVX2), reason="clusterdyn_avx2.so not built")
def test_100_steps_agree(tmp_path):
    """100 steps of the hot block with the lagunov tail: the trajectories of the two builds
    part only by round-off."""
    native = run(tmp_path / "native", PLUGIN, *CASES["morse lagunov"], steps=100)
    avx2 = run(tmp_path / "avx2", AVX2, *CASES["morse lagunov"], steps=100)
    assert_close(native[0], avx2[0], 1e-9)
    assert_close(native[1], avx2[1], 1e-9)


def instructions(path):
    return subprocess.run(["objdump", "-d", "--no-show-raw-insn", path], capture_output=True,
                          text=True, check=True).stdout


@pytest.mark.skipif(not os.path.isfile(AVX2), reason="clusterdyn_avx2.so not built")
def test_avx2_build_has_no_avx512_and_calls_vector_exp():
    code = instructions(AVX2)
    assert "%zmm" not in code
    assert "_ZGVdN4v_exp" in code            # libmvec's AVX2 exp, 4 doubles a call


def vector_stages(path):
    """The instances of the vector stage (SplineBlock::compute<Law, Tail, KAPPA, UNIFORM>,
    src/spline_block.h) in a plugin: their names and disassembled bodies."""
    code = subprocess.run(["objdump", "-d", "-C", "--no-show-raw-insn", path],
                          capture_output=True, text=True, check=True).stdout
    return {name: body for name, body in
            re.findall(r"^[0-9a-f]+ <(.*?)>:\n(.*?)(?=\n\n|\Z)", code, re.S | re.M)
            if "SplineBlock::compute<" in name and not name.endswith("@plt")}


@pytest.mark.skipif(not os.path.isfile(AVX2), reason="clusterdyn_avx2.so not built")
@pytest.mark.parametrize("plugin", [PLUGIN, AVX2], ids=["native", "avx2"])
def test_every_tail_vectorized(plugin):
    """Every instance of the vector stage (each law, tail, kappa and one or many atom types)
    computes its pairs in vector registers: no scalar square root and no call of the scalar
    exp or pow.  GCC 12 vectorizes an `if` or a `?:` of computed values in a tail only with
    AVX-512's masks; the AVX2 build had the wagner and lagunov instances scalar (24 of 36) and
    lagunov cost 1.7x the cut tail there (doc/benchmarks/bench_pair_spline.md)."""
    stages = vector_stages(plugin)
    for tail in ("CutTail", "WagnerTail", "LagunovTail"):
        assert any(tail in name for name in stages), tail
    scalar = [name for name, body in stages.items()
              if re.search(r"\bv?sqrtsd\b|<(exp|pow)@plt>", body)]
    assert not scalar, scalar
    morse = [body for name, body in stages.items() if "MorseLaw" in name]
    assert morse and all(re.search(r"_ZGV[bcde]N\d+v_exp", body) for body in morse)


def test_native_build_calls_vector_exp():
    """The native kernel calls libmvec's exp for 8 (AVX-512) or 4 (AVX2) doubles."""
    flags = open("/proc/cpuinfo").read()
    code = instructions(PLUGIN)
    if " avx512f" in flags:
        assert "_ZGVeN8v_exp" in code and "%zmm" in code
    elif " avx2" in flags:
        assert "_ZGVdN4v_exp" in code
