#!/usr/bin/python3
"""Plots of one rockfall hazard run (`chute hazard`), from the files it wrote into DIR:

- profile.png: the slope profile (ground filled, water shaded below its level), the sample paths of paths.csv
  (flights blue, slides orange), where the blocks stopped (a histogram of stop_x) and the reach probability
  (the fraction of all blocks that stop beyond x), the collectors marked;
- envelopes.png: against x, the mean and 95th percentile, among the blocks crossing each station, of the speed,
  the translational and rotational kinetic energies and the bounce height (stations.csv);
- collectors.png: per collector, the histogram of the energies (translational + rotational) of the blocks that
  hit it (pass at or below its height; hazard.h5 collectors/*), the hit probability in the title.

Usage: /usr/bin/python3 python/hazard/plot_hazard.py DIR
Uses Debian's numpy, h5py and matplotlib (call /usr/bin/python3: a pyenv python does not see them).
"""
import csv
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from plot_run import read_csv, save  # noqa: E402

NEEDED = ("trajectories.csv", "stations.csv", "collectors.csv", "paths.csv", "hazard.h5")
NO_WATER = -1e29  # profile/water_level below this: no water (the solver writes -1e30)
GROUND, WATER, COLLECTOR = "#b59b7c", "#cfe3f7", "#8b1a1a"


class Run:
    """What the plots need from one hazard run's folder."""

    def __init__(self, folder):
        missing = [f for f in NEEDED if not os.path.exists(os.path.join(folder, f))]
        if missing:
            raise SystemExit(f"plot_hazard: {folder} lacks {', '.join(missing)}: is it the --out folder of a "
                             "finished `chute hazard` run?")
        self.folder = folder
        self.trajectories = read_csv(os.path.join(folder, "trajectories.csv"))
        self.stations = read_csv(os.path.join(folder, "stations.csv"))
        self.collectors = read_csv(os.path.join(folder, "collectors.csv"))
        with open(os.path.join(folder, "collectors.csv")) as f:
            self.names = [r["name"] for r in csv.DictReader(f)]  # as written, even a name that reads as a number
        self.paths = read_csv(os.path.join(folder, "paths.csv"))
        with h5py.File(os.path.join(folder, "hazard.h5"), "r") as f:
            self.profile_x = f["profile/x"][...]
            self.profile_z = f["profile/z"][...]
            level = float(f["profile/water_level"][()])
            self.water_level = level if level > NO_WATER else None
            C = len(self.names)
            shape = (len(f["trajectories/stop_x"]), C)
            self.collector_energy = f["collectors/energy"][...] if "collectors/energy" in f else np.full(shape, np.nan)
            self.collector_height = f["collectors/height"][...] if "collectors/height" in f else np.full(shape, np.nan)
        self.n = len(self.trajectories.get("index", []))

    def stop_x(self):
        """Where each block stopped; a block past the profile's end counts at its last x (as the solver does)."""
        x = np.array(self.trajectories["stop_x"], dtype=float)
        x[np.asarray(self.trajectories["end"]) == "past_end"] = self.profile_x[-1]
        return x

    def name(self):
        return os.path.basename(os.path.normpath(self.folder))


def draw_profile(ax, run, bottom):
    """Ground filled down to `bottom`, the water shaded between the ground and the level (if over any ground)."""
    x, z = run.profile_x, run.profile_z
    if water_span(run):
        ax.fill_between(x, z, run.water_level, where=z < run.water_level, interpolate=True, color=WATER,
                        label=f"water (level {run.water_level:g} m)")
        ax.axhline(run.water_level, color="#4a7fb5", lw=0.8)
    ax.fill_between(x, bottom, z, color=GROUND, label="ground")
    ax.plot(x, z, color="#5b4a36", lw=1.0)


def mark_collectors(axes, run, label_axis=None):
    """A vertical dotted line at each collector on every axis; its name on `label_axis`, at the top."""
    names = run.names
    xs = np.atleast_1d(run.collectors.get("x", np.array([])))
    for name, x in zip(names, xs):
        for ax in axes:
            ax.axvline(x, color=COLLECTOR, ls=":", lw=1.2)
        if label_axis is not None:
            label_axis.annotate(name, (x, 1.0), xycoords=("data", "axes fraction"), xytext=(3, -3),
                                textcoords="offset points", va="top", ha="left", fontsize=8, color=COLLECTOR)


def water_span(run):
    """The x range where the ground is under the water (for a light band on the panels), or None."""
    if run.water_level is None:
        return None
    wet = run.profile_x[run.profile_z < run.water_level]
    return (wet.min(), wet.max()) if len(wet) else None


def x_view(run):
    """The x range the plots show: the profile from its start to a little past the farthest of the stops, the
    stations crossed and the collectors (the rest of a long flat seabed that no block reaches is empty); and a note
    for the axis label when that is short of the profile's end."""
    x0, x1 = run.profile_x[0], run.profile_x[-1]
    s = run.stations
    crossed = s["x"][s["passing_fraction"] > 0] if len(s.get("x", [])) else np.array([])
    far = max([np.nanmax(run.stop_x()) if run.n else x0, np.max(crossed) if len(crossed) else x0] +
              list(np.atleast_1d(run.collectors.get("x", np.array([])))))
    end = min(x1, far + 0.15 * (far - x0))
    return (x0, end), ("" if end >= x1 else f" (the profile goes on to {x1:g} m, where no block goes)")


def finish(fig, run, name):
    """Lays the figure out, writes it into the run's folder (atomically) and returns its path."""
    fig.tight_layout()
    path = os.path.join(run.folder, name)
    save(fig, path)
    plt.close(fig)
    return path


def plot_profile(run):
    fig, (ax, ax_stop) = plt.subplots(2, 1, figsize=(12, 8.5), sharex=True, gridspec_kw={"height_ratios": [2.2, 1]})
    zmin, zmax = run.profile_z.min(), run.profile_z.max()
    bottom = zmin - 0.08 * (zmax - zmin)
    draw_profile(ax, run, bottom)
    p = run.paths
    ids = np.unique(p["trajectory"]) if "trajectory" in p else []
    for k, i in enumerate(ids):
        rows = p["trajectory"] == i
        x, z, sliding = p["x"][rows], p["z"][rows], p["sliding"][rows] > 0.5
        both = sliding[:-1] & sliding[1:]  # a step between two sliding rows is a slide
        # Flights blue and slides orange: each a line through its own steps, the other's masked out (a step is
        # drawn from its start to its end row; the next step starts where it ends).
        for slide, (colour, lw, label) in ((False, ("C0", 0.6, "sample paths: flight")),
                                           (True, ("C1", 1.0, "sample paths: slide"))):
            mask = both if slide else ~both
            xs, zs = np.full(2 * len(mask), np.nan), np.full(2 * len(mask), np.nan)
            xs[0::2], xs[1::2] = np.where(mask, x[:-1], np.nan), np.where(mask, x[1:], np.nan)
            zs[0::2], zs[1::2] = np.where(mask, z[:-1], np.nan), np.where(mask, z[1:], np.nan)
            ax.plot(xs, zs, "-", color=colour, lw=lw, alpha=0.7, label=label if k == 0 else None)
    stops = run.stop_x()
    stop_z = np.interp(stops, run.profile_x, run.profile_z)
    ax.plot(stops, stop_z, "|", color="k", ms=9, alpha=min(1.0, max(0.02, 30.0 / max(1, run.n))))
    ax.plot([], [], "|", color="k", ms=9, label="stopping points")  # the legend's mark, not faded
    ax.set_ylim(bottom, zmax + 0.12 * (zmax - zmin))
    ax.set_ylabel("z (m)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")  # over the ground, clear of the collectors' names
    ax.set_title(f"{run.name()}: the slope, {len(ids)} sample paths of {run.n} blocks and where they stopped",
                 fontsize=10)
    mark_collectors([ax, ax_stop], run, ax)

    # Where they stopped (share of the blocks per metre) and the reach probability on a second axis.
    (x0, x1), note = x_view(run)
    edges = np.linspace(x0, x1, max(10, min(500, int(round(x1 - x0)))) + 1)
    counts, _ = np.histogram(stops, bins=edges)
    width = np.diff(edges)
    ax_stop.bar(edges[:-1], counts / max(1, run.n) / width, width=width, align="edge", color="0.45",
                label="stopping x (share of blocks per m)")
    ax_stop.set_ylabel("stopping x: share per m (1/m)")
    ax_stop.set_xlabel("x (m)" + note)
    ax_stop.grid(alpha=0.3)
    reach_ax = ax_stop.twinx()
    s = run.stations
    reach_ax.plot(s["x"], s["reach_probability"], color="C3", lw=1.5, label="reach probability")
    reach_ax.set_ylim(-0.03, 1.03)
    reach_ax.set_ylabel("reach probability (stops beyond x)", color="C3")
    reach_ax.tick_params(axis="y", colors="C3")
    handles = ax_stop.get_legend_handles_labels()[0] + reach_ax.get_legend_handles_labels()[0]
    ax_stop.legend(handles, [h.get_label() for h in handles], fontsize=8, loc="center right")
    ax_stop.set_title("Where the blocks stopped, and the probability that a block stops beyond x", fontsize=10)
    ax_stop.set_xlim(x0, x1)
    return finish(fig, run, "profile.png")


def plot_envelopes(run):
    s = run.stations
    panels = [("speed", "speed (m/s)", "linear", "Speed"),
              ("kinetic", "kinetic energy (J)", "log", "Translational kinetic energy"),
              ("rotational", "rotational energy (J)", "log", "Rotational kinetic energy"),
              ("height", "bounce height (m)", "linear", "Bounce height of the block's lowest point above the ground")]
    fig, axes = plt.subplots(4, 1, figsize=(11, 11), sharex=True)
    wet = water_span(run)
    for ax, (key, ylabel, scale, title) in zip(axes, panels):
        if wet:
            ax.axvspan(*wet, color=WATER, alpha=0.6, lw=0, label="ground under water")
        ax.plot(s["x"], s[key + "_p95"], "-", color="C3", lw=1.4, label="95th percentile")
        ax.plot(s["x"], s[key + "_mean"], "-", color="C0", lw=1.2, label="mean")
        if scale == "log":
            ax.set_yscale("log", nonpositive="mask")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3, which="both" if scale == "log" else "major")
        ax.set_title(title + " among the blocks crossing each station" + (" (log scale)" if scale == "log" else ""),
                     fontsize=10)
    mark_collectors(axes, run, axes[0])
    fig.legend(*axes[0].get_legend_handles_labels(), loc="upper center", ncol=3, fontsize=8,
               bbox_to_anchor=(0.5, 0.965), frameon=False)
    view, note = x_view(run)
    axes[-1].set_xlabel("x (m)" + note)
    axes[-1].set_xlim(*view)
    fig.suptitle(f"{run.name()}: envelopes along the slope ({run.n} blocks; no line where none crossed)",
                 fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    path = os.path.join(run.folder, "envelopes.png")
    save(fig, path)
    plt.close(fig)
    return path


def plot_collectors(run):
    names = run.names
    if not names:
        return None
    c = run.collectors
    xs, heights = np.atleast_1d(c["x"]), np.atleast_1d(c["height"])
    fig, axes = plt.subplots(1, len(names), figsize=(5.2 * len(names), 4.2), squeeze=False)
    for k, (ax, name) in enumerate(zip(axes[0], names)):
        h, e = run.collector_height[:, k], run.collector_energy[:, k]
        passing = np.isfinite(h)
        hit = passing & (h <= heights[k])
        energies = e[hit]
        p = hit.sum() / max(1, run.n)
        ax.set_title(f"{name} (x {xs[k]:g} m, {heights[k]:g} m high): hit probability {p:.4g}\n"
                     f"{hit.sum()} hits, {passing.sum()} passing, of {run.n} blocks", fontsize=10)
        ax.set_xlabel("energy at the collector, translational + rotational (J)")
        ax.set_ylabel("blocks")
        ax.grid(alpha=0.3)
        if len(energies) == 0:
            ax.text(0.5, 0.5, "no block reaches it" if passing.sum() == 0 else "no block hits it (all pass above)",
                    transform=ax.transAxes, ha="center", va="center", fontsize=12, color="0.3")
            ax.set_xticks([])
            ax.set_yticks([])
            continue
        lo, hi = energies.min(), energies.max()
        if hi - lo <= 1e-9 * max(1.0, abs(hi)):  # all the same energy: one bar around it
            lo, hi = lo - 0.5 * max(1e-3, 0.01 * abs(lo)), hi + 0.5 * max(1e-3, 0.01 * abs(hi))
        ax.hist(energies, bins=min(60, max(10, int(np.sqrt(len(energies))))), range=(lo, hi), color="0.45")
        for q, style in ((50, "--"), (95, "-")):
            v = np.percentile(energies, q)
            ax.axvline(v, color="C3", ls=style, lw=1.2, label=f"p{q} {v:.4g} J")
        ax.legend(fontsize=8)
    fig.suptitle(f"{run.name()}: energies of the blocks that hit each collector", fontsize=11)
    return finish(fig, run, "collectors.png")


def main(folder):
    run = Run(folder)
    written = [p for p in (plot_profile(run), plot_envelopes(run), plot_collectors(run)) if p]
    print("plot_hazard: wrote " + ", ".join(written))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    main(sys.argv[1])
