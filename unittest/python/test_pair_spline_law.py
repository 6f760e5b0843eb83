"""The force kernel and single() against the spec's closed forms and finite differences:
energy on every branch, force = -dE/dr, continuity at the tail joints, LJ's Wagner cutoff,
single() (pair_write) = compute, born_matrix() = compute born/matrix numdiff."""
import numpy as np
import pytest
from conftest import fcc_block, pair_curve, session
from spec_laws import Law

CASES = [  # law, tail, rc, rs
    (Law("morse", 1.3, 1.0, alpha=6.0), "cut", 1.2, None),
    (Law("morse", 1.3, 1.0, alpha=3.76, kappa=1.3), "wagner", None, None),
    (Law("morse", 1.3, 1.0, alpha=5.0), "lagunov", 1.4, None),
    (Law("lj", 1.3, 1.0), "wagner", None, None),
    (Law("lj", 1.3, 1.0, kappa=1.2), "lagunov", 1.45, None),
    (Law("mie", 1.3, 1.0, n=10, m=5, kappa=0.8), "lagunov", 1.5, 1.08),
    (Law("mie", 1.3, 1.0, n=9, m=6), "wagner", None, None),
    (Law("harmonic", 1.3, 1.0, alpha=5.5), "cut", 1.2, None),
    (Law("harmonic", 1.3, 1.0, alpha=5.5, kappa=1.2), "lagunov", 1.3, 1.1),
]
IDS = [f"{c[0].base}-{c[1]}-k{c[0].kappa}" for c in CASES]


def tail_args(tail, rc, rs):
    return {"cut": f"cut {rc}", "wagner": "wagner",
            "lagunov": f"lagunov {rc}" + (f" start {rs}" if rs else "")}[tail]


def joints(law, tail, rc, rs):
    """(joint, smoothness) pairs: 1 = E and F continuous, 2 = also dF/dr."""
    if tail == "cut":
        return []
    if tail == "wagner":
        b, ac, _, _ = law.wagner()
        return [(b, 2), (ac, 1)]
    return [(rs * law.a if rs else law.b(), 1), (rc * law.a, 1)]


def end(law, tail, rc):
    return law.wagner()[1] if tail == "wagner" else rc * law.a


@pytest.mark.parametrize("law,tail,rc,rs", CASES, ids=IDS)
def test_energy_matches_spec_on_every_branch(law, tail, rc, rs):
    r = np.linspace(0.8 * law.a, end(law, tail, rc) * 1.05, 301)
    r, e, f = pair_curve(f"{law.style()} {tail_args(tail, rc, rs)}", law.coeff(), r)
    expected = np.array([law.energy(tail, x, rc, rs) for x in r])
    assert np.max(np.abs(e - expected)) <= 1e-12 * law.D * np.max(np.abs(expected) / law.D + 1)
    beyond = r >= end(law, tail, rc)
    assert np.any(beyond) and np.all(e[beyond] == 0.0) and np.all(f[beyond] == 0.0)


@pytest.mark.parametrize("law,tail,rc,rs", CASES, ids=IDS)
def test_force_is_minus_energy_derivative(law, tail, rc, rs):
    h = 1e-6 * law.a
    r = np.linspace(0.8 * law.a, end(law, tail, rc) - 2 * h, 200)
    for j, _ in joints(law, tail, rc, rs):  # stay off the joints, where E'' may jump
        r = r[np.abs(r - j) > 2 * h]
    x, e, f = pair_curve(f"{law.style()} {tail_args(tail, rc, rs)}", law.coeff(),
                         np.concatenate([r, r + h, r - h]))
    n = len(r)
    fd = -(e[n:2 * n] - e[2 * n:]) / (x[n:2 * n] - x[2 * n:])
    assert np.max(np.abs(f[:n] - fd)) <= 1e-7 * np.max(np.abs(f[:n]))


@pytest.mark.parametrize("law,tail,rc,rs", CASES, ids=IDS)
def test_continuity_at_tail_joints(law, tail, rc, rs):
    eps, d = 1e-9 * law.a, 1e-4 * law.a
    for j, order in joints(law, tail, rc, rs):
        r = np.array([j - eps, j + eps, j - 2 * d, j - d, j + d, j + 2 * d])
        r, e, f = pair_curve(f"{law.style()} {tail_args(tail, rc, rs)}", law.coeff(), r)
        scale = np.max(np.abs(f)) + law.D / law.a
        assert abs(e[1] - e[0]) <= 1e-7 * law.D, (j, e)
        assert abs(f[1] - f[0]) <= 1e-6 * scale, (j, f)
        if order == 2:  # second-order one-sided slopes of F agree to O(d^2)
            left = (3 * (f[0] + f[1]) / 2 - 4 * f[3] + f[2]) / (2 * d)
            right = (-3 * (f[0] + f[1]) / 2 + 4 * f[4] - f[5]) / (2 * d)
            assert abs(left - right) <= 1e-4 * scale / law.a, (j, left, right)


def test_lj_wagner_cutoff_is_spec_value():
    law = Law("lj", 1.0, 1.0)
    b, ac, _, _ = law.wagner()
    assert b == pytest.approx(1.10868, abs=5e-6)
    assert ac == pytest.approx(1.52454, abs=5e-6)
    _, e, f = pair_curve("lj/spline wagner", law.coeff(), [1.52450, 1.52453, 1.52455, 1.6])
    assert e[0] != 0.0 and e[1] != 0.0 and f[1] != 0.0
    assert e[2] == 0.0 and f[2] == 0.0 and e[3] == 0.0


@pytest.mark.parametrize("law,tail,rc,rs", CASES, ids=IDS)
def test_single_equals_compute(law, tail, rc, rs, tmp_path):
    inner, outer, n = 0.85 * law.a, end(law, tail, rc) * 0.999, 200
    table = tmp_path / "pair.table"
    with session() as lmp:
        lmp.commands_list(["units lj", "region box block 0 5 0 5 0 5", "create_box 1 box",
                           "mass 1 1.0", f"pair_style {law.style()} {tail_args(tail, rc, rs)}",
                           f"pair_coeff 1 1 {law.coeff()}",
                           f"pair_write 1 1 {n} r {inner} {outer} {table} PAIR"])
    rows = np.loadtxt([l for l in table.read_text().splitlines()
                       if l.strip() and l.split()[0].isdigit()])
    r, e, f = pair_curve(f"{law.style()} {tail_args(tail, rc, rs)}", law.coeff(), rows[:, 1])
    assert np.array_equal(r, rows[:, 1])
    # pair_write prints 15 significant digits
    assert np.max(np.abs(rows[:, 2] - e)) <= 1e-13 * law.D, np.max(np.abs(rows[:, 2] - e))
    assert np.max(np.abs(rows[:, 3] - f)) <= 1e-12 * np.max(np.abs(f))


def spec_derivatives(law, tail, rc, rs, r, h=1e-3):
    """dE/dr and d2E/dr2 of the spec's energy by 5-point differences, one-sided where
    the stencil would cross a joint (or the cut) at which E'' jumps."""
    breaks = [j for j, _ in joints(law, tail, rc, rs)] + [end(law, tail, rc)]
    du, du2 = np.empty_like(r), np.empty_like(r)
    for i, x in enumerate(r):
        near = [j for j in breaks if abs(x - j) < 4.5 * h]
        side = 0 if not near else (-1 if x < near[0] else 1)
        if side == 0:
            e = [law.energy(tail, x + k * h, rc, rs) for k in (-2, -1, 0, 1, 2)]
            du[i] = (e[0] - 8 * e[1] + 8 * e[3] - e[4]) / (12 * h)
            du2[i] = (-e[0] + 16 * e[1] - 30 * e[2] + 16 * e[3] - e[4]) / (12 * h * h)
        else:
            e = [law.energy(tail, x + side * k * h, rc, rs) for k in range(5)]
            du[i] = side * (-25 * e[0] + 48 * e[1] - 36 * e[2] + 16 * e[3] - 3 * e[4]) / (12 * h)
            du2[i] = (35 * e[0] - 104 * e[1] + 114 * e[2] - 56 * e[3] + 11 * e[4]) / (12 * h * h)
    return du, du2


# compute born/matrix component order (LAMMPS EXTRA-COMPUTE/compute_born_matrix.cpp)
VOIGT = [(0, 0, 0, 0), (1, 1, 1, 1), (2, 2, 2, 2), (1, 2, 1, 2), (0, 2, 0, 2), (0, 1, 0, 1),
         (0, 0, 1, 1), (0, 0, 2, 2), (0, 0, 1, 2), (0, 0, 0, 2), (0, 0, 0, 1), (1, 1, 2, 2),
         (1, 1, 1, 2), (1, 1, 0, 2), (1, 1, 0, 1), (2, 2, 1, 2), (2, 2, 0, 2), (2, 2, 0, 1),
         (1, 2, 0, 2), (1, 2, 0, 1), (0, 1, 0, 2)]


@pytest.mark.parametrize("law,tail,rc,rs", CASES, ids=IDS)
def test_born_matrix_equals_spec_derivatives(law, tail, rc, rs):
    """compute born/matrix sums (du2/2 - du/r) r_a r_b r_c r_d / r^2 over the full
    neighbour list; here du, du2 are 5-point differences of the spec's energy."""
    with session() as lmp:
        fcc_block(lmp, noise=0.05, a=law.a)
        lmp.commands_list([f"pair_style {law.style()} {tail_args(tail, rc, rs)}",
                           f"pair_coeff * * {law.coeff()}", "compute born all born/matrix",
                           "thermo_style custom step pe c_born[1]", "run 0 post no"])
        born = np.array(lmp.numpy.extract_compute("born", 0, 1)[:21])
        x = np.array(lmp.gather_atoms("x", 1, 3)).reshape(-1, 3)
        boxlo, boxhi = lmp.extract_box()[:2]
    box = np.array(boxhi) - np.array(boxlo)
    d = x[None, :, :] - x[:, None, :]
    d -= box * np.round(d / box)
    r = np.sqrt((d * d).sum(axis=2))
    inside = (r > 0) & (r < end(law, tail, rc))
    d, r = d[inside], r[inside]
    du, du2 = spec_derivatives(law, tail, rc, rs, r)
    pref = 0.5 * du2 - du / r
    expected = np.array([np.sum(pref * d[:, a] * d[:, b] * d[:, c] * d[:, e_] / r ** 2)
                         for a, b, c, e_ in VOIGT])
    assert np.max(np.abs(expected)) > 0
    assert np.max(np.abs(born - expected)) <= 1e-6 * np.max(np.abs(expected))
