"""compute free/surface (the velocity of a body's free face, dust excluded): against the same
quantity built from stock LAMMPS commands (atom-style variables and compute reduce) over a
spall run, a closed form on a velocity ramp in two unit styles (with three masses: the
mass-weighted mean of the layer's atoms), serial against 2 ranks, and bad input."""
import math
import os

import numpy as np
import pytest
from conftest import PLUGIN, run_lmp, session

EXAMPLES = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "examples"))

# the rear face of the target by stock commands (examples/spall/in.spall before this compute)
STOCK = """variable inlarge atom x*(c_parts[3]==0)*(c_parts[2]>0)
compute stockrear target reduce max v_inlarge
variable stockrear equal c_stockrear
variable nearrear atom (c_parts[3]==0)&&(c_parts[2]>0)&&(x>v_stockrear-2*v_a)
variable vrear atom vx*v_nearrear
compute rearsum target reduce sum v_vrear v_nearrear
variable stockv equal c_rearsum[1]/c_rearsum[2]
variable stockn equal c_rearsum[2]"""


def test_equals_the_stock_construction_through_a_spall():
    """examples/spall/in.spall at 1.5 vd (the target spalls; the face is then the spalled
    layer's): the compute's velocity, face position and count equal the stock construction's
    at every check, before and after the spall."""
    with session("-var", "ratio", "1.5", "-var", "records", "0", "-var", "target", "12",
                 "-var", "flyer", "6") as lmp:
        lmp.file(os.path.join(EXAMPLES, "spall", "in.spall"))
        lmp.commands_string(STOCK)
        seen = 0
        for _ in range(8):
            lmp.command("run 100 post no")
            got = [lmp.extract_variable(n) for n in ("vfree", "rear")]
            assert got[0] == pytest.approx(lmp.extract_variable("stockv"), rel=1e-12, abs=1e-9)
            assert got[1] == lmp.extract_variable("stockrear")
            seen += got[0] != 0.0
        assert lmp.extract_variable("large") >= 2 and seen > 0


RAMP = """units {units}
boundary p p p
lattice sc {a}
region box block -2 14 0 4 0 4
create_box 1 box
region body block 1 10.9 INF INF INF INF
create_atoms 1 region body
create_atoms 1 single 12 1 1
mass 1 {m}
pair_style morse/spline cut 1.2
pair_coeff 1 1 {D} {alpha} {a}
neighbor {skin} bin
group body region body
variable ramp atom {k}*x
velocity all set v_ramp 0 0 units box
compute dust all dust
compute face all free/surface dust {depth}
compute front all free/surface dust {depth} face front
compute side all free/surface dust {depth} axis y
thermo_style custom step c_face[*] c_front[*] c_side[*]
thermo_modify format float %.15g
run 0
"""


@pytest.mark.parametrize("units", ["lj", "si"])
def test_velocity_ramp_closed_form(units):
    """A 10 x 4 x 4 sc block from x = a with vx = k x and one lone atom beyond its rear
    (dust): the rear face (depth 1.5 a: the last two planes, x = 9a and 10a) stands at 10 a
    and moves at k 9.5 a, the front face (x = a and 2a) stands at a (not at 0, where its sign
    would not show) and moves at k 1.5 a, the face along y at 0 (vx only); 32 atoms each."""
    a, m, D = (1.0, 1.0, 1.0) if units == "lj" else (1e-5, 2.338e-12, 2.46e-6)
    k = 0.01 if units == "lj" else 1.0e7
    with session() as lmp:
        lmp.commands_string(RAMP.format(units=units, a=a, m=m, D=D, alpha=3.76 / a,
                                        skin=0.2 * a, k=k, depth=1.5 * a))
        face = [lmp.extract_compute("face", 0, 1)[i] for i in range(3)]
        front = [lmp.extract_compute("front", 0, 1)[i] for i in range(3)]
        side = [lmp.extract_compute("side", 0, 1)[i] for i in range(3)]
    assert face == pytest.approx([k * 9.5 * a, 10 * a, 32], rel=1e-12)
    assert front == pytest.approx([k * 1.5 * a, a, 32], rel=1e-12)
    assert side[0] == 0.0 and side[2] == 80    # the planes y = 2a and 3a: 10 x 2 x 4 atoms


@pytest.mark.parametrize("masses", ["per type", "per atom"])
@pytest.mark.parametrize("units", ["lj", "si"])
def test_the_face_velocity_is_mass_weighted(units, masses):
    """The velocity ramp vx = k x with three masses (m, 1.5 m and 2.5 m, types at random, or the
    same per atom through atom_style sphere's masses): the face layer (the planes x = 9a and 10a,
    32 atoms) moves at the mass-weighted mean sum(m vx) / sum(m) of its atoms, computed here
    from the atoms (not the plain mean k 9.5 a that equal masses give)."""
    a, m, D = (1.0, 1.0, 1.0) if units == "lj" else (1e-5, 2.338e-12, 2.46e-6)
    k = 0.01 if units == "lj" else 1.0e7
    script = RAMP.format(units=units, a=a, m=m, D=D, alpha=3.76 / a, skin=0.2 * a, k=k,
                         depth=1.5 * a)
    lines = ["set type 1 type/fraction 2 0.4 881", "set type 1 type/fraction 3 0.4 882"] + [
        f"set type {t} mass {f * m!r}" if masses == "per atom" else f"mass {t} {f * m!r}"
        for t, f in ((1, 1.0), (2, 1.5), (3, 2.5))]
    script = script.replace("create_box 1 box", "create_box 3 box").replace(
        f"mass 1 {m}\n", "\n".join(lines) + "\n").replace("pair_coeff 1 1", "pair_coeff * *")
    if masses == "per atom":
        script = "atom_style sphere\n" + script
    with session() as lmp:
        lmp.commands_string(script)
        face = [lmp.extract_compute("face", 0, 1)[i] for i in range(3)]
        x = np.array(lmp.gather_atoms("x", 1, 3)).reshape(-1, 3)
        vx = np.array(lmp.gather_atoms("v", 1, 3)).reshape(-1, 3)[:, 0]
        t = np.array(lmp.gather_atoms("type", 0, 1))
    mass = m * np.array([0.0, 1.0, 1.5, 2.5])[t]
    layer = (x[:, 0] > 8.5 * a) & (x[:, 0] < 11 * a)
    assert layer.sum() == 32 and len(set(t[layer])) == 3
    want = np.sum(mass[layer] * vx[layer]) / np.sum(mass[layer])
    assert abs(want - k * 9.5 * a) > 1e-3 * k * a    # the weights matter here
    assert face == pytest.approx([want, 10 * a, 32], rel=1e-12)


def thermo_row(out):
    return [float(x) for x in out.split("c_face[1]")[1].splitlines()[1].split()]


def test_two_ranks_give_the_serial_values(tmp_path):
    """The same numbers on 2 ranks (to round-off: the layer's sums are added in another
    order), the counts exactly."""
    script = f"plugin load {PLUGIN}\n" + RAMP.format(units="lj", a=1.0, m=1.0, D=1.0,
                                                     alpha=3.76, skin=0.2, k=0.01, depth=1.5)
    serial = thermo_row(run_lmp(tmp_path, script))
    parallel = thermo_row(run_lmp(tmp_path, script, nprocs=2))
    assert len(serial) == 13 and parallel == pytest.approx(serial, rel=1e-12, abs=1e-14)
    assert parallel[3::4] == serial[3::4]


# a block of 10 planes (sc, 4 x 4 across) and a piece of 2 planes beyond its rear, apart
PIECE = """units {units}
boundary p p p
lattice sc {a}
region box block -2 18 0 4 0 4
create_box 1 box
region body block 0 9.9 INF INF INF INF
region piece block 12 13.9 INF INF INF INF
create_atoms 1 region body
create_atoms 1 region piece
mass 1 {m}
pair_style morse/spline cut 1.2
pair_coeff 1 1 {D} {alpha} {a}
neighbor {skin} bin
compute dust all dust maxsize 40
compute face all free/surface dust {depth}
compute body all free/surface dust {depth} minsize 33
compute layer all free/surface dust {depth} minsize 32
thermo_style custom step c_face[*] c_body[*] c_layer[*]
"""


@pytest.mark.parametrize("units", ["lj", "si"])
def test_minsize_names_the_pieces_of_the_body(units):
    """The piece of 2 planes (32 atoms) is dust by maxsize 40: the face is the block's
    (x = 9a); with minsize 32 the piece is the body's outermost part (x = 13a), with minsize
    33 it is not; the dust flags are not read with minsize."""
    a, m, D = (1.0, 1.0, 1.0) if units == "lj" else (1e-5, 2.338e-12, 2.46e-6)
    with session() as lmp:
        lmp.commands_string(PIECE.format(units=units, a=a, m=m, D=D, alpha=3.76 / a,
                                         skin=0.2 * a, depth=1.5 * a))
        lmp.command("velocity all set 0.0 0.0 0.0")
        lmp.command("run 0")
        got = {c: [lmp.extract_compute(c, 0, 1)[i] for i in range(4)]
               for c in ("face", "body", "layer")}
    assert got["face"] == pytest.approx([0.0, 9 * a, 32, 0], rel=1e-12)
    assert got["body"] == pytest.approx([0.0, 9 * a, 32, 0], rel=1e-12)
    assert got["layer"] == pytest.approx([0.0, 13 * a, 32, 0], rel=1e-12)


@pytest.mark.parametrize("units", ["lj", "si"])
def test_jumps_count_a_face_that_leaves_its_path(units):
    """A block and its outer piece moving together at V (t in the compute's time): no jump
    over 200 steps evaluated every 10 (the face moves V dt, the check allows depth); the piece
    deleted: the face jumps back 4 a > depth, counted once however often it is evaluated;
    a face gone (every atom of the group deleted) is a jump too."""
    a, m, D = (1.0, 1.0, 1.0) if units == "lj" else (1e-5, 2.338e-12, 2.46e-6)
    tau = math.sqrt(m * a * a / D)
    with session() as lmp:
        lmp.commands_string(PIECE.format(units=units, a=a, m=m, D=D, alpha=3.76 / a,
                                         skin=0.2 * a, depth=1.5 * a))
        lmp.commands_list([f"velocity all set {0.5 * a / tau!r} 0.0 0.0 units box",
                           "fix nve all nve", f"timestep {0.01 * tau!r}", "thermo 10",
                           "run 200"])
        layer = lambda: [lmp.extract_compute("layer", 0, 1)[i] for i in range(4)]
        moved = layer()
        lmp.commands_list(["delete_atoms region piece", "run 10"])
        after = layer()
        lmp.commands_list(["run 10", "run 0"])
        still = layer()
        lmp.commands_list(["delete_atoms group all", "run 1"])
        gone = layer()
    assert moved[0] == pytest.approx(0.5 * a / tau, rel=1e-9)
    assert moved[1] == pytest.approx(13 * a + 200 * 0.01 * 0.5 * a, rel=1e-9)
    assert moved[3] == 0
    assert after[1] == pytest.approx(9 * a + 210 * 0.01 * 0.5 * a, rel=1e-9) and after[3] == 1
    assert still[3] == 1 and gone[:3] == [0.0, 0.0, 0.0] and gone[3] == 2


@pytest.mark.parametrize("units", ["lj", "si"])
def test_an_accelerating_face_is_no_jump(units):
    """The block and its piece pushed by a uniform force (acceleration 0.5 a / tau^2),
    evaluated every 3 tau: the face moves by the mean of its two velocities times the interval
    exactly; its new velocity alone would put it 0.5 g T^2 = 2.25 a off, beyond the depth 1.5 a.
    No jump, and the face where x0 + g t^2 / 2 puts it."""
    a, m, D = (1.0, 1.0, 1.0) if units == "lj" else (1e-5, 2.338e-12, 2.46e-6)
    tau = math.sqrt(m * a * a / D)
    g = 0.5 * a / tau ** 2
    with session() as lmp:
        lmp.commands_string(PIECE.replace("block -2 18", "block -2 118").format(
            units=units, a=a, m=m, D=D, alpha=3.76 / a, skin=0.2 * a, depth=1.5 * a))
        lmp.commands_list(["velocity all set 0.0 0.0 0.0", "fix nve all nve",
                           f"fix push all addforce {m * g!r} 0.0 0.0",
                           f"timestep {0.01 * tau!r}", "thermo 300", "run 900"])
        layer = [lmp.extract_compute("layer", 0, 1)[i] for i in range(4)]
    t = 9.0 * tau
    # velocity Verlet is exact under a constant force: to round-off, not 1e-6
    assert layer[0] == pytest.approx(g * t, rel=1e-10)
    assert layer[1] == pytest.approx(13 * a + 0.5 * g * t * t, rel=1e-10)
    assert layer[3] == 0


@pytest.mark.parametrize("step", [0, 1000])
def test_a_reset_clock_is_no_jump(step):
    """reset_timestep (back to 0, or forward) between evaluations of a moving block: the
    first evaluation after it compares nothing, the following ones follow the face again."""
    with session() as lmp:
        lmp.commands_string(PIECE.format(units="lj", a=1.0, m=1.0, D=1.0, alpha=3.76,
                                         skin=0.2, depth=1.5))
        lmp.commands_list(["group outer region piece",
                           "velocity all set 0.5 0.0 0.0 units box", "fix nve all nve",
                           "timestep 0.01", "thermo 10", "run 400", f"reset_timestep {step}",
                           "run 10", "run 100"])
        assert lmp.extract_compute("layer", 0, 1)[3] == 0
        lmp.commands_list(["delete_atoms group outer", "run 10"])
        assert lmp.extract_compute("layer", 0, 1)[3] == 1


@pytest.mark.parametrize("args,message", [
    ("", "expected compute ID group free/surface dust-ID depth"),
    ("nosuch 1.0", "no compute with ID 'nosuch'"),
    ("ke 1.0", "compute 'ke' is ke, not a compute dust"),
    ("dust 0", "depth"),
    ("dust -1", "depth"),
    ("dust 1.0 axis w", "axis must be x, y or z"),
    ("dust 1.0 face back", "face must be rear or front"),
    ("dust 1.0 side rear", "unknown keyword 'side'"),
    ("dust 1.0 axis", "axis needs a value"),
    ("dust 1.0 minsize 0", "minsize must be >= 1"),
    ("dust 1.0 minsize 2.5", "minsize must be an integer"),
    ("dust 1.0 minsize 8 minsize 9", "keyword minsize given twice"),
    ("dust 1.0 face rear axis y face front", "keyword face given twice"),
    ("dust 1.0 minsize", "minsize needs a value"),
])
def test_bad_arguments(args, message):
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 4 0 4 0 4", "create_box 1 box",
                           "mass 1 1.0", "pair_style morse/spline cut 1.2",
                           "pair_coeff 1 1 1.0 3.76 1.0", "compute dust all dust",
                           "compute ke all ke"])
        with pytest.raises(Exception, match=message):
            lmp.commands_list([f"compute f all free/surface {args}",
                               "thermo_style custom step c_f[1]", "run 0"])
