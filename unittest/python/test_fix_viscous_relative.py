"""fix viscous/relative against independent oracles: conservation laws, the closed-form
decay of a pair, pair_style dpd/tstat at zero temperature, fix viscous, the energy
balance, serial vs MPI, restart, stability, the pairs a pair style with link L holds bonded
(free flight as the oracle for the others), the closed-form force atom by atom in an
accelerating block of three types (each type pair its own cutoff, C and m_ij), a dimer's exact
velocity-Verlet recurrence in the eight unit styles, and bad input (the table of hostile input,
conftest.InputTable)."""
import ctypes
import math

import numpy as np
import pytest
from conftest import (OK, PLUGIN, SCENE_BOX, SCENE_EMPTY, SCENE_MORSE, SCENE_NOBOX, SCENE_UNITS,
                      SI_CLUSTERS, InputTable, carried_totals, check_input, fcc_block, last_thermo,
                      morse_fcc, run_lmp, scene_dimer, scene_pair, scene_unit_dimer, session)


def arrays(lmp, name, n=3):
    return np.array(lmp.gather_atoms(name, 1, n)).reshape(-1, n)


def momentum(lmp):
    return arrays(lmp, "v").sum(axis=0)  # unit masses


def thermal_morse(lmp, fix, temp=0.3, ntypes=1):
    fcc_block(lmp, noise=0.05, temp=temp, ntypes=ntypes)
    lmp.commands_list(["pair_style morse/spline cut 1.3", "pair_coeff * * 1.0 6.0 1.0",
                       "pair_modify shift yes", "timestep 0.002", "fix nve all nve", fix,
                       "thermo_style custom step pe ke", "thermo_modify norm no"])


@pytest.mark.parametrize("mode", ["full", "normal"])
@pytest.mark.parametrize("weight", ["none", "dpd"])
def test_momentum_is_conserved_and_energy_removed(mode, weight):
    with session() as lmp:
        thermal_morse(lmp, f"fix damp all viscous/relative gamma 2.0 mode {mode} weight {weight}",
                      ntypes=2)  # masses 1 and 2
        masses = {1: 1.0, 2: 2.0}
        def total_p():
            t = np.array(lmp.gather_atoms("type", 0, 1))
            return (arrays(lmp, "v") * np.array([masses[k] for k in t])[:, None]).sum(axis=0)
        lmp.command("velocity all set 0.3 -0.2 0.1 sum yes units box")  # a drift to keep
        p0, ke0 = total_p(), None
        lmp.command("run 0 post no")
        ke0 = lmp.get_thermo("ke")
        lmp.command("run 500 post no")
        p1 = total_p()
        removed = lmp.extract_fix("damp", 0, 0)
    assert np.max(np.abs(p1 - p0)) <= 1e-12 * np.max(np.abs(p0))
    assert 0.0 < removed < ke0 * 1e4


def rigid_body(lmp, fix, omega=0.0, vel=(0.0, 0.0, 0.0)):
    """A free fcc cluster, no pair forces (pair zero gives the damping range)."""
    lmp.commands_list([
        "units lj", "boundary s s s", "atom_modify map array", "lattice fcc 1.4142135623730951",
        "region box block 0 3 0 3 0 3", "create_box 1 box", "create_atoms 1 box", "mass 1 1.0",
        "pair_style zero 1.2", "pair_coeff * *", "neighbor 0.3 bin", "timestep 0.001",
        "fix nve all nve", fix])
    x = arrays(lmp, "x")
    c = x.mean(axis=0)
    v = np.array(vel) + omega * np.stack([-(x[:, 1] - c[1]), x[:, 0] - c[0], 0 * x[:, 0]], axis=1)
    flat = v.ravel()
    lmp.scatter_atoms("v", 1, 3, (ctypes.c_double * len(flat))(*flat))
    return c


def angular_momentum(lmp):
    x, v = arrays(lmp, "x"), arrays(lmp, "v")
    return np.cross(x - x.mean(axis=0), v).sum(axis=0)


@pytest.mark.parametrize("mode", ["full", "normal"])
def test_rigid_translation_is_not_damped(mode):
    with session() as lmp:
        rigid_body(lmp, f"fix damp all viscous/relative gamma 5.0 mode {mode}",
                   vel=(0.4, -0.3, 0.2))
        lmp.command("run 200 post no")
        v = arrays(lmp, "v")
        assert lmp.extract_fix("damp", 0, 0) == 0.0
    assert np.allclose(v, [0.4, -0.3, 0.2], rtol=0, atol=1e-14)


def test_rigid_rotation_damped_in_full_mode_not_in_normal_mode():
    result = {}
    for mode in ("full", "normal"):
        with session() as lmp:
            rigid_body(lmp, f"fix damp all viscous/relative gamma 5.0 mode {mode}", omega=0.2)
            l0 = angular_momentum(lmp)
            lmp.command("run 200 post no")
            result[mode] = (l0, angular_momentum(lmp), lmp.extract_fix("damp", 0, 0))
    l0, l1, removed = result["full"]
    assert abs(l1[2]) < 0.9 * abs(l0[2]) and removed > 0
    l0, l1, removed = result["normal"]
    # normal mode: central forces conserve L (the rotation stretches bonds only to O(dt^2))
    assert np.max(np.abs(l1 - l0)) <= 1e-6 * abs(l0[2])


def pair_decay(g, dt, t_end):
    """Relative velocity of two free particles (no pair force) after t_end."""
    with session() as lmp:
        lmp.commands_list([
            "units lj", "atom_modify map array", "region box block -5 5 -5 5 -5 5",
            "create_box 1 box", "create_atoms 1 single -0.5 0 0", "create_atoms 1 single 0.5 0 0",
            "mass 1 1.0", "pair_style zero 1.5", "pair_coeff * *", f"timestep {dt}",
            "fix nve all nve", f"fix damp all viscous/relative gamma {g}",
            "velocity all set 0 0 0", "set atom 1 vy 0.05", "set atom 2 vy -0.05",
            f"run {round(t_end / dt)} post no"])
        v = arrays(lmp, "v")
    return v[0, 1] - v[1, 1]


def test_pair_relative_velocity_decays_as_exp_minus_2_g_t():
    """The damping acts on the half-step velocity (as pair dpd/tstat does), so the decay
    rate is exact to first order in G dt: measured error 0.80 % at 2 G dt = 0.008."""
    g, t_end = 2.0, 0.5
    exact = 0.1 * math.exp(-2 * g * t_end)
    err = {dt: pair_decay(g, dt, t_end) - exact for dt in (0.002, 0.001)}
    assert abs(err[0.002]) <= 1.2 * 2 * g * 0.002 * exact, err
    assert 1.8 <= err[0.002] / err[0.001] <= 2.2, err  # first order in dt


def test_normal_dpd_weight_equals_pair_dpd_tstat_at_zero_temperature():
    gamma, rc = 1.5, 1.3
    runs = []
    for variant in ("dpd", "fix"):
        with session() as lmp:
            lmp.command("comm_modify vel yes")
            fcc_block(lmp, noise=0.05, temp=0.5)
            if variant == "dpd":
                lmp.commands_list([f"pair_style hybrid/overlay morse {rc} dpd/tstat 0 0 {rc} 4242",
                                   "pair_coeff * * morse 1.0 6.0 1.0",
                                   f"pair_coeff * * dpd/tstat {gamma}"])
            else:
                lmp.commands_list([f"pair_style morse {rc}", "pair_coeff * * 1.0 6.0 1.0",
                                   f"fix damp all viscous/relative gamma {gamma} mode normal "
                                   f"weight dpd cutoff {rc}", "fix_modify damp virial yes"])
            lmp.commands_list(["timestep 0.002", "fix nve all nve",
                               "thermo_style custom step ke press pxy", "run 100 post no"])
            runs.append((arrays(lmp, "x"), arrays(lmp, "v"),
                         [lmp.get_thermo(k) for k in ("ke", "press", "pxy")]))
    (x1, v1, t1), (x2, v2, t2) = runs
    assert np.max(np.abs(x1 - x2)) <= 1e-11
    assert np.max(np.abs(v1 - v2)) <= 1e-10 * np.max(np.abs(v1))
    assert t2 == pytest.approx(t1, rel=1e-9)


def test_fix_viscous_loses_momentum_this_fix_keeps_it():
    p = {}
    for fix in ("fix damp all viscous 2.0", "fix damp all viscous/relative gamma 2.0"):
        with session() as lmp:
            thermal_morse(lmp, fix)
            lmp.command("velocity all set 0.5 0 0 sum yes units box")
            p0 = momentum(lmp)
            lmp.command("run 200 post no")
            p[fix.split()[3]] = (p0, momentum(lmp))
    p0, p1 = p["viscous"]
    assert p1[0] < 0.6 * p0[0]
    p0, p1 = p["viscous/relative"]
    assert abs(p1[0] - p0[0]) <= 1e-12 * abs(p0[0])


def energy_balance_error(dt, steps_time=2.0):
    with session() as lmp:
        thermal_morse(lmp, "fix damp all viscous/relative gamma 1.0")
        lmp.commands_list([f"timestep {dt}", "run 0 post no"])
        e0 = lmp.get_thermo("pe") + lmp.get_thermo("ke")
        lmp.command(f"run {round(steps_time / dt)} post no")
        e1 = lmp.get_thermo("pe") + lmp.get_thermo("ke")
        removed = lmp.extract_fix("damp", 0, 0)
    return e0 - e1 - removed, removed


def test_energy_balance_thermal_block_is_second_order():
    """Initial energy = kinetic + potential + removed, to O(dt^2): measured errors 0.408,
    0.107, 0.028 of 315 removed at dt = 0.004, 0.002, 0.001 (T0 = 0.74)."""
    err1, removed = energy_balance_error(0.004)
    err2, _ = energy_balance_error(0.002)
    assert removed > 0
    assert abs(err1) <= 2e-3 * removed, (err1, removed)
    assert abs(err2) <= 0.3 * abs(err1), (err1, err2)  # O(dt^2): a quarter


def test_energy_balance_piston_chain():
    """Piston work (trapezoid rule on the piston's force) + initial energy = kinetic +
    potential + removed, for a 1D Morse chain driven at u (reduced units)."""
    u, dt, n = 0.5, 0.002, 40
    with session() as lmp:
        lmp.commands_list([
            "units lj", "atom_modify map array", "boundary m p p", "lattice sc 1.0",
            f"region box block -0.5 {n + 0.5} -5 5 -5 5", "create_box 1 box",
            f"region line block -0.5 {n + 0.5} -0.5 0.5 -0.5 0.5", "create_atoms 1 region line",
            "mass 1 1.0", "pair_style morse/spline cut 1.2", "pair_coeff 1 1 1.0 4.0 1.0",
            "pair_modify shift yes", "neighbor 0.2 bin", "neigh_modify every 1 delay 0",
            "group piston id 1", "group chain subtract all piston",
            f"velocity piston set {u} 0 0", f"fix move piston move linear {u} 0 0 units box",
            "fix nve chain nve", "fix damp all viscous/relative J 20", f"timestep {dt}",
            "thermo_style custom step pe ke", "thermo_modify norm no", "run 0 post no"])
        e0 = lmp.get_thermo("pe") + lmp.get_thermo("ke")
        f_prev, work = lmp.extract_atom("f")[0][0], 0.0
        for _ in range(1500):
            lmp.command("run 1 pre no post no")
            f_now = lmp.extract_atom("f")[0][0]
            work -= 0.5 * (f_prev + f_now) * u * dt  # force on the chain = -force on piston
            f_prev = f_now
        e1 = lmp.get_thermo("pe") + lmp.get_thermo("ke")
        removed = lmp.extract_fix("damp", 0, 0)
    assert work > 0 and removed > 0
    assert abs(e0 + work - e1 - removed) <= 2e-3 * work, (e0 + work, e1 + removed)


def test_fix_modify_energy_adds_removed_energy_to_pe():
    with session() as lmp:
        thermal_morse(lmp, "fix damp all viscous/relative gamma 1.0")
        lmp.command("run 100 post no")
        pe_plain = lmp.get_thermo("pe")
        lmp.commands_list(["fix_modify damp energy yes", "run 0 post no"])
        assert lmp.get_thermo("pe") == pytest.approx(pe_plain + lmp.extract_fix("damp", 0, 0),
                                                     rel=1e-12)


# the energy removed, a cumulative total, in a thermalised Morse block
DAMPED = "\n".join(morse_fcc() + ["velocity all create 0.3 4712 loop geom", "timestep 0.002", ""])
DAMPING = "fix 1 all nve\nfix v all viscous/relative gamma 2.0\n"


@pytest.mark.parametrize("nprocs", [1, 2])
def test_removed_energy_carries_across_run_boundaries_and_restart_files(tmp_path, nprocs):
    """run N + run M pre no (the straight run's steps) ends with run N+M's energy removed and
    a run 0 (a setup) at the boundary keeps it; a restart file written between runs or during
    one (restart N) gives it back to a fix with the same ID in a fresh instance, the
    uninterrupted run's at that step.  A run resumed from the file parts from the straight one
    as a split run does (the setup damps the full-step velocities: measured 1.1e-7)."""
    r = carried_totals(tmp_path, DAMPED + DAMPING, ["f_v"], "neighbor 0.3 bin\n" + DAMPING,
                       100, 100, nprocs)
    assert 0 < r["straight_n"][0] < r["straight_nm"][0]
    assert r["split_n"] == pytest.approx(r["straight_n"], rel=1e-12)
    assert r["split_nm"] == pytest.approx(r["straight_nm"], rel=1e-12)
    assert r["boundary"] == pytest.approx(r["split_nm"], rel=1e-12)
    assert r["read_nm"] == pytest.approx(r["straight_nm"], rel=1e-12)
    assert r["mid_nm"] == pytest.approx(r["straight_nm"], rel=1e-12)
    assert r["read_n"] == pytest.approx(r["straight_n"], rel=1e-12)
    assert r["resumed_nm"] == pytest.approx(r["straight_nm"], rel=1e-6)


def test_removed_energy_survives_restart(tmp_path):
    restart = tmp_path / "restart.bin"
    with session() as lmp:
        thermal_morse(lmp, "fix damp all viscous/relative gamma 1.0")
        lmp.commands_list(["run 100 post no", f"write_restart {restart}"])
        removed = lmp.extract_fix("damp", 0, 0)
    with session() as lmp:
        lmp.commands_list([f"read_restart {restart}", "fix nve all nve",
                           "fix damp all viscous/relative gamma 1.0", "run 0 post no"])
        assert lmp.extract_fix("damp", 0, 0) == removed > 0


@pytest.mark.parametrize("nprocs", [2, 4])
def test_mpi_equals_serial(tmp_path, nprocs):
    script = "\n".join([
        f"plugin load {PLUGIN}", "units lj", "lattice fcc 1.4142135623730951",
        "region box block 0 5 0 5 0 5", "create_box 1 box", "create_atoms 1 box", "mass 1 1.0",
        "reset_atoms id sort yes", "displace_atoms all random 0.05 0.05 0.05 4711",
        "velocity all create 0.3 1 loop geom", "pair_style morse/spline cut 1.3",
        "pair_coeff * * 1.0 6.0 1.0", "neighbor 0.3 bin", "fix nve all nve",
        "fix damp all viscous/relative J 5 mode normal", "fix_modify damp virial yes",
        "variable px equal vcm(all,x)", "timestep 0.002",
        "thermo_style custom step pe ke press f_damp v_px",
        "thermo_modify format float %.15g", "run 300"])
    cols = ["PotEng", "KinEng", "Press", "f_damp"]
    serial = last_thermo(run_lmp(tmp_path, script), cols)
    parallel = last_thermo(run_lmp(tmp_path, script, nprocs), cols)
    assert serial[3] > 0
    assert parallel == pytest.approx(serial, rel=1e-9)


def test_warns_when_unstable_and_strong_damping_below_bound_is_stable(tmp_path):
    base = "\n".join([
        f"plugin load {PLUGIN}", "units lj", "lattice fcc 1.4142135623730951",
        "region box block 0 4 0 4 0 4", "create_box 1 box", "create_atoms 1 box", "mass 1 1.0",
        "velocity all create 0.3 1 loop geom", "pair_style morse/spline cut 1.3",
        "pair_coeff * * 1.0 6.0 1.0", "neighbor 0.3 bin", "fix nve all nve",
        "fix damp all viscous/relative J 1", "thermo_style custom step pe ke f_damp",
        "thermo_modify format float %.15g"])
    # omega0 = sqrt(C/m) = sqrt(72) = 8.49; J = 1: G = 8.49; 12 bonds: stable for dt < 0.0098
    out = run_lmp(tmp_path, base + "\ntimestep 0.02\nrun 0\n")
    assert "damping is unstable" in out and "time step below 0.0098" in out
    out = run_lmp(tmp_path, base + "\ntimestep 0.005\nrun 2000\n")
    assert "damping is unstable" not in out
    pe, ke, removed = last_thermo(out, ["PotEng", "KinEng", "f_damp"])
    assert all(map(math.isfinite, (pe, ke, removed))) and ke < 1e-6 and removed > 0


BAD = [
    ("gamma", "expected fix ID group viscous/relative"),
    ("gamma 0", "gamma must be > 0"),
    ("J -2", "J must be > 0"),
    ("beta 1", "unknown style 'beta'"),
    ("gamma 1 mode tangential", "unknown mode 'tangential'"),
    ("gamma 1 weight gauss", "unknown weight 'gauss'"),
    ("gamma 1 cutoff 0", "cutoff must be > 0"),
    ("gamma 1 mode", "keyword mode needs a value"),
    ("gamma 1 scale 2", "unknown keyword 'scale'"),
]


@pytest.mark.parametrize("args,message", BAD)
def test_bad_arguments(args, message):
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 4 0 4 0 4", "create_box 1 box"])
        with pytest.raises(Exception, match=message):
            lmp.command(f"fix damp all viscous/relative {args}")


def test_j_needs_a_pair_style_with_stiffness_and_cutoff_within_ghost_range():
    with session() as lmp:
        fcc_block(lmp)
        lmp.commands_list(["pair_style morse 1.3", "pair_coeff * * 1.0 6.0 1.0",
                           "fix damp all viscous/relative J 10"])
        with pytest.raises(Exception, match="needs a pair style that provides the bond stiffness"):
            lmp.command("run 0")
        lmp.command("unfix damp")
        lmp.command("fix damp all viscous/relative gamma 1 cutoff 3.0")
        with pytest.raises(Exception, match="exceeds the ghost atom range"):
            lmp.command("run 0")


def test_per_atom_masses_conserve_momentum_and_match_type_masses():
    """atom_style with per-atom masses (rmass): the same masses as per-type masses give the
    same forces (the m_ij path per pair), and the momentum is conserved."""
    forces = []
    for style in ("atomic", "sphere"):
        with session() as lmp:
            lmp.command(f"atom_style {style}")
            fcc_block(lmp, noise=0.05, temp=0.3, ntypes=2, rmass=style == "sphere")
            lmp.commands_list(["pair_style zero 1.3", "pair_coeff * *",
                               "fix damp all viscous/relative gamma 3.0 mode normal",
                               "run 0 post no"])
            forces.append(arrays(lmp, "f"))
    assert np.max(np.abs(forces[0])) > 0
    assert np.max(np.abs(forces[0] - forces[1])) <= 1e-13 * np.max(np.abs(forces[0]))
    assert np.max(np.abs(forces[1].sum(axis=0))) <= 1e-12 * np.max(np.abs(forces[1]))


def test_only_pairs_inside_the_group_are_damped():
    with session() as lmp:
        fcc_block(lmp, noise=0.05, temp=0.3)
        lmp.commands_list(["region half block 0 2 INF INF INF INF", "group half region half",
                           "pair_style zero 1.3", "pair_coeff * *",
                           "fix damp half viscous/relative gamma 3.0", "run 0 post no"])
        f = arrays(lmp, "f")
        inside = np.array(lmp.gather_atoms("mask", 0, 1)) & 2 > 0  # bit of group "half"
    assert np.any(inside) and np.any(~inside)
    assert np.all(f[~inside] == 0.0) and np.max(np.abs(f[inside])) > 0
    assert np.max(np.abs(f[inside].sum(axis=0))) <= 1e-12 * np.max(np.abs(f))


# --- the damping summed in the spline pair style's force pass (damping_pass.h) ---------------

FUSED = "damping summed in pair"


def hot_block(lmp, units="lj", ntypes=2, law="morse", a_scale=1.0):
    """A hot fcc block: units lj, fcc_block's (masses 1 and 2); units si, the aluminium
    clusters of the 3D examples, 10 um.  Returns pair_coeff's values of the law (a: a_scale
    lattice's a), the time step and the lattice's a."""
    if units == "lj":
        fcc_block(lmp, noise=0.05, temp=0.3, ntypes=ntypes)
        coeff, dt, a = (f"1.0 6.0 {a_scale!r}" if law == "morse" else f"1.0 {a_scale!r}"), 0.002, 1.0
    else:
        a = 1.0e-5
        lmp.commands_list([
            "units si", "atom_modify map array", f"lattice fcc {a * math.sqrt(2)!r}",
            "region box block 0 4 0 4 0 4", f"create_box {ntypes} box", "create_atoms 1 box",
            "mass * 2.338e-12", "reset_atoms id sort yes",
            f"displace_atoms all random {0.05 * a} {0.05 * a} {0.05 * a} 4711 units box",
            "velocity all create 1e16 4712 loop geom", f"neighbor {0.3 * a} bin"])
        if ntypes == 2:
            lmp.commands_list(["set type 1 type/fraction 2 0.5 4713", "mass 2 4.676e-12"])
        coeff, dt = (f"2.46e-6 3.76e5 {a_scale * a!r}" if law == "morse" else
                     f"2.46e-6 {a_scale * a!r}"), 2e-10
    return coeff, dt, a


def by_id(lmp, *names):
    order = np.argsort(np.array(lmp.gather_atoms("id", 0, 1)))
    return [arrays(lmp, name)[order] for name in names]


def damped_run(lmp, log, fix, thermo, steps=200, units="lj", ntypes=2, newton="on",
               pair="morse/spline cut 1.3", suffix=None, a_scale=1.0, extra=()):
    """A hot damped block; thermo 1 asks for the energy on every step, so the pair style never
    takes the damping into its pass (steps with tallies), thermo `steps` leaves it every step
    but the first and last.  a_scale: pair_coeff's a in units of the lattice's; extra: commands
    after the fix.  Returns positions, velocities (by atom ID) and the energy removed."""
    lmp.command(f"log {log}")
    if suffix:
        lmp.commands_list([f"suffix {suffix}", "package omp 2"])
    coeff, dt, _ = hot_block(lmp, units, ntypes, pair.split("/")[0], a_scale)
    lmp.commands_list([f"newton {newton} on", f"pair_style {pair}", f"pair_coeff * * {coeff}",
                       "pair_modify shift yes", f"timestep {dt}", "fix nve all nve", fix,
                       *extra, f"thermo {thermo}", "thermo_style custom step pe ke f_damp",
                       f"run {steps} post no"])
    removed = lmp.extract_fix("damp", 0, 0)
    lmp.command("log none")
    x, v = by_id(lmp, "x", "v")
    return x, v, removed


@pytest.mark.parametrize("units,ntypes,newton,suffix,law", [
    ("lj", 1, "on", None, "morse"), ("lj", 2, "on", None, "morse"), ("lj", 2, "off", None, "morse"),
    ("si", 2, "on", None, "morse"), ("lj", 2, "on", "omp", "morse"),
    ("lj", 2, "off", "omp", "morse"), ("si", 1, "on", "omp", "morse"),
    ("lj", 2, "on", None, "lj"), ("si", 1, "off", "omp", "lj")])
@pytest.mark.parametrize("options", ["gamma 2.0", "gamma 2.0 mode normal",
                                     "J 20 mode normal weight dpd", "J 20 weight dpd"])
def test_damping_in_the_pair_pass_equals_the_fix_loop(tmp_path, units, ntypes, newton, suffix,
                                                      law, options):
    """/omp with 2 threads: thread 0 into fd, thread 1 into its block, summed after.  lj/spline
    applies each pair as it is read (no vector stage), morse/spline through the block."""
    if units == "si":
        options = options.replace("gamma 2.0", "gamma 1e8")
    runs = {}
    for thermo in (1, 200):  # every step by the fix's own loop; all but two in the pair's pass
        log = tmp_path / f"log.{thermo}"
        with session() as lmp:
            runs[thermo] = damped_run(lmp, log, f"fix damp all viscous/relative {options}", thermo,
                                      units=units, ntypes=ntypes, newton=newton, suffix=suffix,
                                      pair=f"{law}/spline cut 1.3")
        assert FUSED in log.read_text()
    (x1, v1, e1), (x2, v2, e2) = runs[1], runs[200]
    assert e1 > 0
    assert e2 == pytest.approx(e1, rel=1e-10)
    assert np.max(np.abs(v2 - v1)) <= 1e-10 * np.max(np.abs(v1))
    assert np.max(np.abs(x2 - x1)) <= 1e-10 * np.max(np.abs(x1))


@pytest.mark.parametrize("case,fixes,pair,suffix,claims", [
    ("pairs of the pair style", ["all viscous/relative J 20"], "morse/spline cut 1.3", None, 1),
    ("kappa", ["all viscous/relative J 20"], "morse/spline cut 1.3", None, 1),
    ("two fixes: the first", ["all viscous/relative J 20", "all viscous/relative gamma 1.0"],
     "morse/spline cut 1.3", None, 1),
    ("a group", ["half viscous/relative J 20"], "morse/spline cut 1.3", None, 0),
    ("cutoff keyword", ["all viscous/relative gamma 1.0 cutoff 1.2"], "morse/spline cut 1.3",
     None, 0),
    ("link L", ["all viscous/relative J 20"], "morse/spline cut 1.3 link 1.2", None, 0),
    ("chain N", ["all viscous/relative J 20"], "morse/spline cut 1.3 chain 2", None, 0),
    ("/omp", ["all viscous/relative J 20"], "morse/spline cut 1.3", "omp", 1),
    ("hybrid", ["all viscous/relative gamma 1.0"], "hybrid/overlay morse/spline cut 1.3 zero 1.3",
     None, 0),
])
def test_the_pair_pass_takes_the_damping_only_where_its_pairs_are_the_fixs(tmp_path, case, fixes,
                                                                          pair, suffix, claims):
    log = tmp_path / "log.claim"
    with session() as lmp:
        lmp.command(f"log {log}")
        if suffix:
            lmp.commands_list([f"suffix {suffix}", "package omp 1"])
        fcc_block(lmp, noise=0.05, temp=0.3)
        coeff = "* * morse/spline 1.0 6.0 1.0\npair_coeff * * zero" if "hybrid" in pair else \
            "* * 1.0 6.0 1.0" + (" kappa 1.05" if case == "kappa" else "")
        lmp.commands_list(["region half block 0 2 INF INF INF INF", "group half region half",
                           f"pair_style {pair}", *[f"pair_coeff {c}" for c in coeff.split("\npair_coeff ")],
                           "timestep 0.002", "fix nve all nve",
                           *[f"fix damp{k} {f}" for k, f in enumerate(fixes)],
                           "run 20 post no"])
        lmp.command("log none")
        removed = [lmp.extract_fix(f"damp{k}", 0, 0) for k in range(len(fixes))]
    text = log.read_text()
    assert text.count(FUSED) == claims, case
    if claims:
        style = "morse/spline/omp" if suffix else "morse/spline"
        assert f"Fix viscous/relative damp0: damping summed in pair {style}'s force pass" in text
    assert all(e > 0 for e in removed)


def test_the_pass_follows_unfix_and_a_new_pair_style(tmp_path):
    """The pair style's slot is cleared at each init and by the fix's deletion: after unfix, a
    run is undamped (its energy conserved as plain NVE's); a new pair style is claimed anew."""
    log = tmp_path / "log.sequence"
    with session() as lmp:
        lmp.command(f"log {log}")
        fcc_block(lmp, noise=0.05, temp=0.3)
        lmp.commands_list(["pair_style morse/spline cut 1.3", "pair_coeff * * 1.0 6.0 1.0",
                           "pair_modify shift yes", "timestep 0.002", "fix nve all nve",
                           "thermo_style custom step etotal", "fix damp all viscous/relative J 5",
                           "run 100 post no", "unfix damp", "run 0 post no"])
        e0 = lmp.get_thermo("etotal")
        lmp.command("run 200 post no")
        undamped_drift = abs(lmp.get_thermo("etotal") - e0) / abs(e0)
        lmp.commands_list(["pair_style lj/spline cut 1.3", "pair_coeff * * 1.0 1.0",
                           "fix damp2 all viscous/relative J 5", "run 100 post no"])
        removed = lmp.extract_fix("damp2", 0, 0)
        lmp.command("log none")
    text = log.read_text()
    assert undamped_drift < 1e-4
    assert removed > 0
    assert "damp: damping summed in pair morse/spline's" in text
    assert "damp2: damping summed in pair lj/spline's" in text


@pytest.mark.parametrize("units", ["lj", "si"])
def test_under_fix_adapt_the_damping_follows_the_pairs_cutoffs_and_stiffness(tmp_path, units):
    """fix adapt setting a = 0.95 (pair_coeff 1.0, in lattice units) damps as pair_coeff a =
    0.95 does: the fix's range (Rc a, weight dpd) and C (J) are the pair's at each step, not
    those at init.  Under fix adapt the pass is not taken (its tables would be read before the
    change); a ramp of a gives the same run with energy tallies on every step as with none."""
    unit = 1.0 if units == "lj" else 1.0e-5
    fix = "fix damp all viscous/relative J 20 mode normal weight dpd"
    adapt = [f"fix ad all adapt 1 pair morse/spline a * * v_aa"]
    runs = {}
    for case, a_scale, extra, thermo in [
            ("coeff", 0.95, [], 200),
            ("adapt", 1.0, [f"variable aa equal {0.95 * unit!r}"] + adapt, 200),
            ("ramp1", 1.0, [f"variable aa equal {unit!r}*(1.0-0.1*step/200)"] + adapt, 1),
            ("ramp200", 1.0, [f"variable aa equal {unit!r}*(1.0-0.1*step/200)"] + adapt, 200)]:
        with session() as lmp:
            _, v, removed = damped_run(lmp, tmp_path / f"log.{case}", fix, thermo, units=units,
                                       a_scale=a_scale, extra=extra)
        runs[case] = (v, removed)
    for a, b in [("coeff", "adapt"), ("ramp1", "ramp200")]:
        (v1, e1), (v2, e2) = runs[a], runs[b]
        assert e1 > 0
        assert e2 == pytest.approx(e1, rel=1e-10), (a, b)
        assert np.max(np.abs(v2 - v1)) <= 1e-10 * np.max(np.abs(v1)), (a, b)
    # the ramp damps differently from the fixed a (not a vacuous comparison)
    assert runs["ramp1"][1] != pytest.approx(runs["adapt"][1], rel=1e-3)
    for case in runs:
        assert (FUSED in (tmp_path / f"log.{case}").read_text()) == (case == "coeff"), case


def test_under_fix_adapt_the_stability_check_sees_the_adapted_stiffness():
    """kappa 2 (C x 4) makes J 0.5 unstable at this step: pair_coeff kappa 2 and fix adapt
    setting kappa 2 stop with the same error (the check runs after adapt's change)."""
    messages = []
    for kappa, adapt in [("2.0", []), ("1.0", ["variable k equal 2.0",
                                                "fix ad all adapt 1 pair morse/spline kappa * * v_k"])]:
        with session() as lmp:
            fcc_block(lmp)
            lmp.commands_list(["pair_style morse/spline cut 1.3",
                               f"pair_coeff * * 1.0 6.0 1.0 kappa {kappa}", "timestep 0.004",
                               "fix nve all nve", "fix damp all viscous/relative J 0.5"] + adapt)
            with pytest.raises(Exception) as err:
                lmp.command("run 10 post no")
            messages.append(str(err.value))
    assert "the damping is unstable" in messages[0]
    assert messages[1] == messages[0]


def test_under_a_hybrid_style_and_fix_adapt_the_fixed_cutoffs_are_a_warning(tmp_path):
    """Under pair_style hybrid the damping range and the dust bond distances are the hybrid's
    cutoffs, which fix adapt does not move: both say so (only where a fix adapt exists)."""
    texts = []
    for adapt in ([], ["variable k equal 0.95", "fix ad all adapt 1 pair morse/spline a * * v_k"]):
        log = tmp_path / f"log.{len(adapt)}"
        with session() as lmp:
            lmp.command(f"log {log}")
            fcc_block(lmp)
            lmp.commands_list(["pair_style hybrid/overlay morse/spline cut 1.3 zero 1.3",
                               "pair_coeff * * morse/spline 1.0 6.0 1.0", "pair_coeff * * zero",
                               "compute d all dust", "thermo_style custom step pe c_d[1]",
                               "fix nve all nve", "fix damp all viscous/relative gamma 1.0"]
                              + adapt + ["run 5 post no"])
            lmp.command("log none")
        texts.append(log.read_text())
    for text, warned in zip(texts, (False, True)):
        assert ("WARNING: Fix viscous/relative: under pair_style hybrid/overlay the damping range "
                "is the hybrid's cutoffs" in text) == warned
        assert ("WARNING: Compute dust: under pair_style hybrid/overlay the bond distances are "
                "the hybrid's cutoffs" in text) == warned


def test_a_pair_style_line_that_sets_chain_between_runs_leaves_the_damping_to_the_fix(tmp_path):
    """Re-issuing the style with chain N keeps the pair style (and its pass slot) without a new
    init when the run says pre no: the chain kernel does not damp, so the fix's own loop must
    (thermo 1 and thermo 20 give the same run; was: the damping lost on the fused steps)."""
    runs = {}
    for thermo in (1, 20):
        with session() as lmp:
            fcc_block(lmp, noise=0.05, temp=0.3)
            lmp.commands_list(["pair_style morse/spline cut 1.3", "pair_coeff * * 1.0 6.0 1.0",
                               "timestep 0.002", "fix nve all nve",
                               "fix damp all viscous/relative J 20", f"thermo {thermo}",
                               "run 50 post no", "pair_style morse/spline cut 1.3 chain 1",
                               "pair_coeff * * 1.0 6.0 1.0", "run 20 pre no post no"])
            ids = np.array(lmp.gather_atoms("id", 0, 1))
            runs[thermo] = (arrays(lmp, "v")[np.argsort(ids)], lmp.extract_fix("damp", 0, 0))
    (v1, e1), (v2, e2) = runs[1], runs[20]
    assert e2 == pytest.approx(e1, rel=1e-10)
    assert np.max(np.abs(v2 - v1)) <= 1e-10 * np.max(np.abs(v1))


def test_rerun_removes_no_energy(tmp_path):
    """rerun evaluates forces on stored snapshots and calls end_of_step, but integrates
    nothing: the energy the fix reports removed stays 0."""
    dump = tmp_path / "dump.snapshots"
    with session() as lmp:
        fcc_block(lmp, noise=0.05, temp=0.3)
        lmp.commands_list(["pair_style morse/spline cut 1.3", "pair_coeff * * 1.0 6.0 1.0",
                           "timestep 0.002", "fix nve all nve",
                           f"dump d all custom 20 {dump} id type x y z vx vy vz",
                           "run 100 post no", "undump d", "unfix nve",
                           "fix damp all viscous/relative J 20", "thermo 20",
                           "thermo_style custom step pe f_damp",
                           f"rerun {dump} dump x y z vx vy vz"])
        removed = lmp.extract_fix("damp", 0, 0)
        nsnap = dump.read_text().count("ITEM: TIMESTEP")
    assert nsnap == 6
    assert removed == 0.0


# --- per-atom masses of ghost atoms ----------------------------------------------------------

@pytest.mark.parametrize("options", ["gamma 2.0", "J 5"])
def test_per_atom_masses_without_ghost_communication_are_an_error(options):
    """fix property/atom rmass, ghost no (its default): the ghosts' masses are 0 or stale, so
    the pairs with a ghost would get a wrong m_ij (was: G = inf with J, weaker damping with
    gamma).  The fix stops at init and names ghost yes."""
    with session() as lmp:
        fcc_block(lmp, noise=0.05, temp=0.3)
        lmp.commands_list(["fix pa all property/atom rmass", "set type 1 mass 1.0",
                           "pair_style morse/spline cut 1.3", "pair_coeff * * 1.0 6.0 1.0",
                           "fix nve all nve", f"fix damp all viscous/relative {options}"])
        with pytest.raises(Exception, match="Fix viscous/relative: fix pa property/atom rmass "
                           "needs ghost yes"):
            lmp.command("run 10 post no")


@pytest.mark.parametrize("units", ["lj", "si"])
@pytest.mark.parametrize("options", ["gamma 2.0 mode normal", "J 5"])
def test_per_atom_masses_with_ghost_yes_damp_as_the_same_per_type_masses(tmp_path, units,
                                                                        options):
    """fix property/atom rmass ghost yes holding each atom's type mass (two types, masses m and
    2m) gives the run of per-type masses to round-off (the fix's general loop against the pair
    style's pass)."""
    if units == "si":
        options = options.replace("gamma 2.0", "gamma 1e8")
    masses = {"lj": (1.0, 2.0), "si": (2.338e-12, 4.676e-12)}[units]
    per_atom = ["fix pa all property/atom rmass ghost yes",
                f"set type 1 mass {masses[0]!r}", f"set type 2 mass {masses[1]!r}"]
    runs = []
    for extra in ([], per_atom):
        with session() as lmp:
            runs.append(damped_run(lmp, tmp_path / "log", f"fix damp all viscous/relative {options}",
                                   200, units=units, extra=extra))
    (x1, v1, e1), (x2, v2, e2) = runs
    assert e1 > 0
    assert e2 == pytest.approx(e1, rel=1e-11)
    assert np.max(np.abs(v2 - v1)) <= 1e-11 * np.max(np.abs(v1))
    assert np.max(np.abs(x2 - x1)) <= 1e-11 * np.max(np.abs(x1))


# --- a run split in two ----------------------------------------------------------------------

def split_scene(lmp, units, damping):
    """The hot two-type block with one of: fix J 5 (mode full) on morse/spline; the force of
    pair dpd/tstat at zero temperature from the fix (mode normal weight dpd) on pair morse; or
    pair dpd/tstat itself.  Returns the time step, the lattice's a and the damping rate G."""
    coeff, dt, a = hot_block(lmp, units)
    rate = 1.5 if units == "lj" else 1.5e8
    rc = 1.3 * a
    if damping == "J":
        pair = ["pair_style morse/spline cut 1.3", f"pair_coeff * * {coeff}",
                "fix damp all viscous/relative J 5"]
    elif damping == "fix dpd":
        pair = [f"pair_style morse {rc!r}", f"pair_coeff * * {coeff}",
                f"fix damp all viscous/relative gamma {rate!r} mode normal weight dpd cutoff {rc!r}"]
    else:  # F = -gamma w (dv . e) e with gamma = m G: per type pair, m = m_ij
        m = [1.0, 2.0] if units == "lj" else [2.338e-12, 4.676e-12]
        mij = lambda i, j: 2 * m[i] * m[j] / (m[i] + m[j])
        pair = ["comm_modify vel yes",
                f"pair_style hybrid/overlay morse {rc!r} dpd/tstat 0 0 {rc!r} 4242",
                f"pair_coeff * * morse {coeff}"] + [
                    f"pair_coeff {i + 1} {j + 1} dpd/tstat {mij(i, j) * rate!r}"
                    for i in range(2) for j in range(i, 2)]
    lmp.commands_list(pair + [f"timestep {dt}", "fix nve all nve"])
    return dt, a, rate


def split_runs(units, damping, pre="yes"):
    """Forces and velocities (by ID) after run 200 and after run 100 + run 100 pre `pre`."""
    out = []
    for runs in (["run 200 post no"], ["run 100 post no", f"run 100 pre {pre} post no"]):
        with session() as lmp:
            split_scene(lmp, units, damping)
            lmp.commands_list(runs)
            out.append(by_id(lmp, "f", "v") + [lmp.extract_fix("damp", 0, 0)
                                                if damping != "dpd/tstat" else 0.0])
    return out


def rel_diff(a, b):
    return np.max(np.abs(a - b)) / np.max(np.abs(a))


@pytest.mark.parametrize("units", ["lj", "si"])
def test_each_run_setup_damps_the_full_step_velocities(units):
    """The cause of a split run's difference: the setup of run 2 computes the forces of step
    100 again, now from v(100) where step 100 of the run had v(99.5) = v(100) - (dt/2) f/m.
    The damping is linear in the velocities, so the setup's forces exceed the step's by the
    damping of (dt/2) f/m: here from the closed form (J: G_ij = sqrt(C/m_ij)/J, C = 2 D
    alpha^2, mode full over the pairs inside 1.3 a; measured: 1.3 % (lj), 2.7 % (si) of the
    largest force)."""
    with session() as lmp:
        dt, a, _ = split_scene(lmp, units, "J")
        lmp.command("run 100 post no")
        f_step, x = by_id(lmp, "f", "x")
        ty = np.array(lmp.gather_atoms("type", 0, 1))[np.argsort(lmp.gather_atoms("id", 0, 1))]
        lo, hi = lmp.extract_box()[:2]
        box = np.array(hi) - np.array(lo)
        lmp.command("run 0 post no")
        (f_setup,) = by_id(lmp, "f")
    m = (np.array([1.0, 2.0]) if units == "lj" else np.array([2.338e-12, 4.676e-12]))[ty - 1]
    d, alpha = (1.0, 6.0) if units == "lj" else (2.46e-6, 3.76e5)
    dv = 0.5 * dt * f_step / m[:, None]
    sep = x[:, None, :] - x[None, :, :]
    sep -= box * np.round(sep / box)
    bonded = (np.sum(sep ** 2, axis=2) < (1.3 * a) ** 2) & ~np.eye(len(x), dtype=bool)
    mij = 2 * m[:, None] * m[None, :] / (m[:, None] + m[None, :])
    friction = np.where(bonded, mij * np.sqrt(2 * d * alpha ** 2 / mij) / 5.0, 0.0)
    expected = -(friction.sum(axis=1)[:, None] * dv - friction @ dv)
    assert np.max(np.abs(expected)) > 1e-3 * np.max(np.abs(f_step))  # visible, not round-off
    assert np.max(np.abs(f_setup - f_step - expected)) <= 1e-9 * np.max(np.abs(expected)), \
        rel_diff(expected, f_setup - f_step)


@pytest.mark.parametrize("units", ["lj", "si"])
def test_a_split_run_parts_from_the_straight_one_as_pair_dpd_tstats_does(units):
    """run 100 + run 100 against run 200: the fix with pair dpd/tstat's force parts by exactly
    as much as pair dpd/tstat itself (which also damps v(100) at the second setup: the two
    differences agree to 3e-10), and J 5 within the bound doc/fix_viscous_relative.rst states.
    Measured after the 100 more steps, of the largest force: dpd/tstat 5.3e-6 (lj), 2.6e-4
    (si); J 5 8.3e-5 (lj), 6.2e-4 (si)."""
    parts = {}
    for damping in ("fix dpd", "dpd/tstat", "J"):
        (f1, v1, _), (f2, v2, _) = split_runs(units, damping)
        parts[damping] = (rel_diff(f1, f2), rel_diff(v1, v2))
    assert parts["dpd/tstat"][0] > 1e-7  # the split is visible (undamped: 2e-14)
    assert parts["fix dpd"] == pytest.approx(parts["dpd/tstat"], rel=1e-7)
    assert parts["J"][0] <= {"lj": 2e-4, "si": 1.5e-3}[units], parts


@pytest.mark.parametrize("units", ["lj", "si"])
@pytest.mark.parametrize("damping", ["J", "fix dpd"])
def test_run_pre_no_continues_the_straight_run_exactly(units, damping):
    """run 100 + run 100 pre no skips the second setup: the straight run, to the last bit
    (forces, velocities, energy removed)."""
    (f1, v1, e1), (f2, v2, e2) = split_runs(units, damping, pre="no")
    assert e1 > 0 and e2 == e1
    assert np.array_equal(f1, f2) and np.array_equal(v1, v2)


def test_normal_mode_skips_coincident_atoms_without_nan():
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 4 0 4 0 4", "create_box 1 box",
                           "mass 1 1.0", "neighbor 0.3 bin", "create_atoms 1 single 1.0 1.0 1.0",
                           "create_atoms 1 single 1.0 1.0 1.0", "create_atoms 1 single 1.5 1.0 1.0",
                           "pair_style zero 1.0", "pair_coeff * *", "set atom 1 vx 1.0",
                           "set atom 2 vx -1.0", "set atom 3 vx 0.5", "fix nve all nve",
                           "fix d all viscous/relative gamma 0.5 mode normal", "timestep 0.001",
                           "run 10 post no"])
        v = np.array(lmp.gather_atoms("v", 1, 3)).reshape(-1, 3)
        removed = lmp.numpy.extract_fix("d", 0, 0)
    assert np.all(np.isfinite(v)) and np.isfinite(removed)
    assert v.sum(axis=0) == pytest.approx([0.5, 0, 0], abs=1e-14)    # momentum conserved
    assert v[2, 0] < 0.5 and removed > 0    # the pairs with a normal are damped


def test_respa_is_refused():
    # with a stock pair style: the spline styles refuse respa themselves
    # (test_pair_spline_errors.py)
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 4 0 4 0 4", "create_box 1 box",
                           "mass 1 1.0", "neighbor 0.3 bin", "create_atoms 1 single 1.0 1.0 1.0",
                           "pair_style morse 1.2", "pair_coeff 1 1 1.0 6.0 1.0", "fix nve all nve",
                           "fix d all viscous/relative gamma 0.5", "run_style respa 2 2"])
        with pytest.raises(Exception, match="does not support run_style respa"):
            lmp.command("run 1")


def test_its_own_cutoff_checks_the_neighbor_skin():
    """the default skin of units si (1 mm) at cluster scale, with the fix's own cutoff"""
    with session() as lmp:
        lmp.commands_list(SI_CLUSTERS + ["pair_style zero 1.2e-5", "pair_coeff * *",
                                         "neighbor 1e-3 bin",
                                         "fix d all viscous/relative gamma 1e6 cutoff 1.2e-5",
                                         "fix nve all nve"])
        with pytest.raises(Exception, match="Fix viscous/relative: neighbor skin"):
            lmp.command("run 0")


# ---------------------------------------------------------------- pairs held by link L

DIMER_UNITS = {"lj": (1.0, 1.0, 1.0, 0.001), "metal": (0.3429, 2.866, 26.98, 0.0005)}    # D a m dt


def dimer_ke(style, r, v, units="lj", steps=40, damp="gamma 5.0"):
    """ke after `steps` of two atoms r a apart moving with -v and +v (a per time unit) along
    their axis, Morse alpha a = 6 in the given unit style."""
    d, a, m, dt = DIMER_UNITS[units]
    rate = float(damp.split()[1]) / (1.0 if units == "lj" else 0.1)    # G per time unit
    with session() as lmp:
        lmp.commands_list([f"units {units}",
                           f"region box block {-5 * a} {5 * a} {-5 * a} {5 * a} {-5 * a} {5 * a} units box",
                           "create_box 1 box", f"mass 1 {m}", "create_atoms 1 single 0 0 0 units box",
                           f"create_atoms 1 single {r * a} 0 0 units box", f"pair_style {style}",
                           f"pair_coeff * * {d} {6.0 / a} {a}", f"neighbor {0.3 * a} bin",
                           "group one id 1", "group two id 2",
                           f"velocity one set {-v * a} 0 0 units box",
                           f"velocity two set {v * a} 0 0 units box",
                           "fix 1 all nve", f"fix 2 all viscous/relative gamma {rate}",
                           f"timestep {dt}", "thermo_modify norm no", "run 0"])
        ke0 = lmp.get_thermo("ke")
        lmp.command(f"run {steps}")
        return ke0, lmp.get_thermo("ke"), lmp.get_thermo("pe")


@pytest.mark.parametrize("units", list(DIMER_UNITS))
def test_viscous_relative_leaves_unlinked_pairs_alone(units):
    # 1.2 a apart: beyond L a = 1.05 a (never linked), inside Rc a = 1.3 a; moving apart
    ke0, ke, pe = dimer_ke("morse/spline cut 1.3 link 1.05", 1.2, 0.1, units)
    assert pe == 0 and ke == ke0    # no force, no damping: free flight
    ke0_d, ke_d, pe_d = dimer_ke("morse/spline cut 1.3", 1.2, 0.1, units)
    assert pe_d < 0 and ke_d != ke0_d    # by distance the same pair is bonded: it interacts


@pytest.mark.parametrize("units", list(DIMER_UNITS))
def test_viscous_relative_damps_linked_pairs_as_distance_bonds(units):
    a = dimer_ke("morse/spline cut 1.3 link 1.05", 1.0, 0.05, units)
    b = dimer_ke("morse/spline cut 1.3", 1.0, 0.05, units)
    assert a[1] < 0.9 * a[0] and a[1] == pytest.approx(b[1], rel=1e-12)


def test_viscous_relative_cutoff_does_not_apply_under_link():
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block -5 5 -5 5 -5 5", "create_box 1 box",
                           "mass 1 1.0", "create_atoms 1 single 0 0 0",
                           "pair_style morse/spline cut 1.3 link 1.05", "pair_coeff * * 1.0 6.0 1.0",
                           "fix 2 all viscous/relative gamma 1.0 cutoff 1.2"])
        with pytest.raises(Exception, match="keyword cutoff does not apply under a pair style "
                                            "with link L"):
            lmp.command("run 0")


# ---------------------------------------------------------------- hostile input

INPUTS = InputTable()
row = INPUTS.row
row("nobox-fix-viscous", SCENE_NOBOX, "fix v all viscous/relative gamma 1.0",
    "Fix viscous/relative command before simulation box is defined")
V = "fix v all viscous/relative "
for rid, args, expect, defect in [
    ("no-args", "", r"expected fix ID group viscous/relative gamma G \| J J", None),
    ("gamma-nothing", "gamma", r"expected fix ID group viscous/relative", None),
    ("style-G", "G 1.0", r"unknown style 'G' \(expected gamma or J\)", None),
    ("gamma-abc", "gamma abc", r"gamma.*abc", None),
    ("gamma-nan", "gamma nan", r"gamma.*nan", None),
    ("gamma-inf", "gamma inf", r"gamma.*inf", None),
    ("gamma-1e309", "gamma 1e309", r"gamma.*1e309", None),
    ("gamma--0", "gamma -0", r"gamma must be > 0 \(got -0\)", None),
    ("gamma-0", "gamma 0", r"gamma must be > 0 \(got 0\)", None),
    ("J--1", "J -1", r"J must be > 0 \(got -1\)", None),
    ("mode-sideways", "gamma 1.0 mode sideways", r"unknown mode 'sideways'", None),
    ("mode-nothing", "gamma 1.0 mode", r"keyword mode needs a value", None),
    ("weight-bogus", "gamma 1.0 weight gauss", r"unknown weight 'gauss'", None),
    ("weight-twice", "gamma 1.0 weight dpd weight none", r"keyword weight given twice", None),
    ("mode-twice", "gamma 1.0 mode full mode normal", r"keyword mode given twice", None),
    ("cutoff-0", "gamma 1.0 cutoff 0", r"cutoff must be > 0 \(got 0\)", None),
    ("cutoff--1", "gamma 1.0 cutoff -1", r"cutoff must be > 0 \(got -1\)", None),
    ("cutoff-abc", "gamma 1.0 cutoff abc", r"cutoff.*abc", None),
    ("unknown-keyword", "gamma 1.0 foo 1", r"unknown keyword 'foo'", None),
    ("wrong-order", "mode normal gamma 1.0", r"unknown style 'mode'", None),
    ("extra-number", "gamma 1.0 2.0", r"unknown keyword '2.0'|extra argument '2.0'",
     None),
]:
    row(f"viscous-{rid}", SCENE_MORSE, V + args, expect, defect)

row("viscous-cutoff-1e300", SCENE_MORSE, V + "gamma 1.0 cutoff 1e300", r"ghost")
row("viscous-J-stock-pair", scene_dimer(), ["pair_style lj/cut 1.5", "pair_coeff * * 1.0 1.0",
                                            V + "J 50"], r"J .*(stiffness|C\b)")
row("viscous-no-pair", scene_dimer(), [V + "gamma 1.0"], r"viscous/relative.*pair style")
row("viscous-no-pair-cutoff", scene_dimer(), [V + "gamma 1.0 cutoff 1.2"], r"ghost|cutoff")
row("viscous-empty-group", SCENE_MORSE, ["group none empty", "fix v none viscous/relative gamma 1.0"],
    OK)
row("viscous-zero-atoms", SCENE_BOX + scene_pair("morse/spline"), [V + "J 50"], OK)
row("viscous-respa", scene_dimer(), ["pair_style lj/cut 1.5", "pair_coeff * * 1.0 1.0",
                                     "run_style respa 2 2", V + "gamma 1.0"],
    r"[Ff]ix viscous/relative.*respa")
row("viscous-J-tiny", SCENE_MORSE, ["velocity all create 0.1 4711", "fix n all nve", V + "J 1e-300",
                                    "timestep 0.001", "run 5 post no"],
    r"viscous/relative.*(J|G|time step|stab)", None,
    isolate=True)
row("viscous-gamma-huge", SCENE_MORSE, ["velocity all create 0.1 4711", "fix n all nve",
                                        V + "gamma 1e300", "timestep 0.001", "run 5 post no"],
    r"viscous/relative: G x bonds x dt = 1e\+300", None, isolate=True)
row("viscous-J-huge", SCENE_MORSE, ["velocity all create 0.1 4711", "fix n all nve", V + "J 1e300",
                                    "run 5 post no"], OK)
row("viscous-normal-overlap", scene_dimer(r=0.0), ["pair_style zero 1.5", "pair_coeff * *",
                                                   "velocity all create 0.1 4711", "fix n all nve",
                                                   V + "gamma 1.0 mode normal cutoff 1.2",
                                                   "run 5 post no"], OK)
# LAMMPS: "it is an error to use pre no" after a change; the fix has no forces of the step
# before to kick with (was a crash: fd never allocated)
row("viscous-minimize-then-run-pre-no", SCENE_MORSE,
    ["fix n all nve", V + "J 50", "minimize 0 1e-8 20 40", "run 10 pre no"],
    r"no damping forces of step \d+ for its second half kick: run \.\.\. pre no", isolate=True)
for u in SCENE_UNITS:
    row(f"viscous-units-{u}", scene_unit_dimer(u, "morse/spline"), ["fix n all nve", V + "J 50",
                                                                    "run 3 post no"], OK)
row("viscous-fix_modify", SCENE_MORSE, ["velocity all create 0.1 4711", "fix n all nve",
                                        V + "gamma 1.0", "fix_modify v energy yes virial yes",
                                        "run 5 post no"], OK)
row("viscous-omp", scene_dimer(omp=True) + scene_pair("morse/spline", omp=True),
    ["fix n all nve", V + "gamma 1.0 mode normal weight dpd", "run 3 post no"], OK)
row("viscous-mode-twice-empty-box", SCENE_EMPTY, V + "gamma 1.0 mode normal mode full",
    "keyword mode given twice")


@pytest.mark.parametrize("setup,cmds,expect,isolate", INPUTS.rows)
def test_hostile_input(setup, cmds, expect, isolate):
    check_input(setup, cmds, expect, isolate)


# ---------------------------------------------------------------- per atom, an accelerating body

def morse_forces(x, types, box, law, cut):
    """Per-atom forces of the kappa-modified Morse laws (cut tail) of each type pair."""
    from test_pair_spline_types import PAIRS, morse_np, pairs_within
    i, j, d, r, k = pairs_within(x, types, box, max(cut.values()))
    keep = r < np.array([cut[PAIRS[q]] for q in k])
    i, j, d, r, k = i[keep], j[keep], d[keep], r[keep], k[keep]
    fpair = np.zeros(len(r))
    for q, p in enumerate(PAIRS):
        fpair[k == q] = morse_np(r[k == q], law[p])[1] / r[k == q]
    f = np.zeros_like(x)
    np.add.at(f, i, d * fpair[:, None])
    np.add.at(f, j, -d * fpair[:, None])
    return f, (i, j, d, r, k)


def damping_closed_form(v, masses, pairs, cut, law, options, ftm2v):
    """doc/fix_viscous_relative.rst: F_i = -F_j = -m_ij G_ij w(r) dv / ftm2v on each pair inside
    its type pair's cutoff, G_ij = gamma or sqrt(ftm2v C_ij / m_ij) / J, C_ij = 2 (kappa alpha)^2
    D of the pair's law."""
    from test_pair_spline_types import PAIRS
    i, j, d, r, k = pairs
    words = options.split()
    mij = 2 * masses[i] * masses[j] / (masses[i] + masses[j])
    if words[0] == "J":
        c = np.array([2 * (law[PAIRS[q]].kappa * law[PAIRS[q]].alpha) ** 2 * law[PAIRS[q]].D
                      for q in k])
        rate = np.sqrt(ftm2v * c / mij) / float(words[1])
    else:
        rate = np.full(len(r), float(words[1]))
    coef = mij * rate / ftm2v
    if "dpd" in words:
        coef = coef * (1 - r / np.array([cut[PAIRS[q]] for q in k])) ** 2
    dv = v[i] - v[j]
    if "normal" in words:
        dv = d * ((dv * d).sum(axis=1) / (r * r))[:, None]
    fd = np.zeros_like(v)
    np.add.at(fd, i, -coef[:, None] * dv)
    np.add.at(fd, j, coef[:, None] * dv)
    return fd


@pytest.mark.parametrize("path", ["own loop", "pair pass"])
@pytest.mark.parametrize("options", ["J 20", "J 20 mode normal weight dpd", "gamma G mode normal",
                                     "gamma G weight dpd"])
@pytest.mark.parametrize("units", ["lj", "si"])
def test_an_accelerating_three_type_block_is_damped_per_atom_as_the_closed_form(
        tmp_path, units, options, path):
    """A hot block of three types (masses m, 1.5 m, 2.5 m) under morse/spline with its own D, a,
    kappa and rc for each type pair, pulled apart by fix addforce (type 2 along +x, type 3 along
    -x): the relative velocities grow, unevenly.  At a step with no output the forces, velocities
    and positions of each atom (dump, 17 digits) give the damping force, f - f_pair - f_push,
    atom by atom equal to the closed form at the half-step velocities v - (dt/2) ftm2v f / m that
    the force was computed from, each pair damped inside its own type pair's cutoff with its own
    m_ij and C_ij; the fix's own loop (thermo every step) and the pair style's pass (thermo only
    at the ends) alike."""
    from test_pair_spline_types import CASES, PAIRS, RC, UNITS, block, laws
    s, e, mass = UNITS[units]
    dt = 0.002 if units == "lj" else 2e-10
    gamma = 2.0 if units == "lj" else 1e8
    options = options.replace("G", repr(gamma))
    push = 2.0 * e / s
    case = CASES[0]    # morse/spline cut 1.2, per-pair rc and kappa
    log = tmp_path / "log.lammps"
    with session("-log", str(log)) as lmp:
        lmp.commands_list(block(units) + case.ours(units) + [
            f"velocity all create {0.3 if units == 'lj' else 1e16} 4712 loop geom",
            f"variable fx atom {push!r}*((type==2)-(type==3))",
            "fix push all addforce v_fx 0.0 0.0", "fix nve all nve",
            f"fix damp all viscous/relative {options}", f"timestep {dt!r}",
            f"thermo {1 if path == 'own loop' else 1000}",
            f"dump d all custom 7 {tmp_path / 'atoms.txt'} id type x y z vx vy vz fx fy fz",
            "dump_modify d sort id format float %.17g", "run 10 post no"])
        ftm2v = lmp.extract_global("ftm2v")
        lo, hi = lmp.extract_box()[:2]
    assert FUSED in log.read_text()    # offered; thermo 1 leaves it untaken (energy each step)
    text = (tmp_path / "atoms.txt").read_text().split("ITEM: TIMESTEP\n")
    step7 = [t for t in text if t.startswith("7\n")][0]
    rows = np.loadtxt(step7.splitlines()[8:])
    types = rows[:, 1].astype(int)
    x, v, f = rows[:, 2:5], rows[:, 5:8], rows[:, 8:11]
    box = np.array(hi) - np.array(lo)
    masses = mass * np.array([0.0, 1.0, 1.5, 2.5])[types]
    law = laws("morse", units)
    cut = {p: (RC[q] or 1.2) * law[p].a for q, p in enumerate(PAIRS)}
    f_pair, pairs = morse_forces(x, types, box, law, cut)
    f_push = np.zeros_like(f)
    f_push[:, 0] = push * ((types == 2).astype(float) - (types == 3))
    f_damp = f - f_pair - f_push
    v_half = v - 0.5 * dt * ftm2v * f / masses[:, None]
    expect = damping_closed_form(v_half, masses, pairs, cut, law, options, ftm2v)
    scale = np.max(np.abs(expect))
    assert scale > 1e-3 * np.max(np.abs(f_pair))
    assert np.max(np.abs(f_damp - expect)) <= 1e-9 * scale, np.max(np.abs(f_damp - expect)) / scale
    # what the test tells apart: the full-step velocities, or one cutoff for all type pairs
    wrong_v = damping_closed_form(v, masses, pairs, cut, law, options, ftm2v)
    assert np.max(np.abs(wrong_v - expect)) > 1e-4 * scale
    one_cut = {p: cut[(1, 1)] for p in PAIRS}
    _, pairs_one = morse_forces(x, types, box, law, one_cut)
    wrong_cut = damping_closed_form(v_half, masses, pairs_one, one_cut, law, options, ftm2v)
    assert np.max(np.abs(wrong_cut - expect)) > 1e-3 * scale


# ---------------------------------------------------------------- the exact Verlet recurrence

EXACT_UNITS = ["lj", "real", "metal", "si", "cgs", "electron", "micro", "nano"]


@pytest.mark.parametrize("damping", ["gamma", "J"])
@pytest.mark.parametrize("units", EXACT_UNITS)
def test_a_dimer_follows_the_damped_verlet_recurrence_exactly(units, damping):
    """Two atoms of masses 2 and 3 along x, moving apart and accelerating (gamma: no pair force;
    J: harmonic/spline, alpha a = 6, D = 1, a = 1, kappa 1.1, its C = 2 (kappa alpha)^2 D).
    Velocity Verlet with the damping at the half-step velocities (doc/fix_viscous_relative.rst)
    is a linear recurrence: written out here step by step with LAMMPS's ftm2v, it gives the
    positions and velocities after 400 steps, and the energy removed as the sum of each half
    kick's (dt/4) F . (v_before + v_after), to 1e-10 (the units test reads exp(-2 G t) at 2e-3)."""
    m = np.array([2.0, 3.0])
    mij = 2 * m[0] * m[1] / (m[0] + m[1])
    kappa, alpha, depth = 1.1, 6.0, 1.0
    c = 2 * (kappa * alpha) ** 2 * depth
    with session() as lmp:
        lmp.commands_list([f"units {units}", "atom_modify map array", "boundary f f f",
                           "region box block -4 8 -4 4 -4 4", "create_box 2 box", "mass 1 2.0",
                           "mass 2 3.0", "neighbor 0.3 bin", "create_atoms 1 single 0 0 0",
                           "create_atoms 2 single 1.02 0 0"])
        ftm2v = lmp.extract_global("ftm2v")
        w0 = math.sqrt(2 * ftm2v * c / mij)    # the pair's angular frequency
        if damping == "gamma":
            rate, dt = w0 / 5, 0.02 / w0
            pair = ["pair_style zero 1.5", "pair_coeff * *"]
            fix = f"gamma {rate!r}"
        else:
            rate, dt = math.sqrt(ftm2v * c / mij) / 5.0, 0.05 / w0
            pair = ["pair_style harmonic/spline cut 1.4",
                    f"pair_coeff * * {depth} {alpha} 1.0 kappa {kappa}"]
            fix = "J 5.0"
        v0 = np.array([-0.6, 0.9]) * w0 * 0.01    # moving apart; momentum not zero
        lmp.commands_list(pair + [f"set atom 1 vx {v0[0]!r}", f"set atom 2 vx {v0[1]!r}",
                                  "fix nve all nve", f"fix d all viscous/relative {fix}",
                                  f"timestep {dt!r}", "run 400 post no"])
        x = lmp.numpy.extract_atom("x")[:2, 0].copy()
        v = lmp.numpy.extract_atom("v")[:2, 0].copy()
        removed = lmp.numpy.extract_fix("d", 0, 0)

    xs, vs = np.array([0.0, 1.02]), v0.copy()

    def force(x_, v_):
        fd = -mij * rate * (v_[1] - v_[0]) / ftm2v    # on atom 2
        fp = -(kappa * alpha) ** 2 * depth * 2 * (x_[1] - x_[0] - 1.0) if damping == "J" else 0.0
        return np.array([-fd - fp, fd + fp]), np.array([-fd, fd])

    tally = 0.0
    f, fd = force(xs, vs)
    for _ in range(400):
        before = vs.copy()
        vs = vs + 0.5 * dt * ftm2v * f / m
        tally -= 0.25 * dt * np.dot(fd, before + vs)    # the second half kick of the last step
        xs = xs + dt * vs
        f, fd = force(xs, vs)
        before = vs.copy()
        vs = vs + 0.5 * dt * ftm2v * f / m
        tally -= 0.25 * dt * np.dot(fd, before + vs)
    assert np.max(np.abs(x - xs)) <= 1e-10 * np.max(np.abs(xs))
    assert np.max(np.abs(v - vs)) <= 1e-10 * np.max(np.abs(v0))
    assert removed > 0 and removed == pytest.approx(tally, rel=1e-10)
    # the relative velocity has moved: 400 steps of damping are visible
    assert abs(vs[1] - vs[0]) < 0.5 * abs(v0[1] - v0[0])
