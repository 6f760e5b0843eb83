"""argparse reads a value such as -1e10 or -3.2e-10 as an option (its test of a negative number,
'-digits' or '-digits.digits', has no exponent), so `--size -3.2e-10` fails with "expected one
argument" instead of the tool's own message about the value.  numbers_take_values(parser) lets
every negative number, with or without an exponent, stand as a value."""
import re

NEGATIVE_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


def numbers_take_values(parser):
    parser._negative_number_matcher = NEGATIVE_NUMBER
    return parser
