"""Hard case: a strong shock (u = 10 km/s) in a chain of aluminium clusters, SI units, with
the time step from the shock-stiffened period T_min(u) (spec section 5).  Two half-chains
collide at +-u/2 (no external work), so the total energy is conserved up to the velocity-
Verlet error at dt = T_min(u)/50.  Measured |drift|/KE0 over 1.5 transit times: wagner
1.6e-6, lagunov 4.1e-6, cut 5.1e-5 (the cut's force jumps when bonds break); the bounds
below are about ten times those.  A 20 km/s collision far past the step compute pair/params
suggests is warned once; run 0 (no step) is not."""
import math

import numpy as np
import pytest
from conftest import session

A, ALPHA, D, M = 1.0e-5, 3.76e5, 2.46e-6, 2.338e-12
C0 = ALPHA * A * math.sqrt(2 * D / M)
U = 1.0e4


def t_min(u):
    """T_min(u) = pi a / c(u): c(u) from y + (u/c0)/sqrt(Pi''(ya)/Pi''(a)) = 1 (Morse)."""
    def stiff(y):
        e = math.exp(-ALPHA * A * (y - 1))
        return 2 * e * e - e
    lo, hi = 0.05, 1.0
    for _ in range(200):
        y = 0.5 * (lo + hi)
        if y + (u / C0) / math.sqrt(stiff(y)) - 1 > 0:
            hi = y
        else:
            lo = y
    return math.pi * A / (C0 * math.sqrt(stiff(y)))


@pytest.mark.parametrize("tail,tolerance", [("wagner", 2e-5), ("lagunov 1.3", 4e-5),
                                             ("cut 1.2", 5e-4)])
def test_strong_shock_chain_stays_finite_and_conserves_energy(tail, tolerance):
    dt = t_min(U) / 50
    n = 100
    steps = int(1.5 * n * A / C0 / dt)
    with session() as lmp:
        lmp.commands_list([
            "units si", "atom_modify map array", "boundary m p p",
            f"lattice sc {A}", f"region box block -0.5 {n + 0.5} -5 5 -5 5",
            "create_box 1 box", f"region line block -0.5 {n + 0.5} -0.5 0.5 -0.5 0.5",
            "create_atoms 1 region line", f"mass 1 {M}",
            f"pair_style morse/spline {tail}", f"pair_coeff 1 1 {D} {ALPHA} {A}",
            "pair_modify shift yes",
            f"neighbor {0.2 * A} bin", "neigh_modify every 1 delay 0 check yes",
            f"region left block INF {n / 2 - 0.1} INF INF INF INF",
            "group left region left", "group right subtract all left",
            f"velocity left set {U / 2} 0 0 units box", f"velocity right set {-U / 2} 0 0 units box",
            f"timestep {dt}", "fix 1 all nve", "thermo_style custom step pe ke etotal",
            "run 0 post no"])
        e0 = lmp.get_thermo("etotal")
        ke0 = lmp.get_thermo("ke")
        lmp.command(f"run {steps} post no")
        e1 = lmp.get_thermo("etotal")
        f = np.array(lmp.gather_atoms("f", 1, 3))
        x = np.array(lmp.gather_atoms("x", 1, 3))
    assert np.all(np.isfinite(f)) and np.all(np.isfinite(x))
    assert abs(e1 - e0) <= tolerance * ke0, (e0, e1, ke0)


# the time-step warning (its threshold in every unit style: test_units.py)

# a row of 21 aluminium clusters of the dusting paper (units si)
AL_ROW = ["units si", "boundary f p p", "lattice sc 1e-5", "region box block -2 40 0 1 0 1",
          "create_box 1 box", "region b block 0 20 0 1 0 1", "create_atoms 1 region b",
          "mass 1 2.338e-12", "neighbor 2e-6 bin", "pair_style morse/spline cut 1.2",
          "pair_coeff 1 1 2.46e-6 3.76e5 1e-5"]


def test_strong_shock_far_past_the_suggested_step_warns(tmp_path):
    """A 20 km/s collision of Al clusters (ten on eleven at rest) at 2.7 x the step compute
    pair/params suggests for it: warned once, at the first check that sees the compression
    (not at the run 0 that read the compute, which takes no step)."""
    log = tmp_path / "log.lammps"
    with session("-log", str(log)) as lmp:
        lmp.commands_list(AL_ROW + [
            "compute p all pair/params 1 1 u 20000", "run 0 post no", "variable dt equal 2.7*c_p[1][6]", "timestep ${dt}",
            "group hit id <= 10", "velocity hit set 20000 0 0 units box", "fix nve all nve",
            "run 60 post no"])
    text = log.read_text()
    assert text.count("WARNING: Pair morse/spline: time step") == 1    # once
    assert "exceeds" in text and "reduce the time step" in text


def test_run_0_takes_no_step_and_does_not_warn(tmp_path):
    """run 0, the way to read compute pair/params before choosing the step, runs under
    LAMMPS's default step (1e-8 s in units si, 35 times the suggested one here) without a
    time-step warning: it takes no step.  The first real run checks."""
    log = tmp_path / "log.lammps"
    with session("-log", str(log)) as lmp:
        lmp.commands_list(AL_ROW + ["compute p all pair/params 1 1",
                                    "thermo_style custom step c_p[13]", "run 0 post no"])
        assert "time step" not in log.read_text()
        lmp.commands_list(["fix nve all nve", "run 1 post no"])
    assert log.read_text().count("WARNING: Pair morse/spline: time step") == 1
