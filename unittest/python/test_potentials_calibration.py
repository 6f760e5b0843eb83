"""potentials/ parameter sets and tools/cd_calibrate.py: the sets load as documented and give
the papers' numbers; calibrate -> load -> compute pair/params returns the requested v_l, vd."""
import os
import re
import subprocess
import sys

import pytest
from conftest import session

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
POTENTIALS = os.path.join(TOP, "potentials")
CALIBRATE = os.path.join(TOP, "tools", "cd_calibrate.py")
NAMES = ["a", "b", "sigma", "D", "fstar", "C", "eps", "kstar", "kv", "k2", "Gamma", "omega0",
         "T0", "v0", "vd", "Bstar", "Rc", "ucr", "ucr1d", "vl"]


def load(path, lattice="fcc"):
    """Include a parameter set the documented way; return compute pair/params as a dict."""
    with session() as lmp:
        lmp.command(f"include {path}")
        units = lmp.extract_variable("pot_units")
        lmp.commands_list([f"units {units}", "region box block 0 $(10*v_pot_a) 0 $(10*v_pot_a) "
                           "0 $(10*v_pot_a) units box", "create_box 1 box", "mass 1 ${pot_m}",
                           "neighbor $(0.2*v_pot_a) bin",
                           "pair_style ${pot_style} cut 1.2", "pair_coeff 1 1 ${pot_coeff}",
                           f"compute p all pair/params 1 1 lattice {lattice}",
                           "thermo_style custom step c_p[1]", "run 0 post no"])
        return dict(zip(NAMES, lmp.numpy.extract_compute("p", 0, 1)[:20].copy()))


def test_aluminium_clusters_give_the_papers_speeds():
    p = load(os.path.join(POTENTIALS, "al-cluster-10um.cd"))
    assert p["a"] == 1e-5
    assert p["v0"] == pytest.approx(5454, abs=0.5)   # paper: c0 = 5454 m/s
    assert p["vd"] == pytest.approx(1451, abs=0.5)   # paper: vd = 1451 m/s
    assert p["kv"] == pytest.approx(3.76, rel=1e-12)


def test_half_size_clusters_have_the_same_continuum_properties():
    big = load(os.path.join(POTENTIALS, "al-cluster-10um.cd"))
    small = load(os.path.join(POTENTIALS, "al-cluster-5um.cd"))
    assert small["a"] == pytest.approx(big["a"] / 2, rel=1e-15)
    for key in ("v0", "vd", "eps", "kstar", "kv", "Gamma", "vl", "ucr"):
        assert small[key] == pytest.approx(big[key], rel=1e-12), key


def test_morse_lj_match():
    p = load(os.path.join(POTENTIALS, "morse-lj-match.cd"))
    assert p["C"] == pytest.approx(72.0, rel=1e-12) and p["kv"] == pytest.approx(6.0, rel=1e-12)
    assert p["Gamma"] == pytest.approx(9.0, rel=1e-12)


@pytest.mark.parametrize("law", [["--law", "morse"], ["--law", "lj"],
                                 ["--law", "mie", "--n", "9", "--m", "6"]])
@pytest.mark.parametrize("lattice", ["chain", "tri", "fcc"])
def test_calibration_round_trip(tmp_path, law, lattice):
    v_l, v_spall = 6420.0, 1500.0
    out = subprocess.run([sys.executable, CALIBRATE, "--density", "2700", "--sound-speed",
                          str(v_l), "--spall-speed", str(v_spall), "--size", "1e-5",
                          "--lattice", lattice, *law], capture_output=True, text=True, check=True)
    path = tmp_path / "calibrated.cd"
    path.write_text(out.stdout)
    p = load(path, lattice)
    assert p["vl"] == pytest.approx(v_l, rel=1e-9)
    assert p["vd"] == pytest.approx(v_spall, rel=1e-9)
    # what the header says the set implies, against compute pair/params on the written set
    # (pair_style cut 1.2: its u_cr is the header's onset at Rc = 1.2); 4 digits printed
    implied = header_numbers(out.stdout)
    assert implied["gamma"] == pytest.approx(p["Gamma"], rel=1e-3)
    assert implied["b"] == pytest.approx(p["b"] / p["a"], rel=1e-3)
    assert implied["ucr12"] == pytest.approx(p["ucr"], rel=1e-3)
    assert implied["ucr11"] == pytest.approx(p["ucr"] / 2, rel=1e-3)
    assert implied["density"] == 2700.0
    assert "warning" not in out.stderr                  # kv = 3.9: the papers' range


IMPLIED = re.compile(r"# implied: cluster \(lattice\) density (?P<density>\S+) \(the density "
                     r"given, on this lattice of a\), Grueneisen \(chain\) (?P<gamma>\S+), "
                     r"break \(inflection\) distance b = (?P<b>\S+) a, dusting onset "
                     r"u_cr = 1.35 \(Rc - 1\) v0: (?P<ucr11>\S+) m/s at Rc = 1.1, "
                     r"(?P<ucr12>\S+) m/s at Rc = 1.2 \(v0: the chain's speed a sqrt\(C/m\)\)$")


def header_numbers(text):
    """The numbers of the '# implied' header line (which must read as IMPLIED)."""
    line = next(line for line in text.splitlines() if line.startswith("# implied"))
    match = IMPLIED.match(line)
    assert match, line
    return {k: float(v) for k, v in match.groupdict().items()}


@pytest.mark.parametrize("units", ["si", "metal", "lj"])
def test_header_ratios_are_unit_free(tmp_path, units):
    """The header's b / a and onsets are SI whatever --units writes (lj once printed b in
    metres over a in lattice units: 1.178e-05 a); the set loaded in that style gives the
    same b / a by compute pair/params."""
    args = ["--density", "2700", "--sound-speed", "6420", "--spall-speed", "1500", "--size",
            "1e-5", "--lattice", "fcc"]
    si = header_numbers(subprocess.run([sys.executable, CALIBRATE, *args], capture_output=True,
                                       text=True, check=True).stdout)
    out = subprocess.run([sys.executable, CALIBRATE, *args, "--units", units],
                         capture_output=True, text=True, check=True).stdout
    assert header_numbers(out) == si
    path = tmp_path / "set.cd"
    path.write_text(out)
    p = load(path)
    assert si["b"] == pytest.approx(p["b"] / p["a"], rel=1e-3)


def test_calibration_warns_far_from_the_papers_range():
    """The new user's copper-like set of issue 28 (spall speed 120 m/s taken from a pull-back):
    kv = 36, Grueneisen 54, a bond that breaks at 1.02 a - a warning that says so."""
    out = subprocess.run([sys.executable, CALIBRATE, "--density", "8900", "--sound-speed", "4760",
                          "--spall-speed", "120", "--size", "1e-5", "--lattice", "fcc"],
                         capture_output=True, text=True, check=True)
    warned = re.search(r"cd_calibrate: warning: kv = v0 / v_spall = (\S+) is far.*Grueneisen "
                       r"coefficient is (\S+) ", out.stderr)
    kv = 4760 / 1.10 / 120                      # v0 / v_spall, v0 = v_l / lambda (fcc: 1.10)
    assert float(warned.group(1)) == pytest.approx(kv, rel=2e-3)            # 3 digits printed
    assert float(warned.group(2)) == pytest.approx(1.5 * kv, rel=2e-3)      # Morse: 1.5 alpha a
    assert "not a free-surface pull-back" in out.stderr


@pytest.mark.parametrize("args,message", [
    (["--spall-speed", "7000"], "admits no bonded solid"),
    (["--spall-speed", "-1"], "--spall-speed must be a finite number > 0"),
    (["--lattice", "hex"], "unknown --lattice 'hex'"),
    (["--lattice", "hcp"], "--lattice hcp: Krivtsov's calibration (--spall-speed) knows chain"),
    (["--law", "buck"], "unknown --law 'buck'"),
    (["--law", "mie", "--n", "4", "--m", "6"], "need finite --n > --m > 0"),
])
def test_calibration_rejects_data_without_a_potential(args, message):
    base = {"--density": "2700", "--sound-speed": "6420", "--spall-speed": "1500",
            "--size": "1e-5", "--lattice": "fcc"}
    for k, v in zip(args[::2], args[1::2]):
        base[k] = v
    cmd = [sys.executable, CALIBRATE] + [x for kv in base.items() for x in kv]
    out = subprocess.run(cmd, capture_output=True, text=True)
    assert out.returncode != 0 and message in out.stderr
