#!/usr/bin/python3
"""Plots of one Chute run: time series (kinetic energy, divergence, Poisson iterations, probes), snapshots of
the last field file (speed with streamlines, vorticity, pressure) and, per immersed body, its force
coefficients against time (body_<name>.png) and the vorticity around it (vorticity_<name>.png); per free body
its trajectory, velocity and forces against the dry and Beranger lumped models of the same release
(trajectory_<name>.png).

Usage: /usr/bin/python3 python/plot_run.py RESULTS_DIR
Uses Debian's numpy, h5py and matplotlib (call /usr/bin/python3: a pyenv python does not see them).
"""
import csv
import glob
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_csv(path):
    """A CSV with a header as columns by name: numbers as float arrays (empty and "nan" as NaN), a column that is not
    all numbers (contacts.csv's body and obstacle) as strings."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return {}

    def column(k):
        try:
            return np.array([float(r[k]) if r[k] not in ("", "nan") else math.nan for r in rows])
        except ValueError:
            return np.array([r[k] for r in rows])

    return {k: column(k) for k in rows[0]}


def save(fig, path):
    """Writes a PNG atomically, as the solver writes its files: to path.tmp, then renamed, so that a full disk
    leaves no cut image under the final name."""
    tmp = path + ".tmp"
    try:
        fig.savefig(tmp, dpi=110, format="png")
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise


def load_timeseries(run_dir, stem="timeseries"):
    path = os.path.join(run_dir, stem + ".h5")
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
    save(fig, os.path.join(run_dir, "timeseries.png"))
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
    lim = np.nanpercentile(np.abs(w), 99) or 1.0
    m = ax[1].pcolormesh(x, y, w, cmap="RdBu_r", vmin=-lim, vmax=lim, shading="flat")
    fig.colorbar(m, ax=ax[1], label="vorticity (1/s)")
    # The lid corners of a cavity (and sharp edges later) are pressure singularities: clip the colour scale.
    lo, hi = np.nanpercentile(p, [1, 99])
    m = ax[2].pcolormesh(x, y, p, cmap="coolwarm", vmin=lo, vmax=hi, shading="flat")
    fig.colorbar(m, ax=ax[2], label="dynamic pressure (Pa)")
    for a, title in zip(ax, ["speed and streamlines", "vorticity", "pressure"]):
        a.set_aspect("equal")
        a.set_title(f"{title}, t = {t:.4g} s")
        a.set_xlabel("x (m)")
        a.set_ylabel("y (m)")
    fig.tight_layout()
    save(fig, os.path.join(run_dir, "fields.png"))
    plt.close(fig)


def plot_body(run_dir, name, b, fields_file):
    """Force coefficients from the forcing (a) and the surface stress (b, split by kind), slip error."""
    t = b["t"]
    fig, ax = plt.subplots(3, 1, figsize=(8, 7.5), sharex=True)
    ax[0].plot(t, b["cx_forcing"], label="C_x forcing (a)")
    ax[0].plot(t, b["cx_surface"], "--", label="C_x surface (b)")
    ax[0].plot(t, b["cy_forcing"], label="C_y forcing (a)")
    ax[0].plot(t, b["cy_surface"], "--", label="C_y surface (b)")
    ax[0].set_ylabel("force coefficient")
    ax[0].legend(fontsize=7, ncol=2)
    ax[1].plot(t, b["cx_pressure"], label="C_x pressure")
    ax[1].plot(t, b["cx_viscous"], label="C_x viscous")
    ax[1].plot(t, b["cy_pressure"], label="C_y pressure")
    ax[1].plot(t, b["cy_viscous"], label="C_y viscous")
    turbulent = "cx_turbulent" in b and (np.any(b["cx_turbulent"] != 0) or np.any(b["cy_turbulent"] != 0))
    if turbulent:
        ax[1].plot(t, b["cx_turbulent"], label="C_x turbulent")
        ax[1].plot(t, b["cy_turbulent"], label="C_y turbulent")
    ax[1].set_ylabel("surface stress by kind")
    ax[1].legend(fontsize=7, ncol=2)
    # Impulsive starts give a spike of many times the later forces: scale the axes to the bulk of the run.
    for a, keys in ((ax[0], ["cx_forcing", "cx_surface", "cy_forcing", "cy_surface"]),
                    (ax[1], ["cx_pressure", "cx_viscous", "cy_pressure", "cy_viscous"] +
                     (["cx_turbulent", "cy_turbulent"] if turbulent else []))):
        values = np.concatenate([b[k][len(t) // 20:] for k in keys]) if len(t) > 20 else None
        if values is not None and values.size:
            lo, hi = np.nanpercentile(values, [0.5, 99.5])
            pad = 0.1 * (hi - lo) or 0.1 * max(abs(hi), 1e-12)
            a.set_ylim(lo - pad, hi + pad)
    slip = b["max_slip"][1:] > 0
    ax[2].semilogy(t[1:][slip], b["max_slip"][1:][slip], label="max")
    ax[2].semilogy(t[1:][slip], b["rms_slip"][1:][slip], label="rms")
    ax[2].set_ylabel("slip at markers (m/s)")
    ax[2].legend(fontsize=7)
    ax[-1].set_xlabel("t (s)")
    fig.suptitle(f"body {name}")
    fig.tight_layout()
    save(fig, os.path.join(run_dir, f"body_{name}.png"))
    plt.close(fig)
    if not fields_file:
        return
    # Vorticity around the body's last position: a window of a quarter of the domain's diagonal.
    with h5py.File(fields_file, "r") as f:
        x, y, w, time = f["x"][...], f["y"][...], f["vorticity"][...], f.attrs["time"]
    k = int(np.argmin(np.abs(t - time)))
    cx, cy = b["x"][k], b["y"][k]
    half = 0.125 * np.hypot(x[-1] - x[0], y[-1] - y[0])
    fig, a = plt.subplots(figsize=(7, 5))
    lim = np.nanpercentile(np.abs(w), 99.5) or 1.0
    m = a.pcolormesh(x, y, w, cmap="RdBu_r", vmin=-lim, vmax=lim, shading="flat")
    fig.colorbar(m, ax=a, label="vorticity (1/s)")
    a.set_xlim(max(x[0], cx - half), min(x[-1], cx + 2 * half))
    a.set_ylim(max(y[0], cy - half), min(y[-1], cy + half))
    a.set_aspect("equal")
    a.set_title(f"vorticity around {name}, t = {time:.4g} s")
    a.set_xlabel("x (m)")
    a.set_ylabel("y (m)")
    fig.tight_layout()
    save(fig, os.path.join(run_dir, f"vorticity_{name}.png"))
    plt.close(fig)


def plot_trajectory(run_dir, name, b):
    """A free body: height and velocity against time with the lumped models, and the forces on it."""
    lumped_path = os.path.join(run_dir, f"lumped_{name}.csv")
    lumped = np.genfromtxt(lumped_path, delimiter=",", names=True) if os.path.exists(lumped_path) else None
    t = b["t"]
    fig, ax = plt.subplots(3, 1, figsize=(8, 8.5), sharex=True)
    ax[0].plot(t, b["y"], label="Chute (CFD)")
    ax[1].plot(t, b["u"], label="u, Chute")
    ax[1].plot(t, b["v"], label="v, Chute")
    if lumped is not None and lumped.size:
        for model, label, style in ((0, "dry", ":"), (1, "Beranger", "--")):
            k = lumped["model"] == model
            ax[0].plot(lumped["t"][k], lumped["y"][k], style, label=label)
            ax[1].plot(lumped["t"][k], lumped["v"][k], style, label=f"v, {label}")
    ax[0].set_ylabel("y of the centre (m)")
    ax[0].legend(fontsize=7)
    ax[1].set_ylabel("velocity (m/s)")
    ax[1].legend(fontsize=7, ncol=2)
    ax[2].plot(t, b["fy_forcing"], label="hydrodynamic (y)")
    ax[2].plot(t, b["fy_gravity"] + b["fy_buoyancy"], label="gravity + buoyancy (y)")
    ax[2].plot(t, b["fy_pressure"], "--", label="pressure (y)")
    ax[2].plot(t, b["fy_viscous"], "--", label="viscous (y)")
    if "fy_turbulent" in b and np.any(b["fy_turbulent"] != 0):
        ax[2].plot(t, b["fy_turbulent"], "--", label="turbulent (y)")
    values = np.concatenate([b["fy_forcing"], b["fy_gravity"] + b["fy_buoyancy"]])
    lo, hi = np.nanpercentile(values, [1, 99])
    pad = 0.2 * (hi - lo) or 1.0
    ax[2].set_ylim(lo - pad, hi + pad)  # impacts give spikes of many times the weight
    ax[2].set_ylabel("force (N)")
    ax[2].legend(fontsize=7, ncol=2)
    ax[-1].set_xlabel("t (s)")
    fig.suptitle(f"free body {name}")
    fig.tight_layout()
    save(fig, os.path.join(run_dir, f"trajectory_{name}.png"))
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    run_dir = sys.argv[1]
    plot_timeseries(run_dir, load_timeseries(run_dir))
    plot_fields(run_dir)
    written = ["timeseries.png", "fields.png"]
    fields = sorted(glob.glob(os.path.join(run_dir, "fields_*.h5")))
    for path in sorted(glob.glob(os.path.join(run_dir, "body_*.h5"))):
        name = os.path.basename(path)[len("body_"):-len(".h5")]
        series = load_timeseries(run_dir, "body_" + name)
        plot_body(run_dir, name, series, fields[-1] if fields else None)
        written += [f"body_{name}.png", f"vorticity_{name}.png"]
        if "fy_gravity" in series and np.any(series["fy_gravity"] != 0.0):
            plot_trajectory(run_dir, name, series)
            written.append(f"trajectory_{name}.png")
    print("plots: " + ", ".join(os.path.join(run_dir, w) for w in written))


if __name__ == "__main__":
    main()
