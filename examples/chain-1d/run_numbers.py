#!/usr/bin/python3
"""The numbers of the dusting paper's sections 3-4 (Piskunov, Tsaplin & Veselov 2011,
doc/references.rst) measured on in.chain, next to the paper's: the relative speeds of
neighbouring boundary clusters at u = 2 km/s (Morse w ~ 2u, harmonic w ~ u/4), the period of
their oscillation (Table 1's T_M, harmonic T_G) next to T_min(u) = pi a / c(u), the shock
heating at 4 km/s (8 MJ/kg) and Table 1's c(u)/c0 with the measured shock front speed.

    source build/env.sh; /usr/bin/python3 examples/chain-1d/run_numbers.py   # about 1 min

Writes numbers.md and cu.png next to this file.

Measures (the ten boundary clusters are sampled every 2 steps, dt = T0/200):
- w: the largest |v_(k+1) - v_k| of the nine neighbour pairs after the shock reaches the first
  of them (v > u/2), per pair; the table gives their range.
- the period: twice the median spacing of the first eight zero crossings of w - mean(w) of the
  innermost pair after that arrival (the oscillation the shock leaves as it reaches the surface;
  later the pair's bond may break).
- the front speed: the shock reaches cluster k (at k a at the start) at t_k (v_k > u/2); the
  front's speed into the chain at rest is k a / t_k, fitted over the ten boundary clusters.
- the heating: a run of a quarter transit (the front at 0.7 of the chain); the clusters the shock
  reached (|v| > u/20; ahead of the front the chain is at rest) hold the piston's work W and
  impulse P; their internal energy per mass is (W - P^2/(2M))/M (the mean flow's kinetic
  energy taken off), split into the compression energy at their mean spacing y a,
  (Pi(y a) - Pi(a))/m per cluster, and the rest (heat).
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import run_study  # noqa: E402

A = 1.0e-5
M = 2.338e-12
D, ALPHA = 2.46e-6, 3.76e5        # potentials/al-cluster-10um.cd
TABLE1 = {50: (1.050, 5.49, 11), 500: (1.409, 4.09, 5.5), 1000: (1.721, 3.35, 4.5),
          2000: (2.238, 2.57, 3), 4000: (3.084, 1.87, 1.9), 10000: (5.099, 1.13, 1)}
# u: c(u)/c0, T_min (1e-9 s), T_M (1e-9 s)


def morse(r):
    e = math.exp(-ALPHA * (r - A))
    return D * (e * e - 2 * e)


def morse_force(r):                  # -dPi/dr
    e = math.exp(-ALPHA * (r - A))
    return 2 * ALPHA * D * (e * e - e)


def hugoniot_speed(u):
    """Rankine-Hugoniot shock speed of the nearest-neighbour Morse chain: mass y = 1 - u/Us,
    momentum (m/a) Us u = -Pi'(y a) (the secant stiffness; c(u) of eq 8 is the tangent one)."""
    lo, hi = u * 1.0001, 1e6
    for _ in range(200):
        us = 0.5 * (lo + hi)
        if M / A * us * u > morse_force((1 - u / us) * A):
            hi = us
        else:
            lo = us
    return us


def boundary(r, u):
    s = r["series"]
    t, v = s[:, 0], s[:, 11:21]
    w = np.diff(v, axis=1)
    arrive = [np.argmax(v[:, k] > u / 2) for k in range(10)]
    amp = np.abs(w[arrive[0]:]).max(axis=0)
    seg = w[arrive[0]:, 0] - w[arrive[0]:, 0].mean()
    crossings = np.where(np.diff(np.sign(seg)) != 0)[0]
    period = 2 * np.median(np.diff(t[arrive[0]:][crossings])[:8])
    n = len(r["x"]) - 1
    ks = np.arange(n - 9, n + 1)
    front = np.polyfit(t[arrive], ks * A, 1)[0]
    return amp, period, front


def heating(u):
    r = run_study.run(u=u, transits=0.25)
    v = r["v"][1:]
    count = int(np.nonzero(np.abs(v) > 0.05 * u)[0].max()) + 1     # clusters the shock reached
    mass = count * M
    flow = r["impulse"] / mass                  # their mean velocity: momentum = impulse
    internal = (r["work"] - 0.5 * mass * flow * flow) / mass
    y = (r["x"][count] - r["x"][0]) / (count * A)   # their mean spacing / a
    cold = (morse(y * A) - morse(A)) / M
    return {"internal": internal, "cold": cold, "heat": internal - cold, "y": y, "count": count,
            "flow": flow}


def main():
    lines = ["| quantity | paper | ours |", "|---|---|---|"]
    amps = {}
    for law in ("morse", "harmonic"):
        r = run_study.run(u=2000, law=law, every=2)
        amps[law] = boundary(r, 2000)
    a, p, _ = amps["morse"]
    lines.append(f"| Morse, u = 2 km/s: relative speed amplitude w of boundary neighbours | ~2u = 4000 m/s "
                 f"| {a.min():.0f}-{a.max():.0f} m/s (median {np.median(a):.0f}) |")
    a, p, _ = amps["harmonic"]
    lines.append(f"| harmonic, u = 2 km/s: w | ~u/4, about 500 m/s | {a.min():.0f}-{a.max():.0f} m/s "
                 f"(median {np.median(a):.0f}) |")
    lines.append(f"| harmonic: period T_G of the boundary clusters | 1.2e-8 s | {p:.3g} s |")
    rows, fronts = [], {}
    for u in TABLE1:
        theta = 0.005 if u <= 4000 else 0.05
        r = run_study.run(u=u, every=2, theta=theta, dtrule="T0" if u <= 4000 else "Tmin")
        _, period, front = boundary(r, u)
        fronts[u] = (front, r["c_u"], r["c0"], period, r["tmin"])
        rows.append(f"| {u} | {TABLE1[u][0]:.3f} | {r['c_u'] / r['c0']:.3f} | {TABLE1[u][1]} | "
                    f"{r['tmin'] * 1e9:.2f} | {TABLE1[u][2]} | {period * 1e9:.2f} | "
                    f"{front / r['c0']:.3f} | {hugoniot_speed(u) / r['c0']:.3f} |")
    h = heating(4000)
    lines.append(f"| Morse, u = 4 km/s: shock heating | 8 MJ/kg (Al vaporisation 11 MJ/kg) | internal "
                 f"energy {h['internal'] / 1e6:.2f} MJ/kg (Hugoniot u^2/2 = 8.00; {h['count']} clusters "
                 f"at mean {h['flow']:.0f} m/s): compression "
                 f"{h['cold'] / 1e6:.2f} (y = {h['y']:.3f}), heat {h['heat'] / 1e6:.2f} MJ/kg |")
    lines += ["", "| u (m/s) | c(u)/c0 paper | compute pair/params | T_min paper (ns) | ours | "
              "T_M paper (ns) | measured period (ns) | front speed / c0, measured | Hugoniot "
              "(secant) |", "|---|---|---|---|---|---|---|---|---|"] + rows
    open(os.path.join(HERE, "numbers.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot(fronts, os.path.join(HERE, "cu.png"))


def plot(fronts, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    us = sorted(fronts)
    c0 = fronts[us[0]][2]
    grid = np.linspace(0, 10000, 101)
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.2))
    ax.plot(us, [fronts[u][1] / c0 for u in us], "-", marker=".", color="C0",
            label="compute pair/params c(u) (eq 8, tangent stiffness)")
    ax.plot(list(TABLE1), [v[0] for v in TABLE1.values()], "s", mfc="none", ms=9, color="k",
            label="paper, Table 1")
    ax.plot(grid[1:], [hugoniot_speed(u) / c0 for u in grid[1:]], "--", color="C2",
            label="Rankine-Hugoniot shock speed (secant)")
    ax.plot(us, [fronts[u][0] / c0 for u in us], "o", color="C3",
            label="front speed measured in the chain")
    ax.set_xlabel("piston speed u (m/s)")
    ax.set_ylabel("speed / c0")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    bx.plot(us, [fronts[u][4] * 1e9 for u in us], "-", marker=".", color="C0",
            label="T_min(u) = pi a / c(u), compute pair/params")
    bx.plot(list(TABLE1), [v[2] for v in TABLE1.values()], "s", mfc="none", ms=9, color="k",
            label="T_M, paper (Table 1)")
    bx.plot(us, [fronts[u][3] * 1e9 for u in us], "o", color="C3",
            label="period of the boundary clusters, measured")
    bx.set_xscale("log")
    bx.set_yscale("log")
    bx.set_xlabel("piston speed u (m/s)")
    bx.set_ylabel("period (ns)")
    bx.legend(fontsize=8)
    bx.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
