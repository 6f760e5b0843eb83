"""pair_style mca with a shock equation of state (doc/pair_mca.rst "Shock equation of state"):
aluminium 6061-T6 from handbook data (rho0 2703 kg/m^3, c0 5350 m/s, s 1.34, Gamma0 2.0, G 26
GPa, Y 0.29 GPa; Marsh, LASL Shock Hugoniot Data 1980) against closed forms, in units si and
metal:
- a piston driven at up into elements at rest: the shock runs at us = c0 + s up (3 %), the
  piston's stress is the Rankine-Hugoniot rho0 us up of the measured us (3 %), the shocked
  elements' specific energy is up^2 / 2 (3 %), the energy the elements hold is the piston's work
  (1.5 %);
- below the plastic shock an elastic precursor runs at c_L = sqrt((K + 4G/3)/rho0) (2 %) with
  the Hugoniot elastic limit Y (1 - nu)/(1 - 2 nu) as its stress rho0 c_L u (10 %);
- an impact without fracture keeps its energy (kinetic + rotational + potential, the elements'
  internal energy included) within 1 %; 1 and 2 ranks agree; a restart continues exactly;
- bad input is refused with the argument named;
- fix deform to V/V0 = 0.8: every element's bulk viscosity is rho0/J L D (b1 c0 + b2^2 L D)
  with D from the box's schedule, exact (si; metal within its constants);
- the hourglass mode kicked over one step: pe(2H) - pe(H) is the spring's energy S b e_hg^2 / 2,
  b the series of the halves 2 H (K + 4G/3 + 2|p|) / R, at rest and at V/V0 = 0.8 (p on the
  Hugoniot), one material and two (H = 1, 2.5), to 1e-6 (si, metal);
- examples/mca-shock reduced: its piston holds the work and pushes rho0 us up (aluminium,
  copper), its plate spalls with the free surface at v, its smd/tlsph reference runs and spalls;
  at 1000 m/s the plate's pull-back at the default step is within 4.5 % of a step four times
  shorter (below it, as documented) and its peak within 0.1 %; the plugin built for AVX2 gives
  the native build's plate record to 1e-9.
"""
import math
import os
import re

import numpy as np
import pytest

from conftest import AVX2_PLUGIN, PLUGIN, lmp_error, run_lmp, session, thermo_rows

RHO0, C0, S, GAMMA0, G, Y = 2703.0, 5350.0, 1.34, 2.0, 26.0e9, 0.29e9
K = RHO0 * C0 ** 2
CL = math.sqrt((K + 4.0 * G / 3.0) / RHO0)
D = 1.0e-5                                  # element diameter (m)
CELL = D * math.sqrt(2.0)
PHI = math.pi / math.sqrt(18.0)
# per unit style: metres, m/s, kg/m^3, Pa, kg -> the style's length, velocity, density,
# pressure, mass (metal: Angstrom, Angstrom/ps, g/mol/Angstrom^3, bar, g/mol)
UNITS = {"si": (1.0, 1.0, 1.0, 1.0, 1.0),
         "metal": (1.0e10, 1.0e-2, 1.0e-3 / 1.66053906660, 1.0e-5, 6.02214076e26)}


def material(units, yield_stress=Y, extra=""):
    L, V, R, P, _ = UNITS[units]
    plastic = f"yield {yield_stress * P}" if yield_stress > 0 else ""
    return (f"shock {RHO0 * R} {C0 * V} {S} {GAMMA0} shear {G * P} {plastic} {extra}",
            RHO0 * R / PHI)


def plate_setup(units, ncell, ntrans=3, boundary="s p p", extra=""):
    L, V, R, P, _ = UNITS[units]
    coeff, density = material(units, extra=extra)
    return [f"units {units}", "atom_style sphere", "atom_modify map array", "comm_modify vel yes",
            f"boundary {boundary}", f"lattice fcc {CELL * L}",
            f"region box block 0 {ncell} 0 {ntrans} 0 {ntrans}", "create_box 1 box",
            "create_atoms 1 box", f"neighbor {0.25 * D * L} bin",
            "neigh_modify every 1 delay 0 check yes", f"set group all diameter {D * L}",
            f"pair_style mca fraction {PHI} tolerance 0.02", f"pair_coeff 1 1 {coeff}",
            f"set group all density {density}", f"timestep {0.1 * D * L / (CL * V)}"]


def layers(lmp, length, L):
    """Mean vx (in the style's units) per half cell along x (metres; L: the style's length per
    metre)."""
    n = lmp.extract_global("nlocal")
    x = lmp.numpy.extract_atom("x")[:n, 0] / L
    v = lmp.numpy.extract_atom("v")[:n, 0]
    edges = np.arange(0.0, length + CELL / 2, CELL / 2)
    idx = np.digitize(x, edges)
    centres = 0.5 * (edges[1:] + edges[:-1])
    prof = np.array([v[idx == k].mean() if np.any(idx == k) else 0.0
                     for k in range(1, len(edges))])
    return centres, prof


def front(centres, prof, level):
    """The foremost place where the profile falls through level (interpolated)."""
    k = np.where(prof > level)[0].max()
    return centres[k] + (centres[k + 1] - centres[k]) * (prof[k] - level) / (prof[k] - prof[k + 1])


def piston(units, up, ncell=50):
    """Drive a piston (4 planes moved at up) into the target; measure at 30 % and 75 % of the
    transit: the front's speed, the piston's stress, the shocked elements' specific energy,
    the energy held against the piston's work.  SI values."""
    L, V, _, P, _ = UNITS[units]
    T = L / V                                   # the style's time per second
    us_h = C0 + S * up
    with session() as lmp:
        lmp.commands_list(plate_setup(units, ncell))
        lmp.commands_list([
            "region pist block INF 1.9 INF INF INF INF", "group piston region pist",
            "group target subtract all piston", "fix 1 target nve/sphere",
            f"fix 2 piston move linear {up * V} 0 0 units box",
            "compute fp piston reduce sum fx", "compute kp piston ke", "compute pe all pe/atom",
            "compute erot target erotate/sphere",
            f"variable pw equal -c_fp*{up * V}", "fix work all ave/time 1 1 1 v_pw ave running",
            "thermo_style custom step pe ke c_kp c_erot", "run 0 post no"])
        dt = lmp.extract_global("dt") / T
        length = ncell * CELL
        n1, n2 = int(0.3 * length / us_h / dt), int(0.75 * length / us_h / dt)
        lmp.command(f"run {n1} post no")
        x1 = front(*layers(lmp, length, L), up * V / 2)
        stress = []
        for _ in range(10):
            lmp.command(f"run {(n2 - n1) // 10} post no")
            stress.append(-lmp.extract_compute("fp", 0, 0) / (3 * CELL * L) ** 2
                          * lmp.extract_global("nktv2p"))
        steps = n1 + 10 * ((n2 - n1) // 10)
        x2 = front(*layers(lmp, length, L), up * V / 2)
        lo, hi = (up * steps * dt + 4 * CELL) * L, (x2 - 4 * CELL) * L
        lmp.commands_list([
            f"variable sh atom x>{lo}&&x<{hi}", "group shocked variable sh",
            "compute pes shocked reduce sum c_pe", "variable ms equal mass(shocked)",
            "thermo_style custom step pe ke c_kp c_erot c_pes v_ms", "run 0 post no"])
        work = lmp.extract_fix("work", 0, 0) * steps * lmp.extract_global("dt")
        held = (lmp.get_thermo("pe") + lmp.get_thermo("ke") + lmp.extract_compute("erot", 0, 0)
                - lmp.extract_compute("kp", 0, 0))
        mvv2e = lmp.extract_global("mvv2e")
        energy = (lmp.extract_compute("pes", 0, 0) / lmp.extract_variable("ms") / mvv2e
                  / V ** 2)
    return dict(us=(x2 - x1) / ((steps - n1) * dt), us_h=us_h,
                stress=np.mean(stress) / P, energy=energy, held=held / work)


@pytest.mark.parametrize("units,up", [("si", 200.0), ("si", 1000.0), ("si", 2000.0),
                                      ("metal", 1000.0)])
def test_piston_gives_the_hugoniot_and_the_rankine_hugoniot_jump(units, up):
    r = piston(units, up)
    assert r["us"] == pytest.approx(r["us_h"], rel=0.03)
    assert r["stress"] == pytest.approx(RHO0 * r["us"] * up, rel=0.03)
    assert r["held"] == pytest.approx(1.0, abs=0.015)
    if up >= 500.0:    # a single shock (at 200 m/s an elastic precursor runs ahead)
        assert r["energy"] == pytest.approx(0.5 * up ** 2, rel=0.03)


def test_precursor_runs_at_the_longitudinal_speed_with_the_hugoniot_elastic_limit():
    up, ncell = 100.0, 80
    nu = (3 * K - 2 * G) / (2 * (3 * K + G))
    hel = Y * (1 - nu) / (1 - 2 * nu)
    ue = hel / (RHO0 * CL)
    length = ncell * CELL
    with session() as lmp:
        lmp.commands_list(plate_setup("si", ncell))
        lmp.commands_list([
            "region pist block INF 1.9 INF INF INF INF", "group piston region pist",
            "group target subtract all piston", "fix 1 target nve/sphere",
            f"fix 2 piston move linear {up} 0 0 units box", "run 0 post no"])
        dt = lmp.extract_global("dt")
        n1, n2 = int(0.35 * length / CL / dt), int(0.85 * length / CL / dt)
        lmp.command(f"run {n1} post no")
        x1 = front(*layers(lmp, length, 1.0), ue / 2)
        lmp.command(f"run {n2 - n1} post no")
        centres, prof = layers(lmp, length, 1.0)
        x2 = front(centres, prof, ue / 2)
        plastic = front(centres, prof, (up + ue) / 2)
    assert (x2 - x1) / ((n2 - n1) * dt) == pytest.approx(CL, rel=0.02)
    between = (centres > plastic + 0.25 * (x2 - plastic)) & (centres < x2 - 0.25 * (x2 - plastic))
    assert between.sum() >= 4
    assert RHO0 * CL * prof[between].mean() == pytest.approx(hel, rel=0.10)


IMPACT = """plugin load {plugin}
{setup}
region fly block INF 9.9 INF INF INF INF
group flyer region fly
velocity flyer set {v} 0 0 units box
fix 1 all nve/sphere
compute erot all erotate/sphere
variable e equal etotal+c_erot
thermo_style custom step ke pe c_erot v_e
thermo_modify format float %.15g
thermo 100
"""


def impact_script(units="si", v=500.0, extra="", dt_share=1.0, elastic=False):
    L, V, _, P, _ = UNITS[units]
    setup = plate_setup(units, 30, boundary="s p p", extra=extra)
    if elastic:
        setup = [c.replace(f"yield {Y * P}", "") for c in setup]
    setup = [f"timestep {0.1 * dt_share * D * L / (CL * V)}" if c.startswith("timestep") else c
             for c in setup]
    return IMPACT.format(plugin=PLUGIN, setup="\n".join(setup), v=v * V)


@pytest.mark.parametrize("units,elastic", [("si", True), ("si", False), ("metal", False)])
def test_an_impact_without_fracture_keeps_its_energy(tmp_path, units, elastic):
    """Kinetic + rotational + pe (with the elements' heat) at the default step 0.1 d / c_L
    within 0.03 % of the impact's energy, and closer at half the step: elastic as dt^2 (a
    quarter, within 0.35), yielding at least by 0.7.  Measured: elastic 0.010 % (0.0026 % at
    half the step), yielding 0.0080 % (0.0051 %: the largest error is the first 100 steps',
    where the elements first yield, first order; later second order).  Before: 0.032 % and
    0.069 % (the links' tangential energy |tau|^2 / (2a), the many-body term's lag behind the
    plastic return and the plastic heat in the next step's old pressure left out); before
    the trapezoid rule of the plastic work and the hourglass spring's energy as its work, 0.53 %
    and 2.0 %."""
    errors, last = [], []
    for share in (1.0, 0.5):
        out = run_lmp(tmp_path, impact_script(units, dt_share=share, elastic=elastic)
                      + f"thermo {int(100 / share)}\nrun {int(1200 / share)}\n")
        rows = thermo_rows(out)
        e0 = rows[0, 4]
        assert rows[0, 1] == pytest.approx(e0)             # all kinetic at the start
        assert rows[:, 2].max() > 0.3 * e0                 # and much of it went into the elements
        errors.append(np.abs(rows[:, 4] - e0).max() / e0)
        last.append(abs(rows[-1, 4] - e0) / e0)
    assert errors[0] < 3e-4, errors
    assert errors[1] < (0.35 if elastic else 0.7) * errors[0], errors
    # after the elements first yield, second order: the error at the end falls to a third
    # (measured 5.1e-5 and 1.6e-5 yielding; 1.4e-5 and 1.7e-5 while the next step's old
    # pressure took the plastic heat its forces had not)
    assert last[1] < 0.5 * last[0], last


def final_state(path, by_place=False):
    """Rows id x y z vx vy vz sorted by id, or by lattice site (y, z, then x: create_atoms
    numbers the elements otherwise on 2 ranks; uniaxial strain keeps y and z, up to the
    periodic image)."""
    rows = np.array([l.split() for l in path.read_text().splitlines()[9:]], dtype=float)
    if by_place:
        width = round(3 * CELL / 1e-7)
        y, z = (np.round(rows[:, k] / 1e-7) % width for k in (2, 3))
        order = np.lexsort((rows[:, 1], z, y))
        return np.column_stack((rows[order][:, 1], rows[order][:, 4:]))
    return rows[np.argsort(rows[:, 0])]


def test_two_ranks_and_a_restart_give_the_same_impact(tmp_path):
    dump = "write_dump all custom {name} id x y z vx vy vz modify sort id format float %.17g\n"
    run_lmp(tmp_path, impact_script() + "run 300\n" + dump.format(name="serial.dump"))
    run_lmp(tmp_path, impact_script() + "run 300\n" + dump.format(name="mpi.dump"), nprocs=2,
            name="in.mpi")
    run_lmp(tmp_path, impact_script() + "run 150\nwrite_restart half.restart\nrun 150\n"
            + dump.format(name="straight.dump"), name="in.straight")
    run_lmp(tmp_path, f"plugin load {PLUGIN}\nread_restart half.restart\n"
            "comm_modify vel yes\nneighbor 2.5e-6 bin\nneigh_modify every 1 delay 0 check yes\n"
            "fix 1 all nve/sphere\nrun 150\n" + dump.format(name="restarted.dump"),
            name="in.restarted")
    serial = final_state(tmp_path / "serial.dump", by_place=True)
    mpi = final_state(tmp_path / "mpi.dump", by_place=True)
    assert np.abs(mpi[:, 0] - serial[:, 0]).max() <= 1e-9 * np.abs(serial[:, 0]).max()
    assert np.abs(mpi[:, 1:] - serial[:, 1:]).max() <= 1e-9 * np.abs(serial[:, 1]).max()
    straight = final_state(tmp_path / "straight.dump")
    restarted = final_state(tmp_path / "restarted.dump")
    assert np.array_equal(straight, restarted)
    assert np.abs(straight[:, 4]).max() > 100.0    # the impact moves them


@pytest.mark.parametrize("coeff,message", [
    ("shock 2703 5350 1.34 2.0 bulk 7e10 shear 26e9", r"shock gives the bulk modulus"),
    ("shock 2703 5350 1.34 2.0", r"shock needs shear G"),
    ("shock 2703 5350 1.34", r"shock needs 4 values"),
    ("shock 2703 -5350 1.34 2.0 shear 26e9", r"c0"),
    ("shock 2703 5350 12 2.0 shear 26e9", r"s of 12 is not the slope"),
    ("shock 2703 5350 1.34 -2 shear 26e9", r"Gamma0"),
    ("bulk 7e10 shear 26e9 bulk_viscosity 0.06 1.2", r"bulk_viscosity needs shock"),
    ("bulk 7e10 shear 26e9 hourglass 1", r"hourglass needs shock"),
    ("shock 2703 5350 1.34 2.0 shear 26e9 bulk_viscosity -1 1.2", r"b1"),
])
def test_bad_shock_input_is_refused_naming_it(coeff, message):
    assert_coeff_refused(coeff, message)


def assert_coeff_refused(coeff, message):
    """pair_coeff 1 1 coeff on plate_setup's box stops with an error matching message."""
    setup = plate_setup("si", 3)
    setup = setup[:setup.index(next(c for c in setup if c.startswith("pair_coeff")))]
    with session() as lmp:
        lmp.commands_list(setup)
        with pytest.raises(Exception, match=message):
            lmp.command(f"pair_coeff 1 1 {coeff}")


@pytest.mark.parametrize("change,message", [
    ("set group all density 1000.0", r"density 740.48 \(mass / element volume\), not"),
    ("pair_style mca fraction 0.74048 manybody no", r"needs the many-body term"),
])
def test_inconsistent_shock_setups_stop_with_an_error(change, message):
    with session() as lmp:
        lmp.commands_list(plate_setup("si", 3))
        if change.startswith("pair_style"):
            coeff = material("si")[0]
            lmp.commands_list([change, f"pair_coeff 1 1 {coeff}"])
        else:
            lmp.command(change)
        lmp.command("fix 1 all nve/sphere")
        with pytest.raises(Exception, match=message):
            lmp.command("run 1 post no")


def test_minimize_is_refused_with_the_shock_law():
    with session() as lmp:
        lmp.commands_list(plate_setup("si", 3))
        with pytest.raises(Exception, match=r"shock equation of state follows their volume through a run"):
            lmp.command("minimize 0 0 10 10")


EXAMPLE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "examples",
                                       "mca-shock"))


def example(tmp_path, name, plugin=PLUGIN, **var):
    """An input of examples/mca-shock run in tmp_path with the plugin under test (or plugin)."""
    text = open(os.path.join(EXAMPLE, name)).read().replace("clusterdynplugin.so", plugin)
    args = [a for k, x in dict(here=EXAMPLE + "/", **var).items() for a in ("-var", k, str(x))]
    return run_lmp(tmp_path, text, name=name, args=args)


@pytest.mark.parametrize("metal,up,us", [("al", 1000.0, 5350.0 + 1.34 * 1000.0),
                                         ("cu", 500.0, 3940.0 + 1.49 * 500.0)])
def test_example_piston_holds_the_work_and_pushes_rho0_us_up(tmp_path, metal, up, us):
    out = example(tmp_path, "in.piston", metal=metal, up=up, length=30)
    stress = float(re.search(r"piston stress (\S+) Pa", out).group(1))
    held = float(re.search(r"piston work (\S+)", out).group(1))
    rho = {"al": 2703.0, "cu": 8930.0}[metal]
    assert stress == pytest.approx(rho * us * up, rel=0.03)
    assert held == pytest.approx(1.0, abs=0.015)


def test_example_plate_spalls_and_its_free_surface_flies_at_v(tmp_path):
    out = example(tmp_path, "in.plate", metal="al", v=400, d=1.0e-5, flyer=5, target=10, cells=3)
    assert re.search(r"large fragments of the target: 2", out)
    t, u = np.loadtxt(tmp_path / "plate.visar", usecols=(1, 2), unpack=True)
    assert u.max() == pytest.approx(400.0, rel=0.05)
    assert u[-1] < 0.98 * u.max()    # the pull-back and the spall signal's ringing


@pytest.mark.skipif(not os.path.isfile(AVX2_PLUGIN), reason="clusterdyn_avx2.so not built")
def test_example_plate_is_the_same_with_the_passes_built_for_avx2(tmp_path):
    """pair mca's passes compiled for this machine (the plugin under test, CLUSTERDYN_SIMD_ARCH
    native) and for AVX2 (clusterdyn_avx2.so), both without fused multiply-adds: the reduced
    plate's free-surface record agrees to round-off and the same fragments fly (doc/Build.rst)."""
    records, fragments = [], []
    for tag, plugin in (("native", PLUGIN), ("avx2", AVX2_PLUGIN)):
        folder = tmp_path / tag
        folder.mkdir()
        out = example(folder, "in.plate", plugin=plugin, metal="al", v=400, d=1.0e-5, flyer=5,
                      target=10, cells=3)
        records.append(np.loadtxt(folder / "plate.visar", usecols=(1, 2)))
        fragments.append(re.search(r"large fragments of the target: (\d+)", out).group(1))
    assert records[0].shape == records[1].shape and fragments[0] == fragments[1] == "2"
    assert np.abs(records[0][:, 1] - records[1][:, 1]).max() <= 1e-9 * np.abs(records[0][:, 1]).max()


def pull_back(record):
    """The peak of a free-surface record and its drop dU to the first minimum after it (the
    spall signal's start)."""
    u = np.loadtxt(record, usecols=2)
    k = int(np.argmax(u))
    j = k + int(np.argmax(u[k:] < 0.95 * u[k]))
    while j + 1 < len(u) and u[j + 1] <= u[j]:
        j += 1
    return u[k], u[k] - u[j]


def test_example_plate_keeps_its_reading_at_the_default_step_as_documented(tmp_path):
    """doc/accuracy_vs_cost.rst, "The time step of the shock law's elements": at 1000 m/s the
    default step theta 0.1 reads the pull-back 2-3 % below the finest steps' (10 um elements;
    theta 0.0125 and 0.025 agree within 0.5 %) and the peak within 0.1 %; the finer step is the
    oracle (a half-thickness plate, as above: dU 206.2 m/s at 0.1, 212.8 at 0.025, 213.9 at
    0.0125 when this was written)."""
    got = {}
    for theta in (0.025, 0.1):
        folder = tmp_path / f"theta{theta}"
        folder.mkdir()
        example(folder, "in.plate", metal="al", v=1000, d=1.0e-5, flyer=5, target=10, cells=3,
                theta=theta, records=800)
        got[theta] = pull_back(folder / "plate.visar")
    (peak_fine, du_fine), (peak, du) = got[0.025], got[0.1]
    assert peak == pytest.approx(peak_fine, rel=1e-3)
    assert du == pytest.approx(du_fine, rel=0.045)
    assert du < du_fine    # the step's error has the documented sign: a shallower pull-back


def test_example_plate_takes_a_mean_tension_threshold_as_pyko_does(tmp_path):
    """-var fracture pressure: the card's spall strength as a threshold on the mean tension (the
    kinetics with m = 0.01, which the summary shows: S at 1e6 /s, 1.023 S at ten times the rate);
    an unknown fracture is refused naming the three."""
    out = example(tmp_path, "in.plate", metal="al", v=400, d=1.0e-5, flyer=5, target=10, cells=3,
                  fracture="pressure")
    line = next(x for x in out.splitlines() if "spall kinetics:" in x)
    words = re.search(r"spall kinetics: (\S+) at the strain rate \S+ per time unit \((\S+) /s\), "
                      r"m (\S+): (\S+) at ten times the rate", line).groups()
    s, per_second, m, tenfold = (float(w) for w in words)
    assert (s, per_second, m) == (pytest.approx(1.2e9), pytest.approx(1.0e6), 0.01)
    assert tenfold == pytest.approx(1.2e9 * 10 ** 0.01, rel=1e-5)
    assert re.search(r"large fragments of the target: 2", out)
    text = open(os.path.join(EXAMPLE, "in.plate")).read().replace("clusterdynplugin.so", PLUGIN)
    bad = lmp_error(tmp_path, [f"variable here index {EXAMPLE}/", "variable fracture index brittle"]
                    + text.splitlines())
    assert "-var fracture brittle: give kinetics" in bad and "or pressure" in bad


def test_example_tlsph_reference_runs_and_spalls(tmp_path):
    out = example(tmp_path, "in.tlsph", metal="al", v=400, failure="pairwise", bodies=1,
                  across=3, flyer=5, target=10, out="tlsph")
    cracked = int(re.search(r"lost more than half of their partners: (\d+)", out).group(1))
    assert cracked > 0
    t, u = np.loadtxt(tmp_path / "tlsph.visar", usecols=(1, 2), unpack=True)
    assert u.max() == pytest.approx(400.0, rel=0.08)


def two_types(first, second, fraction=0.0):
    """The plate of plate_setup("si", 6) with two element types (the second a share of the
    first's elements), struck at 500 m/s from its first 3 cells."""
    setup = [c.replace("create_box 1 box", "create_box 2 box") for c in plate_setup("si", 6)
             if not c.startswith("pair_coeff")]
    at = setup.index(next(c for c in setup if c.startswith("set group all density")))
    types = [f"pair_coeff 1 1 {first}", f"pair_coeff 2 2 {second}"]
    if fraction > 0.0:
        types.append(f"set type 1 type/fraction 2 {fraction} 4711")
    return setup[:at] + types + setup[at:] + [
        "region fly block INF 2.9 INF INF INF INF", "group flyer region fly",
        "velocity flyer set 500 0 0 units box", "fix 1 all nve/sphere"]


def lone_link_after_tension(units, share, lone_law="shock"):
    """A block of shock elements (type 1, unbreakable) whose internal energy is set to u0 < 0,
    so that at J = 1 each has p = Gamma0 u0 = -T (a tension T = 0.5 GPa), and one element of
    type 2 (strength share T; the same law, or lone_law "linear": the linear law of the same
    bulk and shear moduli) linked to a surface element of the block by its only link, so that
    it has no pressure (its links span no volume, or its law has none).  Returns the lone
    element's links after the evaluation at that tension."""
    L, V, R, P, _ = UNITS[units]
    T = 0.5e9
    coeff, density = material(units, yield_stress=0.0)
    linear = f"bulk {K * P} shear {G * P}"
    lone = (3.5 * CELL + D, 0.5 * CELL, CELL)    # D from the surface element (3.5, 0.5, 1) CELL
    with session() as lmp:
        lmp.commands_list([
            f"units {units}", "atom_style sphere", "atom_modify map array", "comm_modify vel yes",
            "boundary f f f", f"lattice fcc {CELL * L}", "region box block -1 6 -1 4 -1 4",
            "create_box 2 box", "region block block 0 3.9 0 2.9 0 2.9",
            "create_atoms 1 region block",
            "create_atoms 2 single " + " ".join(str(c * L) for c in lone) + " units box",
            f"neighbor {0.25 * D * L} bin", f"set group all diameter {D * L}",
            f"pair_style mca fraction {PHI} tolerance 0.02", f"pair_coeff 1 1 {coeff}",
            f"pair_coeff 2 2 {coeff if lone_law == 'shock' else linear} strength {share * T * P}",
            f"set group all density {density}",
            "fix 1 all nve/sphere", "compute links all links/atom", "run 0 post no"])
        n = lmp.extract_global("nlocal")
        lone_atom = lmp.numpy.extract_atom("type")[:n] == 2
        assert lmp.numpy.extract_compute("links", 1, 1)[:n][lone_atom].tolist() == [1.0]
        # u in the style's energy per volume: Pa / nktv2p in metal units (eV/Angstrom^3)
        u0 = -T / GAMMA0 * P / lmp.extract_global("nktv2p")
        lmp.commands_list([f"set type 1 d_mca_energy {u0}", "run 0 post no"])
        return lmp.numpy.extract_compute("links", 1, 1)[:n][lone_atom][0]


@pytest.mark.parametrize("units", ["si", "metal"])
@pytest.mark.parametrize("lone_law", ["shock", "linear"])
def test_a_pair_with_one_pressure_reads_that_pressure_whole(units, lone_law):
    """A pair of which one element has a pressure (the other a linear-law element, or one whose
    links span no volume) reads that element's -p as its mean stress, not half of it: the lone
    element's link, in tension T from the block's pressure alone (its length unchanged), breaks
    at a strength of 0.95 T and holds at 1.05 T."""
    assert lone_link_after_tension(units, 0.95, lone_law) == 0.0
    assert lone_link_after_tension(units, 1.05, lone_law) == 1.0


def test_a_linear_material_is_not_changed_by_a_shock_material_beside_it():
    """A yielding linear material gives the same stresses whether an unused type has a shock law
    or a linear one (the return about the mean, the rupture rule and the hourglass spring are
    decided per pair)."""
    def stresses(other):
        with session() as lmp:
            lmp.commands_list(two_types(f"bulk {K} shear {G} yield {Y}", other) + [
                "compute s all mca/atom", "compute ps all reduce ave c_s[1] c_s[2] c_s[3]",
                "thermo_style custom step c_ps[1] c_ps[2] c_ps[3]", "run 300 post no"])
            return [lmp.extract_compute("ps", 0, 1)[k] for k in range(3)]
    linear = stresses(f"bulk {K} shear {G}")
    assert linear[1] < -0.5e9    # lateral compression in uniaxial strain
    assert stresses(f"shock {RHO0} {C0} {S} {GAMMA0} shear {G}") == pytest.approx(linear,
                                                                               rel=1e-12)


@pytest.mark.parametrize("change,message", [
    ("manybody no", r"needs the many-body term"),
    ("minimize", r"shock equation of state follows their volume through a run"),
])
def test_a_shock_material_on_any_type_is_checked(change, message):
    """The shock law's setup checks see a shock material on the first of two types as on the
    last (outsider mutant [r10-01]: only the last type's material decided)."""
    commands = two_types(f"shock {RHO0} {C0} {S} {GAMMA0} shear {G}", f"bulk {K} shear {G}", 0.5)
    if change == "manybody no":
        commands = [c + " manybody no" if c.startswith("pair_style") else c for c in commands]
    with session() as lmp:
        lmp.commands_list(commands)
        with pytest.raises(Exception, match=message):
            lmp.command("minimize 0 0 10 10" if change == "minimize" else "run 1 post no")


def test_shock_and_linear_elements_linked_keep_their_energy():
    """Half the elements with the shock law, half with the linear one (K = rho0 c0^2), linked at
    random, struck at 500 m/s: the energy stays within 0.3 % over 6000 steps (0.036 %
    measured; 3.1 % while the hourglass spring's energy was S b e^2 / 2, and it grew twentyfold
    while a mixed pair had the spring: doc/pair_mca.rst)."""
    with session() as lmp:
        lmp.commands_list(two_types(f"shock {RHO0} {C0} {S} {GAMMA0} shear {G}",
                                    f"bulk {K} shear {G}", 0.5) + [
            "compute erot all erotate/sphere", "variable e equal etotal+c_erot",
            "thermo_style custom step etotal c_erot v_e", "run 0 post no"])
        e0 = lmp.extract_variable("e")
        energies = []
        for _ in range(6):
            lmp.command("run 1000 post no")
            energies.append(lmp.extract_variable("e"))
    assert max(abs(e / e0 - 1.0) for e in energies) < 0.003


@pytest.mark.parametrize("words,message", [
    ("bulk_viscosity 3 1.2", r"b1 \(linear\) must lie in 0 to 2"),
    ("bulk_viscosity 0.06 5", r"b2 \(quadratic\) must lie in 0 to 4"),
    ("hourglass 6", r"hourglass \(coefficient\) must lie in 0 to 5"),
    ("hourglass 0", r"hourglass must be > 0 with shock \(got 0\)"),
])
def test_numerical_coefficients_beyond_their_range_are_refused(words, message):
    setup = [c for c in plate_setup("si", 3) if not c.startswith("pair_coeff")]
    with session() as lmp:
        lmp.commands_list(setup[:setup.index(next(c for c in setup
                                                   if c.startswith("set group all density")))])
        with pytest.raises(Exception, match=message):
            lmp.command(f"pair_coeff 1 1 {material('si')[0]} {words}")


def test_a_data_file_after_a_run_reads_back_and_restarts_the_elements(tmp_path):
    """write_data after a run: the pair_coeff words come back, the elements' state (fix
    PAIR_MCA_EOS) is not in the file (read_data would meet it before the style makes the fix),
    so the read system starts at J = 1, u = 0 and runs."""
    with session() as lmp:
        lmp.commands_list(plate_setup("si", 4) + [
            "velocity all set 100 0 0 units box", "region fly block INF 1.9 INF INF INF INF",
            "group flyer region fly", "velocity flyer set 300 0 0 units box",
            "fix 1 all nve/sphere", "run 100 post no", f"write_data {tmp_path}/shock.data"])
    text = (tmp_path / "shock.data").read_text()
    assert "PAIR_MCA_EOS" not in text and "shock 2703" in text
    with session() as lmp:
        lmp.commands_list([
            "units si", "atom_style sphere", "atom_modify map array", "comm_modify vel yes",
            "boundary s p p", f"neighbor {0.25 * D} bin", f"pair_style mca fraction {PHI}",
            f"read_data {tmp_path}/shock.data", f"timestep {0.1 * D / CL}",
            "fix 1 all nve/sphere", "run 10 post no"])
        n = lmp.extract_global("nlocal")
        assert np.all(np.isfinite(lmp.numpy.extract_atom("d_mca_energy")[:n]))


def test_removing_the_elements_state_stops_the_next_run():
    with session() as lmp:
        lmp.commands_list(plate_setup("si", 3) + ["fix 1 all nve/sphere", "run 5 post no",
                                                  "unfix PAIR_MCA_EOS"])
        with pytest.raises(Exception, match=r"fix PAIR_MCA_EOS \(the elements' volume"):
            lmp.command("run 5 post no")


@pytest.mark.parametrize("ratio", [0.9, 0.8])
def test_slow_compression_follows_the_isentrope(ratio):
    """A periodic elastic block compressed slowly along x by fix deform (positions remapped, no
    velocities: the elements' volume comes from their positions): its volume ratio J is the
    box's, its internal energy the isentrope's du/dJ = -p(J, u) (integrated here by RK4) within
    0.5 %, and LAMMPS's pressure (the virial of all forces) the isentrope's mean stress within
    2 % (the pairs' deviator at finite strain adds to it)."""
    def pressure(j, u):
        eta = 1.0 - j
        ph = K * eta / (1.0 - S * eta) ** 2 if eta > 0 else K * eta
        return ph + GAMMA0 * (u - 0.5 * ph * eta)
    u_is, j, n = 0.0, 1.0, 4000
    h = (ratio - 1.0) / n
    for _ in range(n):
        k1 = -pressure(j, u_is)
        k2 = -pressure(j + h / 2, u_is + h / 2 * k1)
        k3 = -pressure(j + h / 2, u_is + h / 2 * k2)
        k4 = -pressure(j + h, u_is + h * k3)
        u_is += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        j += h
    setup = [c.replace("boundary s p p", "boundary p p p").replace(f"yield {Y}", "")
             for c in plate_setup("si", 3)]
    with session() as lmp:
        lmp.commands_list(setup + [
            "fix 1 all nve/sphere", "run 0 post no",    # the elements' state exists from a run
            "compute pa all property/atom d_mca_dvolume d_mca_energy",
            "compute r all reduce ave c_pa[1] c_pa[2]", "thermo_style custom step press c_r[1]",
            f"fix 2 all deform 1 x scale {ratio} remap x",
            f"run {int(40000 * (1.0 - ratio))} post no", "run 0 post no"])
        j_mean = 1.0 + lmp.extract_compute("r", 0, 1)[0]
        u_mean = lmp.extract_compute("r", 0, 1)[1]
        press = lmp.get_thermo("press")
    assert j_mean == pytest.approx(ratio, rel=2e-3)
    assert u_mean == pytest.approx(u_is, rel=5e-3)
    assert press == pytest.approx(pressure(ratio, u_is), rel=0.02)


def by_id(lmp, name):
    """A per-atom array of the local atoms sorted by id (serial runs)."""
    n = lmp.extract_global("nlocal")
    return lmp.numpy.extract_atom(name)[:n][np.argsort(lmp.numpy.extract_atom("id")[:n])].copy()


@pytest.mark.parametrize("units", ["si", "metal"])
def test_bulk_viscosity_takes_the_compressed_density(units):
    """The periodic elastic block of test_slow_compression_follows_the_isentrope compressed by
    fix deform at a constant rate to V/V0 = 0.8 in 2000 steps: every element's viscosity is the
    doc's q = rho L D (b1 c0 + b2^2 L D) with rho = rho0 / J (not rho0), L = 2R, D = -(tr H' +
    tr H) / (2 dt) from the box lengths of fix deform's linear schedule (H = 1 - l_(n-1) / l_n
    along x for a homogeneous step; the last evaluation saw the box of step N - 1, after
    those of N - 2 and N - 3), b1 = 0.06, b2 = 1.2: exact in the style's units (its mvv2e), and
    in Pa within LAMMPS's metal constants (1e-6); J is the box's ratio."""
    L, V, R, P, _ = UNITS[units]
    T = L / V
    ratio, nsteps = 0.8, 2000
    setup = [c.replace("boundary s p p", "boundary p p p").replace(f"yield {Y * P}", "")
             for c in plate_setup(units, 3)]
    with session() as lmp:
        lmp.commands_list(setup + ["fix 1 all nve/sphere", "run 0 post no",
                                   f"fix 2 all deform 1 x scale {ratio} remap x",
                                   f"run {nsteps} post no"])
        q = by_id(lmp, "d_mca_viscosity")
        j = 1.0 + by_id(lmp, "d_mca_dvolume")
        dt, mvv2e, nktv2p = (lmp.extract_global(k) for k in ("dt", "mvv2e", "nktv2p"))

    def box(k):    # fix deform's box length after step k, over the reference's
        return 1.0 + (ratio - 1.0) * k / nsteps
    now, before = 1.0 - box(nsteps - 2) / box(nsteps - 1), 1.0 - box(nsteps - 3) / box(nsteps - 2)
    assert j == pytest.approx(box(nsteps - 1), rel=1e-6)
    rate = -0.5 * (before + now) / dt                              # per the style's time
    size = D * L
    style = mvv2e * RHO0 * R / j * size * rate * (0.06 * C0 * V + 1.2 ** 2 * size * rate)
    assert q == pytest.approx(style, rel=1e-10)
    rate_si = rate * T
    si = RHO0 / j * D * rate_si * (0.06 * C0 + 1.2 ** 2 * D * rate_si)
    assert q * nktv2p / P == pytest.approx(si, rel=1e-6)
    assert si.min() > 8e6    # about 9 MPa: the linear term (0.7 MPa the quadratic one)


EV = 1.602176634e-19    # J: metal's energy unit
KICK = 1.0e-4           # the hourglass mode's step, in element diameters


def hourglass_kick(units, ratio, hourglass):
    """The periodic elastic block of plate_setup(units, 3) (fcc [100], 108 elements, 648 links),
    compressed along x to V/V0 = ratio by change_box between runs (its elements jump onto the
    Hugoniot: p = p_H(1 - ratio)), then its x planes of elements kicked alternately by +-KICK d
    over one step, the hourglass mode (hourglass: the coefficient H of type 1 and of type 2,
    type 2 on the odd planes).  Returns pe after the step (J), the elements' energy per volume
    before it (Pa), the positions (SI) at the reference, before and after the step, and the
    types."""
    L, V, R, P, _ = UNITS[units]
    setup = [c.replace("boundary s p p", "boundary p p p").replace("create_box 1 box",
                                                                    "create_box 2 box")
             for c in plate_setup(units, 3) if not c.startswith("pair_coeff")]
    at = setup.index(next(c for c in setup if c.startswith("set group all density")))
    coeffs = [f"pair_coeff {t} {t} {material(units, 0.0, f'hourglass {h}')[0]}"
              for t, h in ((1, hourglass[0]), (2, hourglass[1]))]
    with session() as lmp:
        lmp.commands_list(setup[:at] + coeffs + setup[at:] + [
            f"variable odd atom round(x/{CELL * L / 2})%2==1", "group odd variable odd",
            "set group odd type 2", "fix 1 all nve/sphere", "thermo_style custom step pe",
            "run 0 post no"])
        reference = by_id(lmp, "x") / L
        odd = by_id(lmp, "type") == 2
        if ratio != 1.0:
            lmp.commands_list([f"change_box all x scale {ratio} remap", "run 0 post no"])
        before = by_id(lmp, "x") / L
        energy = by_id(lmp, "d_mca_energy") * lmp.extract_global("nktv2p") / P
        n = lmp.extract_global("nlocal")
        ids = lmp.numpy.extract_atom("id")[:n]
        kick = KICK * D * L / lmp.extract_global("dt")
        lmp.numpy.extract_atom("v")[:n, 0] = np.where(odd[ids - 1], -kick, kick)
        lmp.command("run 1 post no")
        after = by_id(lmp, "x") / L
        pe = lmp.get_thermo("pe") * (EV if units == "metal" else 1.0)
    return pe, energy, reference, before, after, np.where(odd, 2, 1)


def hourglass_energy(reference, before, after, types, ratio, hourglass):
    """The doc's spring energy S b e_hg^2 / 2 summed over the links (the nearest neighbours of
    the reference lattice): e_hg = dr - r n.(H_i + H_j)/2.n over the step (H_i = sum dx x^T
    (sum x x^T)^-1 over i's links, equal weights: the least-squares gradient, second order in
    this mode), S = 3 Omega / (12 R) (12 links), b the series of the halves 2 H (K + 4G/3 +
    2 |p|) / R, p = p_H(1 - ratio) (SI)."""
    span = np.array([3 * CELL] * 3)
    d = reference[None, :, :] - reference[:, None, :]
    d -= span * np.rint(d / span)
    dist = np.linalg.norm(d, axis=2)
    count = np.arange(len(reference))
    ii, jj = np.where((dist < 1.01 * D) & (count[:, None] < count[None, :]))
    assert len(ii) == 648
    span[0] *= ratio

    def separations(x):
        s = x[jj] - x[ii]
        return s - span * np.rint(s / span)
    s0, s1 = separations(before), separations(after)
    r1 = np.linalg.norm(s1, axis=1)
    shape, moved = np.zeros((len(reference), 3, 3)), np.zeros((len(reference), 3, 3))
    for k, xs, dx in ((ii, s1, s1 - s0), (jj, -s1, s0 - s1)):
        np.add.at(shape, k, xs[:, :, None] * xs[:, None, :])
        np.add.at(moved, k, dx[:, :, None] * xs[:, None, :])
    grad = moved @ np.linalg.inv(shape)
    grad = 0.5 * (grad + np.transpose(grad, (0, 2, 1)))
    n = s1 / r1[:, None]
    affine = r1 * np.einsum("pi,pij,pj->p", n, 0.5 * (grad[ii] + grad[jj]), n)
    e_hg = r1 - np.linalg.norm(s0, axis=1) - affine
    radius = D / 2
    area = 3 * (4 * math.pi * radius ** 3 / (3 * PHI)) / (12 * radius)
    eta = 1.0 - ratio
    p = K * eta / (1.0 - S * eta) ** 2
    h = np.where(types == 1, hourglass[0], hourglass[1])
    bi, bj = (2 * h[k] * (K + 4 * G / 3 + 2 * p) / radius for k in (ii, jj))
    return np.sum(0.5 * area * bi * bj / (bi + bj) * e_hg ** 2), p


def hourglass_check(units, ratio, hourglass):
    """pe(2H) - pe(H) over the same step (the kick moves the elements; the spring's force
    comes after) is the spring's energy at H: every other term of pe is the same; to 1e-6
    (the step changes p by 3e-7 of itself)."""
    pe1, energy, reference, before, after, types = hourglass_kick(units, ratio, hourglass)
    pe2 = hourglass_kick(units, ratio, [2 * h for h in hourglass])[0]
    spring, p = hourglass_energy(reference, before, after, types, ratio, hourglass)
    # the change_box jump lands on the Hugoniot: u = p_H eta / 2 per reference volume (metal:
    # within LAMMPS's constants, nktv2p 1.6021765e6)
    assert energy == pytest.approx(0.5 * p * (1.0 - ratio), rel=1e-9 if units == "si" else 1e-6,
                                   abs=1e-6)
    assert pe2 - pe1 == pytest.approx(spring, rel=1e-6)
    return spring


@pytest.mark.parametrize("units", ["si", "metal"])
def test_hourglass_spring_holds_half_s_b_e_squared(units):
    """The hourglass spring of a link at rest pressure: energy S b e_hg^2 / 2 (doc/pair_mca.rst
    "The hourglass spring"), b = H (K + 4G/3) / R for two equal halves."""
    assert hourglass_check(units, 1.0, (1.0, 1.0)) > 1e-10


@pytest.mark.parametrize("units", ["si", "metal"])
def test_hourglass_spring_stiffens_with_the_pressure(units):
    """At V/V0 = 0.8 (p = 28.9 GPa, 2|p| half of K + 4G/3): each half is 2 H (K + 4G/3 +
    2 |p|) / R."""
    hourglass_check(units, 0.8, (1.0, 1.0))


@pytest.mark.parametrize("units", ["si", "metal"])
def test_hourglass_spring_of_two_materials_takes_each_half_in_series(units):
    """Alternate planes of two materials, H = 1 and 2.5: every link of the mode joins the two,
    b = b_1 b_2 / (b_1 + b_2) (not one element's half twice), compressed to V/V0 = 0.8."""
    hourglass_check(units, 0.8, (1.0, 2.5))


def test_example_disc_flies_at_v_on_the_axis_and_writes_its_frames(tmp_path):
    """in.disc reduced (10 um elements, a disc of 8 cells' radius and 2 thick on a target 4
    thick and 20 wide, about 9,200 elements): behind the disc's centre the impact is a plate
    impact until the rim's release arrives, after the shock reaches the free face (the rim is
    twice as far from the axis as the target is thick): the face on the axis flies at v within
    10 % (two elements across the flyer smear the pulse's top); halfway to the rim the release
    arrives earlier and the face peaks at least 10 % lower; the slab's frames are written
    (frames + 1 of them, with the columns the example's picture reads)."""
    out = example(tmp_path, "in.disc", metal="al", v=400, d=1.0e-5, flyer=2, target=4, radius=8,
                  width=20, frames=2)
    n = int(re.search(r"impact at 400 m/s, (\d+) elements", out).group(1))
    assert 8000 < n < 10000
    axis, half = np.loadtxt(tmp_path / "disc.visar", usecols=(2, 3), unpack=True)
    assert axis.max() == pytest.approx(400.0, rel=0.10)
    assert half.max() < 0.9 * axis.max()
    text = (tmp_path / "disc.slice").read_text()
    assert text.count("ITEM: TIMESTEP") == 3
    assert "ITEM: ATOMS id x y vx c_el[11] c_el[9]" in text
