#!/usr/bin/python3
"""Plots of one Chute run: time series (kinetic energy, divergence, Poisson iterations, probes) and
snapshots of the last field file (speed with streamlines, vorticity, pressure).

Usage: /usr/bin/python3 python/plot_run.py RESULTS_DIR
Uses Debian's numpy, h5py and matplotlib (call /usr/bin/python3: a pyenv python does not see them).
"""
import glob
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def load_timeseries(run_dir):
    path = os.path.join(run_dir, "timeseries.h5")
    with h5py.File(path, "r") as f:
        columns = f.attrs["columns"]  # one comma-separated string (core/timeseries.cpp)
        columns = (columns.decode() if isinstance(columns, bytes) else str(columns)).split(",")
        return {c: f[c.replace("/", "_")][...] for c in columns}


def plot_timeseries(run_dir, ts):
    t = ts["t"]
    probes = sorted({c.split("_")[0] for c in ts if c.startswith("probe")})
    n = 3 + (1 if probes else 0)
    fig, ax = plt.subplots(n, 1, figsize=(8, 2.4 * n), sharex=True)
    ax[0].plot(t, ts["kinetic_energy"])
    ax[0].set_ylabel("kinetic energy\n(m^4/s^2 per kg/m)")
    ax[1].semilogy(t[1:], np.maximum(ts["max_divergence"][1:], 1e-300))
    ax[1].set_ylabel("max |div u| (1/s)")
    ax[2].plot(t[1:], ts["poisson_iterations"][1:], ".", ms=2)
    ax[2].set_ylabel("Poisson iterations")
    if probes:
        for p in probes:
            ax[3].plot(t, ts[p + "_u"], label=p + " u")
            ax[3].plot(t, ts[p + "_v"], "--", label=p + " v")
        ax[3].set_ylabel("probe velocity (m/s)")
        ax[3].legend(fontsize=7)
    ax[-1].set_xlabel("t (s)")
    fig.tight_layout()
    fig.savefig(os.path.join(run_dir, "timeseries.png"), dpi=110)
    plt.close(fig)


def plot_fields(run_dir):
    files = sorted(glob.glob(os.path.join(run_dir, "fields_*.h5")))
    if not files:
        return
    with h5py.File(files[-1], "r") as f:
        x, y = f["x"][...], f["y"][...]
        u, v, p, w = f["u"][...], f["v"][...], f["p"][...], f["vorticity"][...]
        t = f.attrs["time"]
    xc, yc = 0.5 * (x[1:] + x[:-1]), 0.5 * (y[1:] + y[:-1])
    aspect = (y[-1] - y[0]) / (x[-1] - x[0])
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6 * min(max(aspect, 0.4), 2.0)))
    speed = np.hypot(u, v)
    m = ax[0].pcolormesh(x, y, speed, cmap="viridis", shading="flat")
    # streamplot needs a uniform grid: resample onto one.
    xs, ys = np.linspace(xc[0], xc[-1], 96), np.linspace(yc[0], yc[-1], 96)
    ui = np.array([np.interp(xs, xc, row) for row in u])
    vi = np.array([np.interp(xs, xc, row) for row in v])
    ui = np.array([np.interp(ys, yc, col) for col in ui.T]).T
    vi = np.array([np.interp(ys, yc, col) for col in vi.T]).T
    ax[0].streamplot(xs, ys, ui, vi, color="w", density=1.2, linewidth=0.5, arrowsize=0.6)
    fig.colorbar(m, ax=ax[0], label="speed (m/s)")
    lim = np.percentile(np.abs(w), 99) or 1.0
    m = ax[1].pcolormesh(x, y, w, cmap="RdBu_r", vmin=-lim, vmax=lim, shading="flat")
    fig.colorbar(m, ax=ax[1], label="vorticity (1/s)")
    # The lid corners of a cavity (and sharp edges later) are pressure singularities: clip the colour scale.
    lo, hi = np.percentile(p, [1, 99])
    m = ax[2].pcolormesh(x, y, p, cmap="coolwarm", vmin=lo, vmax=hi, shading="flat")
    fig.colorbar(m, ax=ax[2], label="dynamic pressure (Pa)")
    for a, title in zip(ax, ["speed and streamlines", "vorticity", "pressure"]):
        a.set_aspect("equal")
        a.set_title(f"{title}, t = {t:.4g} s")
        a.set_xlabel("x (m)")
        a.set_ylabel("y (m)")
    fig.tight_layout()
    fig.savefig(os.path.join(run_dir, "fields.png"), dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    run_dir = sys.argv[1]
    plot_timeseries(run_dir, load_timeseries(run_dir))
    plot_fields(run_dir)
    print(f"plots: {os.path.join(run_dir, 'timeseries.png')}, {os.path.join(run_dir, 'fields.png')}")


if __name__ == "__main__":
    main()
