#!/usr/bin/python3
"""The plot of bench/bench_mca_scale.sh's output: Pair time per element-step and memory per
element against the number of elements (one rank; the 2-rank point of the widest plate), with
issue 54's aims (1.2 x the smallest plate's cost, 3 kB per element).

    bash bench/bench_mca_scale.sh BUILD 200 5 10 20 32 50 > scale.txt
    /usr/bin/python3 bench/plot_mca_scale.py scale.txt doc/benchmarks/bench_mca_scale.png
"""
import re
import sys


def rows(path):
    """(ranks, elements, Pair us, memory kB at the setup, after the run (None: not printed)) of
    each line of the benchmark's output."""
    out = []
    for line in open(path):
        m = re.search(r"(\d+) ranks +\d+ cells: +(\d+) elements.*Pair ([0-9.]+) us.*memory "
                      r"([0-9.]+) kB per element(?: \(([0-9.]+) after the run\))?", line)
        if m:
            after = float(m.group(5)) if m.group(5) else None
            out.append((int(m.group(1)), int(m.group(2)), float(m.group(3)), float(m.group(4)),
                        after))
    return out


def against_n(ax, ylabel):
    """A log axis of elements, the quantity from 0, its legend and grid."""
    ax.set_xscale("log")
    ax.set_xlabel("elements")
    ax.set_ylabel(ylabel)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)


def main():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    data = rows(sys.argv[1])
    one = [r for r in data if r[0] == 1]
    two = [r for r in data if r[0] == 2]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4))
    n = [r[1] for r in one]
    ax.plot(n, [r[2] for r in one], "o-", label="1 rank")
    if two:
        ax.plot([r[1] for r in two], [r[2] for r in two], "s", label="2 ranks (wall time)")
    ax.axhline(1.2 * one[0][2], color="gray", ls="--", label="1.2 x the smallest plate's")
    against_n(ax, "Pair time per element-step (us)")
    bx.plot(n, [r[3] for r in one], "o-", label="LAMMPS's memory report, 1 rank, setup")
    if all(r[4] is not None for r in one):
        bx.plot(n, [r[4] for r in one], "^--", label="1 rank, after list builds")
    if two:
        bx.plot([r[1] for r in two], [r[3] for r in two], "s", label="2 ranks, setup")
        if all(r[4] is not None for r in two):
            bx.plot([r[1] for r in two], [r[4] for r in two], "D", label="2 ranks, after builds")
    bx.axhline(3.0, color="gray", ls="--", label="3 kB")
    against_n(bx, "memory per element (kB)")
    fig.suptitle("pair mca with the shock law: the plate of examples/mca-shock, 10 um, "
                 "200 steps from the impact", fontsize=10)
    fig.savefig(sys.argv[2], dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main()
