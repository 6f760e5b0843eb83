"""Young's modulus and Poisson's ratio of blocks of movable cellular automata (pair_style mca)
against the material's own E and nu, on fcc, hcp and random dense packings, with the
many-body term on and off (in.elastic), and the table and plot of examples/mca-elastic.

    source ../../build/env.sh
    /usr/bin/python3 elastic.py            # elastic.md and elastic.png, about 3 min

A block is strained by 1e-4 along x, y and z in turn; the stresses give the normal block C of
its stiffness (C_ij = stress_i / strain_j), whose inverse S gives the uniaxial-stress moduli
E_k = 1 / S_kk and nu_kl = -S_lk / S_kk.  fcc is loaded along [1-10] (x) and [111] (z), hcp
along a (x) and c (z); random packings along x, y, z (mean over the three).
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from runner import mean_sd, script  # noqa: E402

STRAIN = 1.0e-4
NUS = (0.1, 0.2, 0.3, 0.4, 0.45)


def run(packing, nu, manybody="yes", n=4, seed=1, tolerance=0.02):
    """The stiffness block C (3x3, E = 1 units) after relaxation and before it (affine), and
    the sample: elements, packing fraction, links per element."""
    var = dict(packing=packing, nu=nu, manybody=manybody, n=n, seed=seed, strain=STRAIN,
               tolerance=tolerance)
    with script(os.path.join(HERE, "in.elastic"), var) as lmp:
        c, ca = (np.array([[lmp.extract_variable(f"{p}_{d}_{k}{k}") for d in "xyz"] for k in "xyz"])
                 for p in "sa")
        sample = (lmp.get_natoms(), lmp.extract_variable("phi"), lmp.extract_variable("links"))
    return 0.5 * (c + c.T) / STRAIN, 0.5 * (ca + ca.T) / STRAIN, sample


def moduli(c):
    """E_k and nu_k (mean of the two lateral ratios) for loading along x, y, z."""
    s = np.linalg.inv(c)
    e = 1.0 / np.diag(s)
    nu = np.array([-(s[k, (k + 1) % 3] + s[k, (k + 2) % 3]) / (2.0 * s[k, k]) for k in range(3)])
    return e, nu


def rows(nus=NUS, seeds=(1, 2, 3), n_lattice=4, n_random=5, tolerance=0.02):
    """One dict per (packing, direction, nu, manybody): E/E_input, nu, and the sample."""
    out = []
    for manybody in ("yes", "no"):
        for nu in nus:
            for packing, dirs in (("fcc", {"[1-10]": 0, "[111]": 2}), ("hcp", {"a": 0, "c": 2})):
                c, _, (natoms, phi, links) = run(packing, nu, manybody, n_lattice)
                e, v = moduli(c)
                for name, k in dirs.items():
                    out.append(dict(packing=packing, dir=name, nu_in=nu, manybody=manybody,
                                    e=e[k], nu=v[k], natoms=natoms, phi=phi, links=links))
            es, vs, zs, phis, eas = [], [], [], [], []
            for seed in seeds:
                c, ca, (natoms, phi, links) = run("random", nu, manybody, n_random, seed,
                                                  tolerance)
                e, v = moduli(c)
                eas.append(moduli(ca)[0].mean())
                es.append(e.mean())
                vs.append(v.mean())
                zs.append(links)
                phis.append(phi)
            out.append(dict(packing="random", dir="x,y,z", nu_in=nu, manybody=manybody,
                            e=np.mean(es), e_sd=np.std(es, ddof=1) if len(es) > 1 else 0.0,
                            nu=np.mean(vs), nu_sd=np.std(vs, ddof=1) if len(vs) > 1 else 0.0,
                            natoms=natoms, phi=np.mean(phis), links=np.mean(zs),
                            e_affine=np.mean(eas)))
    return out


def coordination(tolerances=(0.0, 0.02, 0.05, 0.1), seeds=(1, 2, 3), nu=0.3, n=5):
    """Random packings: E and nu against the links per element (the linking tolerance)."""
    lines = ["| tolerance | links/element | E / E input | nu | E / E input, unrelaxed |",
             "|---|---|---|---|---|"]
    for tol in tolerances:
        res = [run("random", nu, "yes", n, seed, tol) for seed in seeds]
        e = [moduli(c)[0].mean() for c, _, _ in res]
        v = [moduli(c)[1].mean() for c, _, _ in res]
        ea = [moduli(ca)[0].mean() for _, ca, _ in res]
        z = [s[2] for _, _, s in res]
        lines.append(f"| {tol} | {np.mean(z):.2f} | {mean_sd(e, 3)} | "
                     f"{mean_sd(v, 3)} | {np.mean(ea):.3f} |")
    return "\n".join(lines) + "\n"


def table(out):
    lines = ["| many-body | packing | load | nu input | E / E input | nu | links/element | "
             "E / E input, unrelaxed |", "|---|---|---|---|---|---|---|---|"]
    for r in out:
        e = f"{r['e']:.4f}" + (f" ± {r['e_sd']:.4f}" if "e_sd" in r else "")
        nu = f"{r['nu']:.4f}" + (f" ± {r['nu_sd']:.4f}" if "nu_sd" in r else "")
        lines.append(f"| {r['manybody']} | {r['packing']} | {r['dir']} | {r['nu_in']} | {e} | "
                     f"{nu} | {r['links']:.2f} | {r.get('e_affine', r['e']):.4f} |")
    return "\n".join(lines) + "\n"


def plot(out, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.2))
    style = {"fcc": "o", "hcp": "s", "random": "^"}
    for manybody, fill in (("yes", None), ("no", "none")):
        for packing in ("fcc", "hcp", "random"):
            rs = [r for r in out if r["packing"] == packing and r["manybody"] == manybody
                  and r["dir"] in ("[1-10]", "a", "x,y,z")]
            x = [r["nu_in"] for r in rs]
            label = f"{packing}, many-body {manybody}"
            kw = dict(marker=style[packing], linestyle="-" if manybody == "yes" else ":",
                      mfc=fill, label=label)
            ax1.plot(x, [r["nu"] for r in rs], **kw)
            ax2.plot(x, [r["e"] for r in rs], **kw)
    ax1.plot([0.1, 0.45], [0.1, 0.45], "k--", lw=0.8, label="input")
    ax2.axhline(1.0, color="k", ls="--", lw=0.8)
    ax1.set_xlabel("Poisson's ratio of the material")
    ax1.set_ylabel("Poisson's ratio of the block")
    ax2.set_xlabel("Poisson's ratio of the material")
    ax2.set_ylabel("E of the block / E of the material")
    ax1.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="nu 0.3 only, one random seed")
    args = ap.parse_args()
    out = rows(nus=(0.3,), seeds=(1,)) if args.quick else rows()
    text = table(out)
    print(text)
    if not args.quick:
        study = coordination()
        print(study)
        with open(os.path.join(HERE, "elastic.md"), "w") as f:
            f.write(text + "\nRandom packings (nu = 0.3, 3 seeds) against the linking tolerance:\n\n"
                    + study)
        plot(out, os.path.join(HERE, "elastic.png"))


if __name__ == "__main__":
    main()
