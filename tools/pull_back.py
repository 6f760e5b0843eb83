#!/usr/bin/python3
"""The spall strength from a free-surface velocity history (a simulated VISAR record, e.g. a
fix ave/time file of compute free/surface): the pull-back dU, the drop from the velocity's
peak to its first minimum after it, and the acoustic spall strength 1/2 rho0 c0 dU.

    /usr/bin/python3 tools/pull_back.py target.visar --rho0 2700 --c0 6386 --flyer 1.41e-4
    /usr/bin/python3 tools/pull_back.py FILE --rho0 RHO --c0 C (--flyer H | --pulse T)
                                        [--time-column 1] [--velocity-column 2] [--smooth 5]
                                        [--rebound 0.1]

FILE: whitespace columns, '#' comments (fix ave/time writes the step first, then its values).
The peak is sought within the pulse duration after the shock's arrival (the first record at
half the largest velocity), the minimum within a pulse duration after the peak; the
velocities are first smoothed by a running mean of --smooth records (a lattice's face rings).
With --rebound F the minimum is the lowest before the record rises again by F times the peak
velocity (the spall signal's first rise): a lattice's face rings after the spall and a later
ring can dip below the pull-back's minimum within the pulse duration.
The pulse lasts 2 H / c0 for a flyer of thickness H.

Which c0: the longitudinal sound speed of the unloaded material along the impact, the speed
at which the release (the pull-back's signal) travels: for a continuum
c_L = sqrt((K + 4G/3)/rho0), for a lattice of clusters its longitudinal speed along the
impact direction (compute pair/params: v0 for fcc [100], v_l for the isotropic average).
Not the bulk speed sqrt(K/rho0), which the experiments' analysis uses with a correction for
the elastic-plastic release; rho0 is the density of the unloaded target (of the clusters'
lattice, not the metal's, for cluster dynamics).  Units: those of the inputs (SI: Pa).

As a module: pull_back(t, v, pulse, smooth=5) -> (t_peak, v_peak, t_min, v_min).
"""
import argparse
import sys

import numpy as np


def pull_back(t, v, pulse, smooth=5, rebound=0.0):
    """The spall signal of a free-surface velocity history (noisy: a running mean over
    `smooth` records first): from the arrival of the shock (half the largest velocity), the
    peak within the pulse duration `pulse` (time), then the lowest velocity within `pulse`
    after the peak; with rebound > 0, the lowest before the record first rises again by that
    share of the peak velocity (the spall signal: a lattice's face rings after it, and a later
    ring can dip lower): (t_peak, v_peak, t_min, v_min)."""
    vs = np.convolve(v, np.ones(smooth) / smooth, mode="same")
    arrived = np.where(vs > 0.5 * vs.max())[0][0]
    plateau = np.where((t >= t[arrived]) & (t <= t[arrived] + pulse))[0]
    peak = plateau[np.argmax(vs[plateau])]
    after = np.where((t >= t[peak]) & (t <= t[peak] + pulse))[0]
    low = after[np.argmin(vs[after])]
    if rebound > 0.0:
        low = after[0]
        for k in after:
            if vs[k] < vs[low]:
                low = k
            elif vs[k] - vs[low] > rebound * vs[peak]:
                break
    return t[peak], vs[peak], t[low], vs[low]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("file")
    ap.add_argument("--rho0", type=float, required=True, help="density of the unloaded target")
    ap.add_argument("--c0", type=float, required=True,
                    help="longitudinal sound speed along the impact (see below)")
    pulse = ap.add_mutually_exclusive_group(required=True)
    pulse.add_argument("--flyer", type=float, help="flyer thickness: the pulse lasts 2 H / c0")
    pulse.add_argument("--pulse", type=float, help="the pulse duration (time units)")
    ap.add_argument("--time-column", type=int, default=1, help="0-based (default 1)")
    ap.add_argument("--velocity-column", type=int, default=2, help="0-based (default 2)")
    ap.add_argument("--smooth", type=int, default=5, help="running mean over N records")
    ap.add_argument("--rebound", type=float, default=0.0,
                    help="the minimum before the record rises again by this share of the peak "
                         "velocity (e.g. 0.1 for a ringing lattice face; default 0: the lowest "
                         "within a pulse duration after the peak)")
    args = ap.parse_args(argv)
    for name in ("rho0", "c0", "flyer", "pulse"):
        value = getattr(args, name)
        if value is not None and not value > 0.0:
            ap.error(f"--{name} must be positive (got {value})")
    if args.smooth < 1:
        ap.error(f"--smooth must be at least 1 (got {args.smooth})")
    try:
        data = np.loadtxt(args.file, ndmin=2)
        t, v = data[:, args.time_column], data[:, args.velocity_column]
    except (OSError, ValueError, IndexError) as err:
        ap.error(f"cannot read the time and velocity columns of {args.file}: {err}")
    if len(t) < 2 * args.smooth or not np.any(v > 0.0):
        ap.error(f"{args.file}: {len(t)} records, no positive velocity: no shock arrived")
    duration = args.pulse if args.pulse else 2.0 * args.flyer / args.c0
    if not 0.0 <= args.rebound < 1.0:
        ap.error(f"--rebound must be in [0, 1) (got {args.rebound})")
    tp, vp, tm, vm = pull_back(t, v, duration, args.smooth, args.rebound)
    du = vp - vm
    print(f"peak {vp:.6g} at {tp:.6g}; minimum {vm:.6g} at {tm:.6g}; pull-back dU = {du:.6g}")
    print(f"spall strength 1/2 rho0 c0 dU = {0.5 * args.rho0 * args.c0 * du:.6g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
