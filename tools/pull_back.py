#!/usr/bin/python3
"""The spall strength from a free-surface velocity history (a simulated VISAR record, e.g. a
fix ave/time file of compute free/surface): the pull-back dU, the drop from the velocity's
peak to its first minimum after it, and the acoustic spall strength 1/2 rho0 c0 dU.

    /usr/bin/python3 tools/pull_back.py target.visar --rho0 2700 --c0 6386 --flyer 1.41e-4
    /usr/bin/python3 tools/pull_back.py FILE --rho0 RHO --c0 C (--flyer H | --pulse T)
                                        [--time-column 1] [--velocity-column 2] [--smooth 5]
                                        [--rebound 0.1] [--jump-column 5]

FILE: whitespace columns, '#' comments (fix ave/time writes the step first, then its values);
columns are 0-based.  The time must increase strictly from record to record (two runs
appended to one file are refused where the time goes back) and every value the reading uses
must be finite.

The reading: the velocities are first smoothed by a centred running mean of --smooth records
(a lattice's face rings; an even N averages N + 1 records, the two outer ones at half
weight); at the ends of the record the window shrinks to the records there are (the last
record is its own mean), so the mean never reads past the record.  The shock arrives at the
first record above half the largest velocity; the peak is the highest within the pulse
duration after the arrival, the minimum the lowest within a pulse duration after the peak.
With --rebound F the minimum is the lowest before the record rises again by F times the peak
velocity (the spall signal's first rise): a lattice's face rings after the spall and a later
ring can dip below the pull-back's minimum within the pulse duration.  The pulse lasts
2 H / c0 for a flyer of thickness H; it must span at least 3 record spacings (the median
spacing) and at least --smooth of them.  A record whose velocity never falls after its peak
(it stays flat, or still rises, or peaks at its last record), or falls by less than 1 % of
its peak (a steady face's ringing), has no pull-back and is refused.
A record that ends while the velocity still falls reads the drop to its last record (a
lower bound: a note says so).

--jump-column K: the column of compute free/surface's jump count (its 4th output: column 5
after fix ave/time's v_now c_face[*]), the cumulative count of evaluations at which the face
lay more than its depth away from where the previous evaluation's face and velocity put it
(or vanished).  A change of the count from one record to the next after the shock's arrival
(less the smoothing's half width, as far back as the smoothed peak reads), up to the end of the reading's window (the minimum, or with --rebound the record where the
rise was found, plus the smoothing's half width, as far as the smoothed velocity there
reads) is refused: the face record has a gap there, the face was set by another piece of the
body (a piece of the spalled layer counted as dust for a while, or one re-attached): give
compute free/surface the minsize keyword (the atoms of one lattice plane of the target's
section) or check compute dust's maxsize.  Changes before the arrival or after the window do
not touch the reading.  Without the column a gap is not detected: a record that dips and
recovers within a few records may be a gap or the face's own ringing (a lattice face rings
by more than half the peak velocity within a few records, and a pull-back near the spall
threshold falls almost to rest), and how many records a dip spans depends on the recording
interval, not on the physics; so no rule on the velocity alone tells them apart.

Which c0 and rho0: c0 is the longitudinal sound speed of the unloaded target along the
impact, the speed of the release that carries the pull-back: for a continuum, movable
cellular automata or peridynamics target c_L = sqrt((K + 4G/3)/rho0); for a lattice of
clusters its own longitudinal speed along the impact (compute pair/params: v0 for fcc
[100], v_l for the isotropic average), which for a set made by tools/cd_calibrate.py's
metal calibration is the Hugoniot c0 the set was matched to (the lattice's elastic wave and
its shock are one), not the metal's handbook longitudinal speed (that reads the strength
20 % high for aluminium: 6420 against 5350 m/s).  rho0 is the density of the unloaded
target: for clusters their lattice's density, which for a metal-calibrated set is the
metal's.  Not the bulk speed sqrt(K/rho0), which the experiments' analysis uses with a
correction for the elastic-plastic release.  Units: those of the inputs (SI: Pa).

As a module: pull_back(t, v, pulse, smooth=5, rebound=0.0) -> (t_peak, v_peak, t_min, v_min)
(keywords lines= and jumps=: the records' line numbers for the messages, the jump counts);
it raises ValueError with the reason where a record or an argument is refused.
"""
import argparse
import math
import sys

import numpy as np

SHOWN = 5           # records named in a message, then how many in all


def _named(k, t, lines):
    where = f"line {lines[k]}" if lines is not None else f"record {k}"
    return f"{where} (t = {t[k]:.6g})"


def _listed(ks, t, lines):
    names = ", ".join(_named(k, t, lines) for k in ks[:SHOWN])
    return names + (f" ... ({len(ks)} in all)" if len(ks) > SHOWN else "")


# the least pull-back read, as a share of the peak velocity: the lattice faces' spall signals
# are 3.4 % (copper's set at 400 m/s) and more; a steady face ringing after a detachment
# wiggles by 0.35 % (doc/plate_impact.rst)
MIN_PULL_BACK = 0.01


def smoothed(v, smooth):
    """The centred running mean over `smooth` records (an even N: N + 1 records, the outer two
    at half weight), its window shrinking at the ends of the record to the records there are:
    never reads past the record.  Summed as deviations from the centre, so that a flat stretch
    stays exactly flat."""
    n = len(v)
    half = min(smooth // 2, n)
    k = np.arange(n)
    reach = np.minimum(np.minimum(k, n - 1 - k), half)
    total, norm = np.zeros(n), np.zeros(n)
    for j in range(-half, half + 1):
        outer = abs(j) == half and smooth % 2 == 0 and half > 0
        w = np.where((reach == half) & outer, 0.5, 1.0) * (abs(j) <= reach)
        total += w * (v[np.clip(k + j, 0, n - 1)] - v)
        norm += w
    return v + total / norm


def _checked_arguments(pulse, smooth, rebound):
    if not (math.isfinite(pulse) and pulse > 0.0):
        raise ValueError(f"the pulse duration must be a finite number > 0 (got {pulse})")
    if isinstance(smooth, bool) or not float(smooth).is_integer() or smooth < 1:
        raise ValueError(f"smooth must be an integer >= 1 (got {smooth})")
    if not (math.isfinite(rebound) and 0.0 <= rebound < 1.0):
        raise ValueError(f"rebound must be in [0, 1) (got {rebound})")


def _checked_record(t, v, pulse, smooth, lines, jumps):
    shapes = [x.shape for x in (t, v, jumps) if x is not None]
    if t.ndim != 1 or len(set(shapes)) > 1:
        raise ValueError(f"time, velocity (and jump count) must be 1-D and of one length "
                         f"(got the shapes {', '.join(map(str, shapes))})")
    if len(t) < 3:
        raise ValueError(f"the record holds {len(t)} records: too few for a pull-back")
    for name, x in (("time", t), ("velocity", v), ("jump count", jumps)):
        bad = [] if x is None else np.where(~np.isfinite(x))[0]
        if len(bad):
            raise ValueError(f"the {name} is not finite (NaN, inf or out of range) at "
                             f"{_listed(bad, t, lines)}")
    back = np.where(np.diff(t) <= 0.0)[0] + 1
    if len(back):
        raise ValueError(f"the time does not increase (it goes back or repeats: runs appended "
                         f"to one file?) at {_listed(back, t, lines)}")
    spacing = float(np.median(np.diff(t)))
    need = max(3, smooth)
    if pulse < need * spacing:
        raise ValueError(f"the pulse duration {pulse:.6g} spans {pulse / spacing:.3g} record "
                         f"spacings (the median spacing {spacing:.6g}): fewer than {need} "
                         f"(3 and the smoothing's {smooth}); give the pulse in the record's time "
                         f"units, or record more often")


def pull_back(t, v, pulse, smooth=5, rebound=0.0, *, lines=None, jumps=None):
    """The spall signal of a free-surface velocity history (noisy: a centred running mean over
    `smooth` records first, see smoothed()): from the arrival of the shock (half the largest
    velocity), the peak within the pulse duration `pulse` (time), then the lowest velocity
    within `pulse` after the peak; with rebound > 0, the lowest before the record first rises
    again by that share of the peak velocity (the spall signal: a lattice's face rings after
    it, and a later ring can dip lower): (t_peak, v_peak, t_min, v_min).  lines: the records'
    line numbers in their file (for the messages); jumps: compute free/surface's jump count
    per record (a change in the reading's window is refused).  ValueError where refused."""
    _checked_arguments(pulse, smooth, rebound)
    t, v = np.asarray(t, dtype=float), np.asarray(v, dtype=float)
    jumps = None if jumps is None else np.asarray(jumps, dtype=float)
    _checked_record(t, v, pulse, smooth, lines, jumps)
    vs = smoothed(v, int(smooth))
    if not vs.max() > 0.0:
        raise ValueError(f"{len(t)} records, no positive velocity: no shock arrived")
    arrived = np.where(vs > 0.5 * vs.max())[0][0]
    plateau = np.where((t >= t[arrived]) & (t <= t[arrived] + pulse))[0]
    peak = plateau[np.argmax(vs[plateau])]
    if peak == len(t) - 1:
        raise ValueError(f"no pull-back in the record: the velocity peaks at its last record, "
                         f"{_named(peak, t, lines)}")
    after = np.where((t >= t[peak]) & (t <= t[peak] + pulse))[0]
    low = end = after[np.argmin(vs[after])]
    if rebound > 0.0:
        low = end = after[0]
        for k in after:
            if vs[k] < vs[low]:
                low = end = k
            elif vs[k] - vs[low] > rebound * vs[peak]:
                end = k
                break
    if low == peak:
        raise ValueError(f"no pull-back in the record: the velocity never falls within the "
                         f"pulse duration after its peak at {_named(peak, t, lines)}")
    if jumps is not None:
        last = min(end + int(smooth) // 2, len(t) - 1)
        first = max(arrived + 1 - int(smooth) // 2, 1)    # the smoothed peak reads back so far
        gaps = [k for k in range(first, last + 1) if jumps[k] != jumps[k - 1]]
        if gaps:
            raise ValueError(
                f"the face record has a gap: the jump count changes at {_listed(gaps, t, lines)}"
                f", between the shock's arrival at {_named(arrived, t, lines)} and the end of "
                f"the reading's window at {_named(last, t, lines)}: the face was set there by "
                f"another piece of the body (a piece of the spalled layer counted as dust for "
                f"a while, or one re-attached): give compute free/surface's minsize keyword "
                f"(the atoms of one lattice plane of the target's section) or check compute "
                f"dust's maxsize")
    if vs[peak] - vs[low] < MIN_PULL_BACK * abs(vs[peak]):
        raise ValueError(f"no pull-back in the record: the velocity falls by "
                         f"{vs[peak] - vs[low]:.4g} after its peak {vs[peak]:.6g} at "
                         f"{_named(peak, t, lines)}, less than {100 * MIN_PULL_BACK:g} % of it: "
                         f"the face's ringing, not a spall signal")
    return t[peak], vs[peak], t[low], vs[low]


def read_columns(path, columns):
    """The named 0-based columns ({argument: column}) of a whitespace file with '#' comments:
    (line numbers, {argument: values}); ValueError naming the line and the argument."""
    lines, rows = [], []
    with open(path) as f:
        for number, text in enumerate(f, 1):
            fields = text.split("#", 1)[0].split()
            if not fields:
                continue
            row = []
            for name, c in columns.items():
                if c >= len(fields):
                    raise ValueError(f"{name} {c} is beyond line {number}'s {len(fields)} "
                                     f"columns (0-based: 0 to {len(fields) - 1})")
                try:
                    row.append(float(fields[c]))
                except ValueError:
                    raise ValueError(f"line {number}: {fields[c]!r} ({name} {c}) is not a "
                                     f"number") from None
            lines.append(number)
            rows.append(row)
    if not rows:
        raise ValueError("no records (only comments or blank lines)")
    data = np.array(rows)
    return lines, {name: data[:, i] for i, name in enumerate(columns)}


def _number(low, high=math.inf, closed_low=False):
    """An argparse type: a finite float in (low, high), or [low, high) with closed_low."""
    def parse(text):
        x = float(text)
        if not (math.isfinite(x) and (x >= low if closed_low else x > low) and x < high):
            bounds = (f"> {low:g}" if high == math.inf else
                      f"in {'[' if closed_low else '('}{low:g}, {high:g})")
            raise argparse.ArgumentTypeError(f"must be a finite number {bounds} (got {text})")
        return x
    parse.__name__ = "number"
    return parse


def _count(least):
    def parse(text):
        k = int(text)
        if k < least:
            raise argparse.ArgumentTypeError(f"must be an integer >= {least} (got {text})")
        return k
    parse.__name__ = "integer"
    return parse


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("file")
    ap.add_argument("--rho0", type=_number(0.0), required=True,
                    help="density of the unloaded target (see below)")
    ap.add_argument("--c0", type=_number(0.0), required=True,
                    help="longitudinal sound speed of the unloaded target along the impact "
                         "(see below)")
    pulse = ap.add_mutually_exclusive_group(required=True)
    pulse.add_argument("--flyer", type=_number(0.0),
                       help="flyer thickness: the pulse lasts 2 H / c0")
    pulse.add_argument("--pulse", type=_number(0.0), help="the pulse duration (time units)")
    ap.add_argument("--time-column", type=_count(0), default=1, help="0-based (default 1)")
    ap.add_argument("--velocity-column", type=_count(0), default=2, help="0-based (default 2)")
    ap.add_argument("--jump-column", type=_count(0),
                    help="0-based: compute free/surface's jump count (see below)")
    ap.add_argument("--smooth", type=_count(1), default=5,
                    help="centred running mean over N records (default 5)")
    ap.add_argument("--rebound", type=_number(0.0, 1.0, closed_low=True), default=0.0,
                    help="the minimum before the record rises again by this share of the peak "
                         "velocity (e.g. 0.1 for a ringing lattice face; default 0: the lowest "
                         "within a pulse duration after the peak)")
    args = ap.parse_args(argv)
    columns = {"--time-column": args.time_column, "--velocity-column": args.velocity_column}
    if args.jump_column is not None:
        columns["--jump-column"] = args.jump_column
    if len(set(columns.values())) < len(columns):
        ap.error("the columns must differ: " + ", ".join(f"{k} {c}" for k, c in columns.items()))
    duration = args.pulse if args.pulse else 2.0 * args.flyer / args.c0
    if not (math.isfinite(duration) and duration > 0.0):
        ap.error(f"the pulse 2 --flyer / --c0 = {duration} is not a finite number > 0")
    try:
        lines, data = read_columns(args.file, columns)
        tp, vp, tm, vm = pull_back(data["--time-column"], data["--velocity-column"], duration,
                                   args.smooth, args.rebound, lines=lines,
                                   jumps=data.get("--jump-column"))
    except (OSError, ValueError) as err:
        ap.error(f"{args.file}: {err}")
    du = vp - vm
    print(f"peak {vp:.6g} at {tp:.6g}; minimum {vm:.6g} at {tm:.6g}; pull-back dU = {du:.6g}")
    print(f"spall strength 1/2 rho0 c0 dU = {0.5 * args.rho0 * args.c0 * du:.6g}")
    if tm == data["--time-column"][-1]:
        print(f"note: the minimum is the record's last record (line {lines[-1]}): the record "
              f"ends before the velocity rises again, the pull-back may be deeper",
              file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
