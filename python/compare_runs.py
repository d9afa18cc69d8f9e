#!/usr/bin/python3
"""One table and overlay plots of the runs of one scenario made different ways (immersed, body-fitted with a
translating grid, body-fitted with layers; water against air): what users compare (issue "body-fitted mode, part 2",
item 5). scripts/compare.sh runs the cases and calls it; it also reads finished result folders.

Usage: /usr/bin/python3 python/compare_runs.py OUT_DIR LABEL=RESULTS_DIR [LABEL=RESULTS_DIR ...] [--body NAME]
Writes OUT_DIR/compare.md (the table: cells, steps, wall time; terminal speed and t95 as the validation tests take
them, the mean speed over t >= 1.5 s before the first impact and the first time at 95 % of it; impact and rebound
speed, rebound height and runout as the run's summary gives them; peak and mean force (a) and the means of its
pressure, viscous and turbulent parts over the same window; the Beranger lumped model of the first run) with each
run's difference from the first, and OUT_DIR/compare_<body>.png (speed, height and force (a) against time).
Uses Debian's numpy, h5py and matplotlib (call /usr/bin/python3).
"""
import csv
import math
import os
import re
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_run import read_csv, save  # noqa: E402


def first_body(run_dir):
    names = sorted(f[5:-4] for f in os.listdir(run_dir) if f.startswith("body_") and f.endswith(".csv"))
    if not names:
        raise SystemExit(f"compare_runs: no body_<name>.csv in {run_dir}")
    return names[0]


def cells(run_dir):
    """From the newest checkpoint's grid lines (a run writes one at its end)."""
    checkpoints = sorted(f for f in os.listdir(run_dir) if f.startswith("checkpoint_") and f.endswith(".h5"))
    if not checkpoints:
        return math.nan
    with h5py.File(os.path.join(run_dir, checkpoints[-1]), "r") as f:
        return (len(f["grid/x_lines"]) - 1) * (len(f["grid/y_lines"]) - 1)


def summary_numbers(run_dir):
    """The run's summary.txt, read for what it states (run/simulation.cpp, run/trajectory_summary.cpp)."""
    text = open(os.path.join(run_dir, "summary.txt")).read()

    def number(pattern):
        m = re.search(pattern, text)
        return float(m.group(1)) if m else math.nan

    return {
        "steps": number(r"(\d+) steps to t ="),
        "wall": number(r"in ([0-9.]+) s wall"),
        "rebound_height": number(r"rebound height \(centre, against gravity\) ([-0-9.e+]+) m"),
        "runout": number(r"runout to the second impact \(t = [-0-9.e+]+ s\): ([-0-9.e+]+) m"),
    }


def measures(run_dir, body):
    b = read_csv(os.path.join(run_dir, f"body_{body}.csv"))
    t, speed = b["t"], np.hypot(b["u"], b["v"])
    contacts_path = os.path.join(run_dir, "contacts.csv")
    impacts = []
    if os.path.exists(contacts_path) and os.path.getsize(contacts_path) > 0:
        with open(contacts_path) as f:
            impacts = [r for r in csv.DictReader(f) if r["body"] == body and r["rests"] == "0"]
    t_impact = float(impacts[0]["t"]) if impacts else t[-1] + 1.0
    window = (t >= 1.5) & (t < t_impact)
    out = {"cells": cells(run_dir), **summary_numbers(run_dir)}
    if window.any():
        terminal = speed[window].mean()
        out["terminal"] = terminal
        reached = np.nonzero((speed >= 0.95 * terminal) & (t < t_impact))[0]
        out["t95"] = t[reached[0]] if len(reached) else math.nan
    else:
        out["terminal"] = out["t95"] = math.nan
    if impacts:
        e = impacts[0]
        out["impact_speed"] = math.hypot(float(e["u_before"]), float(e["v_before"]))
        out["rebound_speed"] = math.hypot(float(e["u_after"]), float(e["v_after"]))
    else:
        out["impact_speed"] = out["rebound_speed"] = math.nan
    force = np.hypot(b["fx_forcing"], b["fy_forcing"])
    out["peak_force"] = force.max()
    # Each part along the mean force (a)'s direction, with its sign (the turbulent part pulls back).
    mean_window = window if window.any() else t > 0
    total = np.array([b["fx_forcing"][mean_window].mean(), b["fy_forcing"][mean_window].mean()])
    along = total / max(np.linalg.norm(total), 1e-300)
    for kind in ("forcing", "pressure", "viscous", "turbulent"):
        out[f"mean_{kind}"] = (b[f"fx_{kind}"][mean_window] * along[0] + b[f"fy_{kind}"][mean_window] * along[1]).mean()
    return out, b


def beranger(run_dir, body):
    """The Beranger lumped model of the same release (lumped_<body>.csv, model 1): its speed at the end."""
    path = os.path.join(run_dir, f"lumped_{body}.csv")
    if not os.path.exists(path):
        return None
    m = read_csv(path)
    keep = m["model"] == 1
    if not keep.any():
        return None
    return {"t": m["t"][keep], "speed": np.hypot(m["u"][keep], m["v"][keep]), "y": m["y"][keep]}


ROWS = [
    ("cells", "cells", "{:.0f}"),
    ("steps", "steps", "{:.0f}"),
    ("wall", "wall time (s)", "{:.1f}"),
    ("terminal", "terminal speed, mean t >= 1.5 s (m/s)", "{:.4f}"),
    ("t95", "t95 (s)", "{:.3f}"),
    ("impact_speed", "speed at the first impact (m/s)", "{:.3f}"),
    ("rebound_speed", "rebound speed (m/s)", "{:.3f}"),
    ("rebound_height", "rebound height, centre (m)", "{:.4f}"),
    ("runout", "runout to the second impact (m)", "{:.4f}"),
    ("peak_force", "peak force (a) (N)", "{:.4g}"),
    ("mean_forcing", "mean force (a), same window (N)", "{:.1f}"),
    ("mean_pressure", "mean pressure force (N)", "{:.1f}"),
    ("mean_viscous", "mean viscous force (N)", "{:.1f}"),
    ("mean_turbulent", "mean turbulent force (N)", "{:.1f}"),
]


def table(labels, results):
    head = "| quantity | " + " | ".join(labels) + " |\n|---|" + "---|" * len(labels) + "\n"
    lines = []
    for key, name, fmt in ROWS:
        values = [r[key] for r in results]
        if all(math.isnan(v) for v in values):
            continue
        cells_ = []
        for k, v in enumerate(values):
            s = "–" if math.isnan(v) else fmt.format(v)
            ref = values[0]
            # A part far under the force it belongs to (the viscous part of a bluff body's drag) gets no percentage.
            scale = abs(results[0]["mean_forcing"]) if key.startswith("mean_") else max(
                abs(x) for x in values if not math.isnan(x))
            if k > 0 and not math.isnan(v) and not math.isnan(ref) and abs(ref) > 1e-3 * scale and abs(ref) > 1e-9:
                s += f" ({100.0 * (v / ref - 1.0):+.1f} %)"
            cells_.append(s)
        lines.append(f"| {name} | " + " | ".join(cells_) + " |")
    return head + "\n".join(lines) + "\n"


def main(argv):
    args = [a for a in argv if not a.startswith("--body")]
    body = None
    for a in argv:
        if a.startswith("--body="):
            body = a.split("=", 1)[1]
    if len(args) < 3 or any("=" not in a for a in args[2:]):
        raise SystemExit(__doc__)
    out_dir = args[1]
    runs = [a.split("=", 1) for a in args[2:]]
    os.makedirs(out_dir, exist_ok=True)
    body = body or first_body(runs[0][1])
    results, series = [], []
    for label, run_dir in runs:
        r, b = measures(run_dir, body)
        results.append(r)
        series.append((label, b))
    text = f"# {body}: " + ", ".join(label for label, _ in runs) + "\n\n" + table([lb for lb, _ in runs], results)
    lumped = beranger(runs[0][1], body)
    if lumped is not None:
        text += f"\nBeranger model (C_D 2, C_a 0.5) of the same release: speed at t = {lumped['t'][-1]:.3g} s " \
                f"{lumped['speed'][-1]:.4f} m/s.\n"
    tmp = os.path.join(out_dir, "compare.md.tmp")
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, os.path.join(out_dir, "compare.md"))

    fig, ax = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    for label, b in series:
        ax[0].plot(b["t"], np.hypot(b["u"], b["v"]), label=label)
        ax[1].plot(b["t"], b["y"], label=label)
        ax[2].plot(b["t"], b["fy_forcing"], label=label, lw=0.8)
    if lumped is not None:
        ax[0].plot(lumped["t"], lumped["speed"], "k--", lw=0.8, label="Beranger")
    ax[0].set_ylabel("speed (m/s)")
    ax[1].set_ylabel("centre y (m)")
    ax[2].set_ylabel("force (a), y (N)")
    ax[2].set_xlabel("t (s)")
    ax[0].legend(fontsize=8)
    fig.tight_layout()
    save(fig, os.path.join(out_dir, f"compare_{body}.png"))
    plt.close(fig)
    print(text)


if __name__ == "__main__":
    main(sys.argv)
