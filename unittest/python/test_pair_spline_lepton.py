"""Bases and tails that have no stock style, against `pair_style lepton` with the spec's
formula as its expression, on a thermalised periodic fcc block."""
import pytest
from conftest import assert_same_state, fcc_block, session, state
from spec_laws import Law

CASES = [  # law, tail, rc, rs
    (Law("harmonic", 1.3, 1.0, alpha=5.5, kappa=1.3), "cut", 1.2, None),
    (Law("harmonic", 1.3, 1.0, alpha=5.5, kappa=0.9), "lagunov", 1.3, 1.1),
    (Law("morse", 1.3, 1.0, alpha=6.0), "wagner", None, None),
    (Law("morse", 1.3, 1.0, alpha=4.0, kappa=1.4), "wagner", None, None),
    (Law("morse", 1.3, 1.0, alpha=5.0), "lagunov", 1.4, None),
    (Law("lj", 1.3, 1.0), "wagner", None, None),
    (Law("lj", 1.3, 1.0, kappa=0.9), "wagner", None, None),
    (Law("lj", 1.3, 1.0), "lagunov", 1.5, None),
    (Law("lj", 1.3, 1.0, kappa=1.2), "cut", 1.4, None),
    (Law("mie", 1.3, 1.0, n=10, m=5, kappa=1.2), "lagunov", 1.5, 1.08),
    (Law("mie", 1.3, 1.0, n=9, m=6), "wagner", None, None),
    (Law("mie", 1.3, 1.0, n=8, m=4, kappa=0.8), "cut", 1.3, None),
]


def tail_args(tail, rc, rs):
    return {"cut": f"cut {rc}", "wagner": "wagner",
            "lagunov": f"lagunov {rc}" + (f" start {rs}" if rs else "")}[tail]


@pytest.mark.parametrize("law,tail,rc,rs", CASES,
                         ids=[f"{c[0].base}-{c[1]}-k{c[0].kappa}" for c in CASES])
def test_equals_lepton(law, tail, rc, rs):
    expr, cutoff = law.lepton(tail, rc, rs)
    with session() as lmp:
        fcc_block(lmp, noise=0.06)
        lmp.commands_list([f"pair_style lepton {cutoff!r}", f'pair_coeff * * "{expr}"'])
        stock = state(lmp)
        lmp.commands_list([f"pair_style {law.style()} {tail_args(tail, rc, rs)}",
                           f"pair_coeff * * {law.coeff()}"])
        ours = state(lmp)
    assert_same_state(stock, ours, rtol=1e-10)
