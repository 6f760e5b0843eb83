"""ensembles.md and dust_ensembles.png from the cached runs of run_ensembles.py."""
import os

import numpy as np

PAPER_UCR = {1.05: 400, 1.1: 600, 1.2: 1400, 1.3: 2500}   # m/s, the paper's 3D runs


def report(runs, cached, here):
    done = [(v, cached(v)) for v in runs]
    missing = [v for v, r in done if r is None]
    done = [(v, r) for v, r in done if r is not None]
    models = [("distance", None), ("link 1.05", 1.05)]

    def counts(link, **var):
        """Dust counts of every seed run at one point."""
        return [r["surface"] for v, r in done
                if v.get("link") == link and v["seed"] >= 1
                and {k: x for k, x in v.items() if k not in ("seed", "link")} == var]

    def stat(c, fmt=".1f"):
        if len(c) == 1:
            return f"{c[0]:{'.0f' if fmt == '.1f' else fmt}}"
        return f"{np.mean(c):{fmt}} ± {np.std(c, ddof=1):{fmt}} ({len(c)})"

    out = ["## Dust clusters beyond the body at 1.5 us: bonds by distance against links made at",
           "1.05 a (fcc [100], 2x2 cells, 5664 clusters; mean ± sample standard deviation (runs))", "",
           "| Rc | model | paper's threshold | criterion 1.35 (Rc-1) c0 | threshold (m/s) | "
           "dust clusters against u (m/s: count) |", "|---|---|---|---|---|---|"]
    grids = {}
    for v, _ in done:
        if v.get("law", "morse") == "morse" and v["seed"] >= 1:
            grids.setdefault(v["rc"], set()).add(v["u"])
    thresholds = {}
    for rc in sorted(grids):
        for name, link in models:
            points = [(u, counts(link, rc=rc, u=u)) for u in sorted(grids[rc])]
            points = [(u, c) for u, c in points if c]
            if not points:
                continue
            zero = [u for u, c in points if max(c) == 0]
            some = [u for u, c in points if np.mean(c) > 0]
            first = min(some) if some else None
            below = max([u for u in zero if first is None or u < first], default=None)
            if first is None:
                text = f"> {points[-1][0]}"
            elif below is None:
                text = f"<= {first}"
            else:
                text = f"{below}-{first}"
            thresholds[(rc, name)] = (below, first)
            ucr = next(r["ucr"] for v, r in done if v["rc"] == rc)
            curve = ", ".join(f"{u}: {stat(c)}" for u, c in points)
            out.append(f"| {rc} | {name} | {PAPER_UCR.get(rc, '')} | {ucr:.0f} | {text} | {curve} |")
    out += ["", "## Harmonic well (Rc = 1.2)", "", "| model | u (m/s) | dust clusters |", "|---|---|---|"]
    for name, link in models:
        for u in (2000, 4000):
            c = counts(link, rc=1.2, u=u, law="harmonic")
            if c:
                out.append(f"| {name} | {u} | {stat(c)} |")
    out += ["", "## The thermal velocity (distance model; Rc, u in m/s)", "",
            "| Rc | u | no thermal velocity (seed 0) | rms 0.1 m/s | rms 1 m/s | link 1.05, seed 0 | link 1.05, 1 m/s |",
            "|---|---|---|---|---|---|---|"]
    for rc, u in ((1.05, 300), (1.1, 500), (1.2, 1400)):
        def pick(link, seeds, vtherm=None):
            return [r["surface"] for v, r in done if v.get("link") == link and v["rc"] == rc
                    and v["u"] == u and v["seed"] in seeds and v.get("vtherm") == vtherm
                    and "law" not in v]
        cells = [pick(None, [0]), pick(None, range(1, 6), 0.1), pick(None, range(1, 6)),
                 pick(1.05, [0]), pick(1.05, range(1, 6))]
        out.append(f"| {rc} | {u} | " + " | ".join(stat(c) if c else "not run" for c in cells) + " |")
    out += ["", "## Equal areas and wider sections (Rc, u in m/s)", "",
            "| scene | model | dust clusters | dust mass per area (kg/m^2) | clusters |", "|---|---|---|---|---|"]
    scenes = [("10 um clusters, 1x1 cell, Rc 1.1, u 2000", dict(rc=1.1, u=2000, cells=1)),
              ("5 um clusters, 2x2 cells (same area), Rc 1.1, u 2000",
               dict(rc=1.1, u=2000, pot="al-cluster-5um"))]
    scenes += [(f"4x4 cells, Rc 1.2, u {u}", dict(rc=1.2, u=u, cells=4)) for u in (600, 800, 1200, 1400)]
    for label, var in scenes:
        for name, link in models:
            rows = [r for v, r in done if v.get("link") == link and v["seed"] >= 1
                    and {k: x for k, x in v.items() if k not in ("seed", "link")} == var]
            if rows:
                out.append(f"| {label} | {name} | {stat([r['surface'] for r in rows])} | "
                           f"{stat([r['dustmass'] for r in rows], '.3g')} | {rows[0]['natoms']} |")
    seconds = [r["seconds"] for _, r in done]
    out += ["", f"{len(done)} runs, {sum(seconds):.0f} s of run time (two at a time on two cores)."]
    if missing:
        out += ["", f"Not run ({len(missing)}): " + "; ".join(
            ", ".join(f"{k} {x}" for k, x in v.items()) for v in missing)]
    open(os.path.join(here, "ensembles.md"), "w").write("\n".join(out) + "\n")
    print("\n".join(out))
    plot(done, models, grids, counts, here)


def plot(done, models, grids, counts, here):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rcs = sorted(grids)
    fig, axes = plt.subplots(2, 2, figsize=(10, 7))
    for ax, rc in zip(axes.flat, rcs):
        for (name, link), colour in zip(models, ("C0", "C3")):
            us = sorted(grids[rc])
            first = [counts(link, rc=rc, u=u) for u in us]
            ax.plot([u for u, c in zip(us, first) if c], [c[0] for c in first if c], "o-",
                    color=colour, alpha=0.5, label=f"{name}: seed 1")
            ens = [(u, c) for u, c in zip(us, first) if len(c) > 1]
            if ens:
                ax.errorbar([u for u, _ in ens], [np.mean(c) for _, c in ens],
                            yerr=[np.std(c, ddof=1) for _, c in ens], fmt="s", color=colour,
                            capsize=4, label=f"{name}: mean ± std of {len(ens[0][1])} seeds")
        ax.axvline(PAPER_UCR[rc], color="k", ls="--", lw=0.8, label="paper's threshold")
        ax.set_yscale("symlog", linthresh=1)    # the few clusters near a threshold show
        ax.set_ylim(-0.1, 1e4)
        ax.set_title(f"Rc = {rc}")
        ax.set_xlabel("loading speed u (m/s)")
        ax.set_ylabel("dust clusters at 1.5 us")
    axes.flat[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "dust_ensembles.png"), dpi=80)
    plt.close(fig)
