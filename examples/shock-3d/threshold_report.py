"""thresholds.md and thresholds.png from the cached runs of run_thresholds.py: the dusting
thresholds by two definitions, first dust and more than one layer of the section."""
import os

import numpy as np

C0 = 5454.0            # m/s, the aluminium clusters' long-wave speed (criterion 1.35 (Rc-1) c0)


def layer(cells):
    """Clusters in one lattice plane across the shock: fcc [100], cells x cells cells."""
    return 2 * cells * cells


def bracket(points, test):
    """(last speed below, first speed at which) at least half of the runs pass `test`;
    points: [(u, counts)] sorted by u."""
    below, at = None, None
    for u, c in points:
        if np.mean([test(x) for x in c]) >= 0.5:
            at = u
            break
        below = u
    return below, at


def text_of(b):
    below, at = b
    if below is None and at is None:
        return "-"
    if at is None:
        return f"> {below}"
    return f"<= {at}" if below is None else f"{below}-{at}"


def report(phases, cached, here, paper, grids):
    """The tables and the plot; grids: {Rc: speeds} of the threshold runs."""
    runs = [v for phase in phases() for v in phase]
    done = [(v, cached(v)) for v in runs]
    missing = [v for v, r in done if r is None]
    done = [(v, r) for v, r in done if r is not None]

    def counts(thermal, **var):
        return [r["surface"] for v, r in done if (v["seed"] > 0) == thermal and
                {k: x for k, x in v.items() if k != "seed"} == var]

    out = ["# Dusting thresholds by two definitions (written by run_thresholds.py)", "",
           "Dust clusters beyond the body at 1.5 us (in.shock3d: fcc [100], 5 mm, aluminium "
           "clusters of 10 um, bonds by distance).  First dust: at least one cluster.  More "
           "than one layer: more clusters than one lattice plane of the section holds (8 in "
           "2x2 cells, 32 in 4x4).  A threshold is the bracket of grid speeds between the last "
           "where fewer than half of the runs pass and the first where at least half do; from "
           "rest: the one run without thermal velocity; thermal: five seeds of a 1 m/s start.",
           ""]
    table = ["| section | Rc | paper (Table 2) | 1.35 (Rc-1) c0 | first dust, from rest | "
             "first dust, thermal | more than one layer, from rest | more than one layer, "
             "thermal |", "|---|---|---|---|---|---|---|---|"]
    detail = ["| section | Rc | u (m/s) | from rest | thermal: mean ± sd (counts) |",
              "|---|---|---|---|---|"]
    curves = {}
    plain = [v for v, _ in done if "pot" not in v and "lattice" not in v]
    for cells in sorted({v["cells"] for v in plain}):
        for rc in sorted({v["rc"] for v in plain if v["cells"] == cells}):
            us = sorted({v["u"] for v in plain if v["cells"] == cells and v["rc"] == rc and
                         v["u"] in grids.get(rc, ())})
            rest = [(u, counts(False, rc=rc, u=u, cells=cells)) for u in us]
            rest = [(u, c) for u, c in rest if c]
            thermal = [(u, counts(True, rc=rc, u=u, cells=cells)) for u in us]
            thermal = [(u, c) for u, c in thermal if c]
            curves[(cells, rc)] = (thermal, rest)
            n = layer(cells)
            row = [f"{cells}x{cells}", f"{rc}", f"{paper[rc]}", f"{1.35 * (rc - 1) * C0:.0f}"]
            for test in (lambda x: x >= 1, lambda x, n=n: x > n):
                row += [text_of(bracket(rest, test)), text_of(bracket(thermal, test))]
            table.append("| " + " | ".join(row[:4] + [row[4], row[5], row[6], row[7]]) + " |")
            for u in us:
                r0 = dict(rest).get(u)
                th = dict(thermal).get(u)
                cells_text = ("-" if not th else f"{np.mean(th):.1f} ± {np.std(th, ddof=1):.1f} "
                              f"({', '.join(f'{x:.0f}' for x in th)})" if len(th) > 1 else
                              f"{th[0]:.0f}")
                detail.append(f"| {cells}x{cells} | {rc} | {u} | "
                              f"{'-' if not r0 else f'{r0[0]:.0f}'} | {cells_text} |")
    out += table + ["", "### Counts", ""] + detail + [""]
    sizes = [(v, r) for v, r in done if v["rc"] == 1.1 and v["u"] == 2000 and v["cells"] == 2]
    if sizes:
        out += ["## 5 um against 10 um clusters at the same periods of cross-section (2x2 "
                "cells, Rc = 1.1, u = 2 km/s, five seeds)", "",
                "| clusters | dust clusters | dust mass per area (kg/m^2) | clusters in the "
                "sample |", "|---|---|---|---|"]
        for pot in ("al-cluster-10um", "al-cluster-5um"):
            rows = [r for v, r in sizes if v.get("pot", "al-cluster-10um") == pot]
            if len(rows) > 1:
                d = [r["surface"] for r in rows]
                m = [r["dustmass"] for r in rows]
                out.append(f"| {pot} | {np.mean(d):.1f} ± {np.std(d, ddof=1):.1f} "
                           f"({', '.join(f'{x:.0f}' for x in d)}) | {np.mean(m):.3g} ± "
                           f"{np.std(m, ddof=1):.2g} | {rows[0]['natoms']} |")
        out.append("")
    sh = [(v, r) for v, r in done if v.get("lattice") == "sh"]
    if sh:
        out += ["## The paper's density at spacing a: simple hexagonal (from rest, 2x2 periods, "
                "8 clusters a layer)", "",
                "| Rc | dust clusters, sh (u m/s: count) | first dust, sh | more than one layer, "
                "sh | fcc [100] from rest: first dust / more than one layer |",
                "|---|---|---|---|---|"]
        for rc in sorted({v["rc"] for v, _ in sh}):
            points = sorted((v["u"], [r["surface"]]) for v, r in sh if v["rc"] == rc)
            fcc = curves.get((2, rc), ([], []))[1]
            out.append(f"| {rc} | {', '.join(f'{u}: {c[0]:.0f}' for u, c in points)} | "
                       f"{text_of(bracket(points, lambda x: x >= 1))} | "
                       f"{text_of(bracket(points, lambda x: x > layer(2)))} | "
                       f"{text_of(bracket(fcc, lambda x: x >= 1))} / "
                       f"{text_of(bracket(fcc, lambda x: x > layer(2)))} |")
        out.append("")
    out.append(f"{len(done)} runs, {sum(r['seconds'] for _, r in done):.0f} s of run time.")
    if missing:
        out += ["", f"Not run yet ({len(missing)}): " +
                "; ".join(", ".join(f"{k} {x}" for k, x in v.items()) for v in missing[:12]) +
                (" ..." if len(missing) > 12 else "")]
    open(os.path.join(here, "thresholds.md"), "w").write("\n".join(out) + "\n")
    plot(curves, paper, here)


def plot(curves, paper, here):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rcs = sorted({rc for _, rc in curves})
    fig, axes = plt.subplots(1, len(rcs), figsize=(4 * len(rcs), 4.2), squeeze=False)
    colours = {2: "tab:blue", 4: "tab:orange"}
    for ax, rc in zip(axes[0], rcs):
        for (cells, r), (thermal, rest) in sorted(curves.items()):
            if r != rc:
                continue
            colour = colours.get(cells, "k")
            if thermal:
                for u, c in thermal:
                    ax.plot([u] * len(c), np.array(c) + 0.5, ".", color=colour, alpha=0.5)
                ax.plot([u for u, _ in thermal], [np.mean(c) + 0.5 for _, c in thermal], "-",
                        color=colour, label=f"{cells}x{cells}: seeds (dots), mean (line)")
            if rest:
                ax.plot([u for u, _ in rest], [c[0] + 0.5 for _, c in rest], "s", mfc="none",
                        color=colour, label=f"{cells}x{cells}: from rest")
            ax.axhline(layer(cells) + 0.5, ls=":", lw=0.8, color=colour)
        ax.axvline(paper[rc], color="k", ls="--", lw=1, label="paper's threshold")
        ax.axvline(1.35 * (rc - 1) * C0, color="r", ls=":", lw=1, label="1.35 (Rc-1) c0")
        ax.set(yscale="log", xlabel="piston speed u (m/s)", title=f"Rc = {rc}",
               ylabel="dust clusters + 0.5 (dotted: one layer)")
        ax.legend(fontsize=6, loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(here, "thresholds.png"), dpi=100)
