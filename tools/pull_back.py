#!/usr/bin/python3
"""The spall strength from a free-surface velocity history (a simulated VISAR record, e.g. a
fix ave/time file of compute free/surface): the pull-back dU, the drop from the velocity's
peak to its first minimum after it, and the spall strength by the acoustic formula with
Kanel's correction for the elastic-plastic release, sigma_sp = 1/2 rho0 c_b (dU + delta).

    /usr/bin/python3 tools/pull_back.py plate.visar --rho0 2703 --c-bulk 5350 --c-long 6438 \\
                                        --flyer 1.414e-4
    /usr/bin/python3 tools/pull_back.py plate.visar --rho0 3306 --c-long 5454 --flyer 1.41e-4
    /usr/bin/python3 tools/pull_back.py FILE --rho0 RHO --c-long CL [--c-bulk CB]
                                        (--flyer H | --pulse T) [--spall-thickness h]
                                        [--window W] [--rebound 0.1] [--jump-column 5]
                                        [--time-column 1] [--velocity-column 2]

FILE: whitespace columns, '#' comments (fix ave/time writes the step first, then its values);
columns are 0-based.  The time must increase strictly from record to record (two runs
appended to one file are refused where the time goes back) and every value the reading uses
must be finite.

The formula (G. I. Kanel, S. V. Razorenov, A. V. Utkin, "Spallation in solids under
shock-wave loading: analysis of dynamic flow, methodology of measurements, and constitutive
factors", in High-Pressure Shock Compression of Solids II, ed. L. Davison, D. E. Grady,
M. Shahinpoor, Springer, New York, 1996, pp. 1-24; G. I. Kanel, "Spall fracture:
methodological aspects, mechanisms and governing factors", Int. J. Fract. 163 (2010)
173-182):
    sigma_sp = 1/2 rho0 c_b (dU + delta),
    delta = h (1/c_b - 1/c_l) |u1'| u2' / (|u1'| + u2')
The release ahead of the pull-back's minimum is plastic and runs at the bulk speed c_b, the
front of the spall pulse after it is elastic and runs at the longitudinal speed c_l: over the
spall layer's thickness h the front catches up on the release and the free surface sees the
minimum cut short by delta.  u1' (< 0) is the velocity gradient of the release ahead of the
minimum, u2' (> 0) that of the spall pulse front after it, both from the smoothed record:
u1' the mean slope from 10 % to 90 % of the drop dU (the last crossing of peak - 0.1 dU
before the minimum to the first crossing of peak - 0.9 dU after it), u2' the mean slope from
10 % to 90 % of the rise R after the minimum (R: from the minimum to the top of the front,
the highest velocity after the minimum before the record falls back from it by 0.1 dU, or a
pulse duration after the minimum, or the record's end).  The plain acoustic values 1/2 rho0
c_b dU and 1/2 rho0 c_l dU are printed beside for comparison.

Which speeds: --c-bulk c_b = sqrt(K/rho0), the bulk sound speed (pair_coeff mca's
`shock rho0 c0 ...` c0, the Hugoniot's us = c0 + s up intercept); --c-long c_l =
sqrt((K + 4G/3)/rho0), the longitudinal speed of the unloaded target along the impact.  A
target whose release is not elastic-plastic (an elastic target: movable cellular automata
without yield, peridynamics; a lattice of clusters, whose elastic and shock waves are one)
has one speed: give --c-long alone (or --c-bulk equal to it): c_b = c_l, delta = 0 and the
strength is 1/2 rho0 c_l dU.  For a lattice of clusters c_l is its own longitudinal speed
along the impact (compute pair/params: v0 for fcc [100], v_l for the isotropic average), which
for a set made by tools/cd_calibrate.py's metal calibration is the Hugoniot c0 the set was
matched to, not the metal's handbook longitudinal speed (that reads the strength 20 % high for
aluminium: 6420 against 5350 m/s).  --c-bulk alone is refused (a metal's bulk speed without
its longitudinal one has no correction).  rho0 is the density of the unloaded target: for
clusters their lattice's density, which for a metal-calibrated set is the metal's.  Units:
those of the inputs (SI: Pa); the slopes in velocity per time unit.

h, the spall layer's thickness: --spall-thickness, by default the flyer's thickness --flyer
(a symmetric impact of a flyer of thickness H on a target of 2H: the release waves meet H
below the free face).  With --pulse and two speeds, --spall-thickness is required.

The pulse: it lasts 2 H / c_b for a flyer of thickness H (the longer of 2 H / c_b and
2 H / c_l: the plastic pulse), or --pulse T; it must span at least 3 record spacings (the
median spacing).  The reading looks for the peak within a pulse duration after the shock's
arrival (the first record above half the largest velocity), and for the minimum within a
pulse duration after the peak.  With --rebound F the minimum is the lowest before the record
rises again by F times the peak velocity (the spall signal's first rise): a lattice's face
rings after the spall and a later ring can dip below the pull-back's minimum within the pulse
duration.  A record whose velocity never falls after its peak (it stays flat, or still
rises, or peaks at its last record), or falls by less than 1 % of its peak (a steady face's
ringing), has no pull-back and is refused.  A record that ends while the velocity still
falls reads the drop to its last record (a lower bound: a note says so); one without a rise
after the minimum has no u2' and reads delta = 0 (a lower bound: a note says so).

The smoothing: a centred running mean over a time window --window W (time units; default a
tenth of the pulse duration, 2 H / (10 c_b): for a flyer of 10 lattice cells the time the
wave takes to cross 2 cells, about the ringing period of a lattice's face, and short against
the release and the spall pulse's front), the mean over |t - t_k| <= W/2 of the record's
piecewise-linear interpolant (the records weighed by the time they stand for: 200, 400 or 800
records of one run read alike).  At the ends of the record the window shrinks symmetrically to
the records there are (half-width min(W/2, t_k - t_first, t_last - t_k): the last record is
its own mean), so the mean never reads past the record and a straight line stays straight.
W = 0: no smoothing.  W above half the pulse duration is refused (it averages the pull-back
away).

A record with records missing between the shock's arrival and the minimum (a spacing wider
than the smoothing window and than two median spacings) is refused, naming the two records
around the gap: the smoothed velocity would interpolate across it and read a shallower minimum.

--jump-column K: the column of compute free/surface's jump count (its 4th output: column 5
after fix ave/time's v_now c_face[*]), the cumulative count of evaluations at which the face
lay more than its depth away from where the previous evaluation's face and velocity put it
(or vanished).  A change of the count between two records whose interval overlaps the span
the reading reads, from the shock's arrival less half the window to the end of the reading's
window (the minimum, or with --rebound the record where the rise was found) plus half the
window, is refused: the face record has a gap there, the face was set by another piece of the
body (a piece of the spalled layer counted as dust for a while, or one re-attached): give
compute free/surface the minsize keyword (the atoms of one lattice plane of the target's
section) or check compute dust's maxsize.  Changes before or after that span do not touch the
reading.  Without the column a gap is not detected: a record that dips and recovers within a
few records may be a gap or the face's own ringing (a lattice face rings by more than half
the peak velocity within a few records, and a pull-back near the spall threshold falls almost
to rest), so no rule on the velocity alone tells them apart.

As a module: spall_strength(t, v, pulse, rho0, c_long, c_bulk=None, thickness=None,
window=None, rebound=0.0) -> a Reading (the peak, the minimum, dU, u1', u2', delta, sigma_sp
and the two acoustic values); pull_back(t, v, pulse, window=None, rebound=0.0) -> (t_peak,
v_peak, t_min, v_min); slopes(t, vs, peak, low, pulse) -> (u1', u2'); smoothed(t, v, window).
Keywords lines= and jumps=: the records' line numbers for the messages, the jump counts.
They raise ValueError with the reason where a record or an argument is refused.
"""
import argparse
import math
import os
import sys
from dataclasses import dataclass, field

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_numbers import numbers_take_values  # noqa: E402

SHOWN = 5           # records named in a message, then how many in all

# the least pull-back read, as a share of the peak velocity: the lattice faces' spall signals
# are 3.4 % (copper's set at 400 m/s) and more; a steady face ringing after a detachment
# wiggles by 0.35 % (doc/plate_impact.rst)
MIN_PULL_BACK = 0.01
# the default smoothing window, as a share of the pulse duration
WINDOW_SHARE = 0.1
# the slopes: the mean slope between these shares of the drop (and of the rise)
LOW_SHARE, HIGH_SHARE = 0.1, 0.9
# the top of the spall pulse's front: where the record falls back from it by this share of dU
FALL_BACK = 0.1


def _named(k, t, lines):
    where = f"line {lines[k]}" if lines is not None else f"record {k}"
    return f"{where} (t = {t[k]:.6g})"


def _listed(ks, t, lines):
    names = ", ".join(_named(k, t, lines) for k in ks[:SHOWN])
    return names + (f" ... ({len(ks)} in all)" if len(ks) > SHOWN else "")


def smoothed(t, v, window):
    """The centred running mean over the time window `window`: at each record t_k the mean of
    the record's piecewise-linear interpolant over |t - t_k| <= h_k, h_k = min(window/2,
    t_k - t_first, t_last - t_k) (the window shrinks symmetrically at the ends of the record:
    never reads past it; the first and last records are their own means).  Summed as
    deviations from the centre, so that a flat stretch stays exactly flat; a straight line is
    kept (to round-off) at any spacing."""
    t, v = np.asarray(t, dtype=float), np.asarray(v, dtype=float)
    out = v.copy()
    half = 0.5 * window
    n = len(t)
    if not half > 0.0 or n < 3:
        return out
    for k in range(1, n - 1):
        h = min(half, t[k] - t[0], t[-1] - t[k])
        if not h > 0.0:
            continue
        a, b = max(t[k] - h, t[0]), min(t[k] + h, t[-1])
        lo = max(int(np.searchsorted(t, a, "right")) - 1, 0)
        hi = min(int(np.searchsorted(t, b, "left")), n - 1)
        ts = np.concatenate(([a], t[lo + 1:hi], [b]))
        d = np.interp(ts, t[lo:hi + 1], v[lo:hi + 1] - v[k])
        out[k] = v[k] + float(np.sum((d[1:] + d[:-1]) * np.diff(ts))) / (2.0 * (b - a))
    return out


def default_window(pulse):
    """The default smoothing window: WINDOW_SHARE of the pulse duration."""
    return WINDOW_SHARE * pulse


def _checked_arguments(pulse, window, rebound):
    if not (math.isfinite(pulse) and pulse > 0.0):
        raise ValueError(f"the pulse duration must be a finite number > 0 (got {pulse})")
    if isinstance(window, bool) or not (math.isfinite(window) and window >= 0.0):
        raise ValueError(f"the window must be a finite time >= 0 (got {window})")
    if window > 0.5 * pulse:
        raise ValueError(f"the window {window:.6g} is longer than half the pulse duration "
                         f"{pulse:.6g}: it would average the pull-back away")
    if not (math.isfinite(rebound) and 0.0 <= rebound < 1.0):
        raise ValueError(f"rebound must be in [0, 1) (got {rebound})")


def _checked_record(t, v, pulse, lines, jumps):
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
    if pulse < 3 * spacing:
        raise ValueError(f"the pulse duration {pulse:.6g} spans {pulse / spacing:.3g} record "
                         f"spacings (the median spacing {spacing:.6g}): fewer than 3; give the "
                         f"pulse in the record's time units, or record more often")


def _reading(t, v, pulse, window, rebound, lines, jumps):
    """The pull-back's records: (smoothed velocity, peak, low, the arrival's record, the end
    of the reading's window), checked."""
    if window is None:
        window = default_window(pulse) if math.isfinite(pulse) and pulse > 0.0 else 0.0
    _checked_arguments(pulse, window, rebound)
    t, v = np.asarray(t, dtype=float), np.asarray(v, dtype=float)
    jumps = None if jumps is None else np.asarray(jumps, dtype=float)
    _checked_record(t, v, pulse, lines, jumps)
    vs = smoothed(t, v, window)
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
        first, last = t[arrived] - 0.5 * window, t[end] + 0.5 * window
        gaps = [k for k in range(1, len(t))
                if jumps[k] != jumps[k - 1] and t[k] > first and t[k - 1] < last]
        if gaps:
            k_last = min(int(np.searchsorted(t, last, "left")), len(t) - 1)
            raise ValueError(
                f"the face record has a gap: the jump count changes at {_listed(gaps, t, lines)}"
                f", between the shock's arrival at {_named(arrived, t, lines)} and the end of "
                f"the reading's window at {_named(k_last, t, lines)}: the face was set there by "
                f"another piece of the body (a piece of the spalled layer counted as dust for "
                f"a while, or one re-attached): give compute free/surface's minsize keyword "
                f"(the atoms of one lattice plane of the target's section) or check compute "
                f"dust's maxsize")
    first, last = t[arrived] - 0.5 * window, t[end] + 0.5 * window
    # a gap: records missing over more than the smoothing window (and two median spacings), so
    # that the smoothed velocity there interpolates across the missing part
    spacing = float(np.median(np.diff(t)))
    widest = max(window, 2.0 * spacing)
    holes = [k for k in range(1, len(t))
             if t[k] - t[k - 1] > widest and t[k] > first and t[k - 1] < last]
    if holes:
        k = holes[0]
        raise ValueError(
            f"the record has a gap of {(t[k] - t[k - 1]) / spacing - 1:.0f} missing records "
            f"between {_named(k - 1, t, lines)} and {_named(k, t, lines)} (the median spacing is "
            f"{spacing:.6g}), within the reading's window from the shock's arrival to the "
            f"minimum: the pull-back cannot be read across it; record the face without gaps")
    if vs[peak] - vs[low] < MIN_PULL_BACK * abs(vs[peak]):
        raise ValueError(f"no pull-back in the record: the velocity falls by "
                         f"{vs[peak] - vs[low]:.4g} after its peak {vs[peak]:.6g} at "
                         f"{_named(peak, t, lines)}, less than {100 * MIN_PULL_BACK:g} % of it: "
                         f"the face's ringing, not a spall signal")
    return t, vs, peak, low, window


def pull_back(t, v, pulse, *, window=None, rebound=0.0, lines=None, jumps=None, smooth=None):
    """The spall signal of a free-surface velocity history (noisy: a centred running mean over
    the time window `window` first, default a tenth of `pulse`, see smoothed()): from the
    arrival of the shock (half the largest velocity), the peak within the pulse duration
    `pulse` (time), then the lowest velocity within `pulse` after the peak; with rebound > 0,
    the lowest before the record first rises again by that share of the peak velocity (the
    spall signal: a lattice's face rings after it, and a later ring can dip lower):
    (t_peak, v_peak, t_min, v_min), the velocities smoothed.  lines: the records' line numbers
    in their file (for the messages); jumps: compute free/surface's jump count per record (a
    change in the reading's window is refused).  ValueError where refused."""
    if smooth is not None:
        raise ValueError("smooth (a count of records) is replaced by window (a time: the "
                         "reading no longer depends on the record interval)")
    t, vs, peak, low, _ = _reading(t, v, pulse, window, rebound, lines, jumps)
    return t[peak], vs[peak], t[low], vs[low]


def _crossing(t, vs, k, level):
    """The time at which the segment from record k to k + 1 crosses level (linear)."""
    return t[k] + (t[k + 1] - t[k]) * (level - vs[k]) / (vs[k + 1] - vs[k])


def slopes(t, vs, peak, low, pulse, fall_back=None):
    """The velocity gradients of Kanel's correction on the smoothed record vs: u1' (< 0), the
    mean slope of the release from 10 % to 90 % of the drop dU = vs[peak] - vs[low] (from the
    last crossing of vs[peak] - 0.1 dU before the minimum to the first crossing of
    vs[peak] - 0.9 dU after it), and u2' (> 0), the mean slope of the spall pulse front from
    10 % to 90 % of its rise R after the minimum (R up to the highest velocity after the
    minimum before the record falls back from it by fall_back, default 0.1 dU, within a pulse
    duration after the minimum): (u1', u2'); u2' is None where the record does not rise by
    0.1 dU after the minimum or ends while it still rises."""
    t, vs = np.asarray(t, dtype=float), np.asarray(vs, dtype=float)
    du = vs[peak] - vs[low]
    upper, lower = vs[low] + HIGH_SHARE * du, vs[low] + LOW_SHARE * du
    a = peak + int(np.where(vs[peak:low + 1] >= upper)[0][-1])
    b = a + 1 + int(np.where(vs[a + 1:low + 1] <= lower)[0][0])
    u1 = (lower - upper) / (_crossing(t, vs, b - 1, lower) - _crossing(t, vs, a, upper))
    fall_back = FALL_BACK * du if fall_back is None else fall_back
    top = low
    k = low + 1
    while k < len(t) and t[k] <= t[low] + pulse:
        if vs[k] > vs[top]:
            top = k
        elif vs[top] - vs[k] > fall_back:
            break
        k += 1
    rise = vs[top] - vs[low]
    still_rising = top == len(t) - 1
    if not rise >= FALL_BACK * du or still_rising:
        return u1, None
    upper, lower = vs[low] + HIGH_SHARE * rise, vs[low] + LOW_SHARE * rise
    a = low + int(np.where(vs[low:top + 1] >= lower)[0][0])
    b = a + int(np.where(vs[a:top + 1] >= upper)[0][0])
    u2 = (upper - lower) / (_crossing(t, vs, b - 1, upper) - _crossing(t, vs, a - 1, lower))
    return u1, u2


@dataclass
class Reading:
    """A spall strength read from a free-surface record (see spall_strength())."""
    t_peak: float
    v_peak: float
    t_min: float
    v_min: float
    du: float               # the pull-back v_peak - v_min
    u1: float               # u1', the release's gradient ahead of the minimum (< 0)
    u2: float               # u2', the spall pulse front's gradient after it (> 0; None: none)
    delta: float            # Kanel's correction (velocity)
    sigma: float            # 1/2 rho0 c_b (dU + delta)
    acoustic_bulk: float    # 1/2 rho0 c_b dU
    acoustic_long: float    # 1/2 rho0 c_l dU
    rho0: float
    c_bulk: float
    c_long: float
    thickness: float        # h (None where c_b = c_l: not needed)
    window: float           # the smoothing window used
    ends_falling: bool      # the minimum is the record's last record: dU a lower bound
    notes: list = field(default_factory=list)

    def formula(self):
        """The formula with the numbers it used."""
        return (f"sigma_sp = 1/2 rho0 c_b (dU + delta) = {self.sigma:.6g} (rho0 = {self.rho0:.6g},"
                f" c_b = {self.c_bulk:.6g}, c_l = {self.c_long:.6g}, dU = {self.du:.6g}, "
                f"delta = {self.delta:.6g})")


def _speeds(c_long, c_bulk):
    c_bulk = c_long if c_bulk is None else c_bulk
    for name, c in (("c_long", c_long), ("c_bulk", c_bulk)):
        if isinstance(c, bool) or not (math.isfinite(c) and c > 0.0):
            raise ValueError(f"{name} must be a finite number > 0 (got {c})")
    if c_bulk > c_long * (1.0 + 1e-12):
        raise ValueError(f"the bulk speed c_b = {c_bulk:.6g} exceeds the longitudinal speed "
                         f"c_l = {c_long:.6g}: sqrt(K/rho0) <= sqrt((K + 4G/3)/rho0) (are they "
                         f"swapped?)")
    return c_long, min(c_bulk, c_long)


def spall_strength(t, v, pulse, rho0, c_long, c_bulk=None, thickness=None, *, window=None,
                   rebound=0.0, lines=None, jumps=None):
    """The spall strength of a free-surface record by Kanel's formula, sigma_sp = 1/2 rho0 c_b
    (dU + delta), delta = h (1/c_b - 1/c_l) |u1'| u2' / (|u1'| + u2'): the pull-back dU as
    pull_back() reads it (pulse, window, rebound, lines, jumps as there), u1' and u2' as
    slopes() reads them on the same smoothed record; c_bulk None or equal to c_long: one speed,
    delta = 0 (an elastic target or a lattice of clusters); thickness h the spall layer's,
    required where c_b < c_l.  A Reading; ValueError where refused."""
    c_long, c_bulk = _speeds(c_long, c_bulk)
    if isinstance(rho0, bool) or not (math.isfinite(rho0) and rho0 > 0.0):
        raise ValueError(f"rho0 must be a finite number > 0 (got {rho0})")
    two = c_bulk < c_long
    if two and (thickness is None or not (math.isfinite(thickness) and thickness > 0.0)):
        raise ValueError(f"the spall layer's thickness must be a finite number > 0 where c_b "
                         f"< c_l (got {thickness})")
    t, vs, peak, low, window = _reading(t, v, pulse, window, rebound, lines, jumps)
    u1, u2 = slopes(t, vs, peak, low, pulse)
    du = vs[peak] - vs[low]
    notes, delta = [], 0.0
    if two:
        if u2 is None:
            notes.append("no spall pulse front after the minimum (the record does not rise by "
                         "a tenth of dU after it, or ends while it rises): u2' unknown, delta "
                         "taken 0, the strength a lower bound")
        else:
            delta = thickness * (1.0 / c_bulk - 1.0 / c_long) * abs(u1) * u2 / (abs(u1) + u2)
    ends = low == len(t) - 1
    return Reading(t[peak], vs[peak], t[low], vs[low], du, u1, u2, delta,
                   0.5 * rho0 * c_bulk * (du + delta), 0.5 * rho0 * c_bulk * du,
                   0.5 * rho0 * c_long * du, rho0, c_bulk, c_long, thickness if two else None,
                   window, ends, notes)


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
            bounds = (f"{'>=' if closed_low else '>'} {low:g}" if high == math.inf else
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


# options that are gone, and what replaces them
REPLACED = {
    "--c0": "--c0 is replaced by --c-bulk and --c-long (\"c0\" named two speeds): --c-long the "
            "longitudinal speed sqrt((K + 4G/3)/rho0) along the impact, --c-bulk the bulk "
            "speed sqrt(K/rho0) (pair_coeff mca shock's c0); for an elastic target or a lattice "
            "of clusters give --c-long alone (its own speed along the impact)",
    "--smooth": "--smooth (a count of records) is replaced by --window (a time, default a tenth "
                "of the pulse duration): the reading no longer depends on the record interval",
}


def _fmt(x):
    return "-" if x is None else f"{x:.6g}"


def main(argv=None):
    ap = numbers_take_values(argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=__doc__.split("\n\n", 1)[1]))
    ap.add_argument("file")
    ap.add_argument("--rho0", type=_number(0.0), required=True,
                    help="density of the unloaded target (see below)")
    ap.add_argument("--c-long", type=_number(0.0),
                    help="c_l, the longitudinal sound speed of the unloaded target along the "
                         "impact (see below); alone: one speed, c_b = c_l, delta = 0")
    ap.add_argument("--c-bulk", type=_number(0.0),
                    help="c_b, the bulk sound speed sqrt(K/rho0) (pair_coeff mca shock's c0); "
                         "below c_l: Kanel's correction delta for the elastic-plastic release")
    pulse = ap.add_mutually_exclusive_group(required=True)
    pulse.add_argument("--flyer", type=_number(0.0),
                       help="flyer thickness H: the pulse lasts 2 H / c_b, and the spall layer "
                            "is H thick unless --spall-thickness")
    pulse.add_argument("--pulse", type=_number(0.0), help="the pulse duration (time units)")
    ap.add_argument("--spall-thickness", type=_number(0.0),
                    help="h, the spall layer's thickness (default: --flyer; required with "
                         "--pulse where c_b < c_l)")
    ap.add_argument("--window", type=_number(0.0, closed_low=True),
                    help="the smoothing window (time units; default a tenth of the pulse "
                         "duration; 0: none)")
    ap.add_argument("--time-column", type=_count(0), default=1, help="0-based (default 1)")
    ap.add_argument("--velocity-column", type=_count(0), default=2, help="0-based (default 2)")
    ap.add_argument("--jump-column", type=_count(0),
                    help="0-based: compute free/surface's jump count (see below)")
    ap.add_argument("--rebound", type=_number(0.0, 1.0, closed_low=True), default=0.0,
                    help="the minimum before the record rises again by this share of the peak "
                         "velocity (e.g. 0.1 for a ringing lattice face; default 0: the lowest "
                         "within a pulse duration after the peak)")
    argv = sys.argv[1:] if argv is None else list(argv)
    for word in argv:
        if word == "--":
            break
        name = word.split("=", 1)[0]
        if name in REPLACED:
            ap.error(REPLACED[name])
    args = ap.parse_args(argv)
    if args.c_long is None:
        ap.error("--c-long is required (the longitudinal speed along the impact; with --c-bulk "
                 "for a target whose release is elastic-plastic)" if args.c_bulk is not None
                 else "--c-long is required (the longitudinal speed along the impact)")
    c_bulk = args.c_long if args.c_bulk is None else args.c_bulk
    if c_bulk > args.c_long:
        ap.error(f"--c-bulk {c_bulk:g} exceeds --c-long {args.c_long:g}: sqrt(K/rho0) <= "
                 f"sqrt((K + 4G/3)/rho0) (are they swapped?)")
    columns = {"--time-column": args.time_column, "--velocity-column": args.velocity_column}
    if args.jump_column is not None:
        columns["--jump-column"] = args.jump_column
    if len(set(columns.values())) < len(columns):
        ap.error("the columns must differ: " + ", ".join(f"{k} {c}" for k, c in columns.items()))
    duration = args.pulse if args.pulse else 2.0 * args.flyer / c_bulk
    if not (math.isfinite(duration) and duration > 0.0):
        ap.error(f"the pulse 2 --flyer / c_b = {duration} is not a finite number > 0")
    thickness = args.spall_thickness if args.spall_thickness is not None else args.flyer
    if c_bulk < args.c_long and thickness is None:
        ap.error("--spall-thickness is required with --pulse where --c-bulk < --c-long (Kanel's "
                 "correction needs the spall layer's thickness)")
    try:
        lines, data = read_columns(args.file, columns)
        r = spall_strength(data["--time-column"], data["--velocity-column"], duration,
                           args.rho0, args.c_long, c_bulk, thickness, window=args.window,
                           rebound=args.rebound, lines=lines, jumps=data.get("--jump-column"))
    except (OSError, ValueError) as err:
        ap.error(f"{args.file}: {err}")
    print(f"peak {r.v_peak:.6g} at {r.t_peak:.6g}; minimum {r.v_min:.6g} at {r.t_min:.6g}; "
          f"pull-back dU = {r.du:.6g}")
    print(f"slopes (smoothed over a window of {r.window:.6g}): release u1' = {_fmt(r.u1)}, "
          f"spall pulse front u2' = {_fmt(r.u2)}; spall layer h = {_fmt(r.thickness)}")
    print(r.formula())
    print(f"acoustic, for comparison: 1/2 rho0 c_b dU = {r.acoustic_bulk:.6g}; "
          f"1/2 rho0 c_l dU = {r.acoustic_long:.6g}")
    if r.ends_falling:
        print(f"note: the minimum is the record's last record (line {lines[-1]}): the record "
              f"ends before the velocity rises again, the pull-back may be deeper",
              file=sys.stderr)
    for note in r.notes:
        print(f"note: {note}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
