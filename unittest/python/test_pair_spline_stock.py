"""Spline pair styles against stock LAMMPS styles on a thermalised periodic fcc block
(ghost atoms, periodic images): energy, pressure tensor and forces to round-off."""
import numpy as np
import pytest
from conftest import assert_same_state, fcc_block, session, state

D, ALPHA, A = 1.3, 5.5, 1.0


def compare(stock, ours, shift):
    """Global energy, pressure tensor and forces, and per-atom energy and virial."""
    with session() as lmp:
        fcc_block(lmp)
        lmp.commands_list(["compute epa all pe/atom", "compute spa all stress/atom NULL pair"])
        results, peratom = [], []
        for pair_style, pair_coeff in (stock, ours):
            lmp.commands_list([f"pair_style {pair_style}", f"pair_coeff * * {pair_coeff}",
                               f"pair_modify shift {shift}"])
            results.append(state(lmp))
            peratom.append(np.hstack([np.array(lmp.gather("c_epa", 1, 1)).reshape(-1, 1),
                                      np.array(lmp.gather("c_spa", 1, 6)).reshape(-1, 6)]))
    assert_same_state(*results)
    scale = np.max(np.abs(peratom[0]), axis=0)
    assert np.all(scale > 0)
    assert np.all(np.max(np.abs(peratom[0] - peratom[1]), axis=0) <= 1e-12 * scale)


@pytest.mark.parametrize("shift", ["no", "yes"])
@pytest.mark.parametrize("rc", [1.2, 1.6])
def test_morse_cut_equals_morse(shift, rc):
    compare((f"morse {rc * A}", f"{D} {ALPHA} {A}"), (f"morse/spline cut {rc}", f"{D} {ALPHA} {A}"),
            shift)


@pytest.mark.parametrize("shift", ["no", "yes"])
def test_lj_cut_equals_lj_cut(shift):
    sigma = A * 2 ** (-1 / 6)
    compare((f"lj/cut {1.5 * A}", f"{D} {sigma}"), ("lj/spline cut 1.5", f"{D} {A}"), shift)


@pytest.mark.parametrize("shift", ["no", "yes"])
@pytest.mark.parametrize("n,m", [(12, 6), (9, 4.5), (20, 7)])
def test_mie_cut_equals_mie_cut(shift, n, m):
    sigma = A * (m / n) ** (1 / (n - m))
    compare((f"mie/cut {1.5 * A}", f"{D} {sigma} {n} {m}"), ("mie/spline cut 1.5", f"{D} {A} {n} {m}"),
            shift)


@pytest.mark.parametrize("kappa", [0.8, 1.5])
def test_morse_kappa_equals_morse_with_kappa_alpha(kappa):
    compare((f"morse {1.3 * A}", f"{D} {kappa * ALPHA} {A}"),
            ("morse/spline cut 1.3", f"{D} {ALPHA} {A} kappa {kappa}"), "yes")


def test_mixed_types_and_per_pair_rc():
    """Two types with their own laws and radii against morse with per-pair cutoffs."""
    with session() as lmp:
        fcc_block(lmp, ntypes=2)
        results = []
        lmp.commands_list([f"pair_style morse {1.2 * A}", f"pair_coeff 1 1 {D} {ALPHA} {A}",
                           f"pair_coeff 1 2 0.9 6.0 1.05 {1.4 * 1.05}",
                           f"pair_coeff 2 2 1.1 {ALPHA} 0.95 {1.1 * 0.95}"])
        results.append(state(lmp))
        lmp.commands_list(["pair_style morse/spline cut 1.2", f"pair_coeff 1 1 {D} {ALPHA} {A}",
                           "pair_coeff 1 2 0.9 6.0 1.05 rc 1.4", f"pair_coeff 2 2 1.1 {ALPHA} 0.95 rc 1.1"])
        results.append(state(lmp))
    assert_same_state(*results)
