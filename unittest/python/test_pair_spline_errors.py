"""Bad input gives a clear LAMMPS error naming the argument; hard cases (deep compression
past the kappa singularity, coincident atoms) stop with an error, never NaN forces."""
import pytest
from conftest import session

BAD_SETTINGS = [
    ("morse/spline", "", "missing tail"),
    ("morse/spline", "spline 1.2", "unknown tail 'spline'"),
    ("morse/spline", "cut", "cut: expected a number Rc \\(got nothing\\)"),
    ("morse/spline", "cut chain 2", "cut: expected a number Rc \\(got 'chain'\\)"),
    ("morse/spline", "cut 1.0", "Rc must be > 1"),
    ("morse/spline", "cut 0.8", "Rc must be > 1"),
    ("lj/spline", "wagner 1.5", "takes no arguments"),
    ("morse/spline", "lagunov 1.2 start 1.3", "Rc = 1.2 must be > start Rs = 1.3"),
    ("morse/spline", "lagunov 1.2 begin 1.1", "unknown keyword 'begin'"),
    ("morse/spline", "lagunov -1", "lagunov Rc must be > 0"),
    ("harmonic/spline", "wagner", "tail wagner needs an inflection point"),
    ("harmonic/spline", "lagunov 1.3", "needs 'start Rs'"),
    ("morse/spline", "cut 1.2 chain 0", "chain N must be between 1 and 1000 \\(got 0\\)"),
    ("morse/spline", "cut 1.2 chain 2147483647", "chain N must be between 1 and 1000"),
    ("morse/spline", "cut 1.2 chain", "keyword chain needs a value"),
    ("morse/spline", "cut 1.2 junk 3", "unknown keyword 'junk' after tail cut \\(expected chain, link"),
    ("morse/spline", "wagner chain", "keyword chain needs a value"),
    ("morse/spline", "lagunov 1.0", "lagunov: Rc must be > 1"),
    ("morse/spline", "lagunov 0.9 start 0.5", "lagunov: Rc must be > 1"),
]

BAD_COEFFS = [  # pair_style, pair_coeff args, message
    ("morse/spline cut 1.2", "1.0 6.0", "expected pair_coeff I J D alpha a"),
    ("morse/spline cut 1.2", "0 6.0 1.0", "D must be > 0"),
    ("morse/spline cut 1.2", "1.0 -6.0 1.0", "alpha must be > 0"),
    ("morse/spline cut 1.2", "1.0 6.0 0", "a must be > 0"),
    ("harmonic/spline cut 1.2", "1.0 0 1.0", "alpha must be > 0"),
    ("lj/spline cut 1.2", "-1.0 1.0", "D must be > 0"),
    ("mie/spline cut 1.2", "1.0 1.0 6 6", "n must be > m"),
    ("mie/spline cut 1.2", "1.0 1.0 4 6", "n must be > m"),
    ("mie/spline cut 1.2", "1.0 1.0 6 0", "m must be > 0"),
    ("morse/spline cut 1.2", "1.0 6.0 1.0 kappa 0", "kappa must be > 0"),
    ("morse/spline cut 1.2", "1.0 6.0 1.0 kappa", "keyword kappa needs a value"),
    ("morse/spline cut 1.2", "1.0 6.0 1.0 gamma 2", "unknown pair_coeff keyword 'gamma'"),
    ("morse/spline cut 1.2", "1.0 6.0 1.0 rc 0.9", "rc must be > 1"),
    ("morse/spline lagunov 1.3", "1.0 6.0 1.0 rc 0.9", "rc must be > 1"),
    ("mie/spline cut 1.2", "1.0 1.0 1e6 6", "law of types 1 1 overflows at r = a/2 \\(the exponents n and m must be below"),
    ("mie/spline cut 1.2", "1.0 1.0 1e6 999999", "overflows at r = a/2"),
    ("morse/spline cut 1.2", "1.0 2000 1.0", "overflows at r = a/2 \\(alpha a must be below about 700"),
    ("lj/spline wagner", "1.0 1.0 kappa 0.1", "wagner has no cutoff for types 1 1 \\(raise kappa\\)"),
    ("morse/spline wagner", "1.0 6.0 1.0 rc 1.3", "rc does not apply to tail wagner"),
    ("morse/spline cut 1.2", "1.0 6.0 1.0 rs 1.1", "rs applies only to tail lagunov"),
    ("morse/spline wagner", "1.0 1.2 1.0", "tail wagner has no cutoff for types 1 1 \\(Morse needs kappa alpha a"),
    ("morse/spline lagunov 1.05", "1.0 6.0 1.0", "lagunov Rc = 1.05 a must be > its start"),
    ("mie/spline lagunov 1.3", "1.0 1.0 12 6 rs 1.4", "must be > its start Rs = 1.4"),
]


def box(lmp):
    lmp.commands_list(["units lj", "region box block 0 4 0 4 0 4", "create_box 1 box",
                       "mass 1 1.0"])


@pytest.mark.parametrize("style,args,message", BAD_SETTINGS)
def test_bad_pair_style_settings(style, args, message):
    with session() as lmp:
        box(lmp)
        with pytest.raises(Exception, match=message):
            lmp.command(f"pair_style {style} {args}")


@pytest.mark.parametrize("pair_style,args,message", BAD_COEFFS)
def test_bad_pair_coeff(pair_style, args, message):
    with session() as lmp:
        box(lmp)
        lmp.command(f"pair_style {pair_style}")
        with pytest.raises(Exception, match=message):
            lmp.command(f"pair_coeff 1 1 {args}")


def test_morse_wagner_cutoff_exists_from_alpha_a_1_56():
    with session() as lmp:
        box(lmp)
        lmp.commands_list(["pair_style morse/spline wagner", "pair_coeff 1 1 1.0 1.56 1.0"])
        with pytest.raises(Exception, match="wagner has no cutoff"):
            lmp.command("pair_coeff 1 1 1.0 1.55 1.0")


@pytest.mark.parametrize("law,coeff", [("lj", "1.0 1.0 kappa 2.0"), ("mie", "1.0 1.0 9 6 kappa 1.5")])
def test_compression_past_kappa_singularity_is_an_error_naming_the_atoms(law, coeff):
    # kappa > 1: the law is singular at r = a (1 - 1/kappa); a pair closer than that stops
    with session() as lmp:
        box(lmp)
        lmp.commands_list(["create_atoms 1 single 1.0 1.0 1.0", "create_atoms 1 single 1.2 1.0 1.0",
                           f"pair_style {law}/spline cut 1.3", f"pair_coeff 1 1 {coeff}"])
        with pytest.raises(Exception, match="atoms 1 and 2 are 0.2 apart"):
            lmp.command("run 0")


def test_coincident_atoms_are_an_error_not_nan():
    with session() as lmp:
        box(lmp)
        lmp.commands_list(["create_atoms 1 single 1.0 1.0 1.0", "create_atoms 1 single 1.0 1.0 1.0",
                           "pair_style morse/spline cut 1.3", "pair_coeff 1 1 1.0 6.0 1.0"])
        with pytest.raises(Exception, match="atoms 1 and 2 are 0 apart"):
            lmp.command("run 0")
