#!/usr/bin/python3
"""Several rockfall hazard runs (`chute hazard`) side by side, e.g. the same slope with and without water:

- OUT/compare_reach.png: the reach probability (the fraction of all blocks that stop beyond x) of each run against
  x, on a linear and a logarithmic scale, with the profile beneath;
- OUT/compare_envelopes.png: the speed and the translational kinetic energy against x, mean and 95th percentile
  among the blocks crossing each station, every run;
- OUT/compare.md and OUT/compare.json: one row per run: trajectories, how they ended, the stopping x's
  percentiles (numpy's default, linear; a block past the profile's end counted at its last x, as the solver does)
  and, per collector, the hits, the hit probability and the 95th percentile of the hit energy (collectors.csv).

Usage: /usr/bin/python3 python/hazard/compare_hazard.py OUT label1=DIR1 label2=DIR2 ...
Uses Debian's numpy, h5py and matplotlib (call /usr/bin/python3: a pyenv python does not see them).
"""
import csv
import json
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from plot_run import read_csv, save  # noqa: E402

NEEDED = ("trajectories.csv", "stations.csv", "collectors.csv", "hazard.h5")
ENDS = [("rest", "rest"), ("past_end", "past end"), ("past_start", "past start"), ("time_limit", "time limit")]
PERCENTILES = (50, 90, 95, 99)
NO_WATER = -1e29  # profile/water_level below this: no water (the solver writes -1e30)


def load(label, folder):
    missing = [f for f in NEEDED if not os.path.exists(os.path.join(folder, f))]
    if missing:
        raise SystemExit(f"compare_hazard: {folder} ({label}) lacks {', '.join(missing)}: is it the --out folder "
                         "of a finished `chute hazard` run?")
    with open(os.path.join(folder, "trajectories.csv")) as f:
        trajectories = list(csv.DictReader(f))
    with open(os.path.join(folder, "collectors.csv")) as f:
        collectors = list(csv.DictReader(f))
    with h5py.File(os.path.join(folder, "hazard.h5"), "r") as f:
        profile_x, profile_z = f["profile/x"][...], f["profile/z"][...]
        level = float(f["profile/water_level"][()])
        seconds = float(f["seconds"][()])
    stops = np.array([profile_x[-1] if t["end"] == "past_end" else float(t["stop_x"]) for t in trajectories])
    ends = {key: sum(t["end"] == key for t in trajectories) for key, _ in ENDS}
    return {
        "label": label,
        "folder": os.path.abspath(folder),
        "trajectories": len(trajectories),
        "water_level": level if level > NO_WATER else None,
        "seconds": seconds,
        "ends": ends,
        "stop_x": {f"p{p}": float(np.percentile(stops, p)) if len(stops) else None for p in PERCENTILES},
        "collectors": [{"name": c["name"], "x": float(c["x"]), "height": float(c["height"]),
                        "passing": int(c["passing"]), "hits": int(c["hits"]),
                        "hit_probability": float(c["hit_probability"]),
                        # NaN in the file for a collector nobody hits: none here.
                        "energy_p95": float(c["energy_p95"]) if int(c["hits"]) > 0 else None}
                       for c in collectors],
        "stations": read_csv(os.path.join(folder, "stations.csv")),
        "profile": (profile_x, profile_z),
    }


def number(x, digits=4):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "–"
    text = f"{x:.{digits}g}"
    return f"{float(text):.0f}" if "e+" in text else text  # 24100 rather than 2.41e+04


def table(runs):
    """The table's header and rows as text, the same in compare.md and on the report page."""
    names = []
    for r in runs:
        names += [c["name"] for c in r["collectors"] if c["name"] not in names]
    header = (["run", "trajectories", "ends: " + " / ".join(n for _, n in ENDS)] +
              [f"stop x p{p} (m)" for p in PERCENTILES])
    for n in names:
        header += [f"{n}: hits", f"{n}: hit probability", f"{n}: hit energy p95 (J)"]
    rows = []
    for r in runs:
        row = [r["label"], str(r["trajectories"]), " / ".join(str(r["ends"][k]) for k, _ in ENDS)]
        row += [number(r["stop_x"][f"p{p}"], 5) for p in PERCENTILES]
        by_name = {c["name"]: c for c in r["collectors"]}
        for n in names:
            c = by_name.get(n)
            row += ["–", "–", "–"] if c is None else [str(c["hits"]), number(c["hit_probability"]),
                                                     number(c["energy_p95"])]
        rows.append(row)
    return header, rows


def markdown(runs, header, rows):
    lines = ["# Rockfall hazard runs compared", "",
             "Stopping x: percentiles over all blocks (a block past the profile's end counted at its last x). "
             "A hit: a block passing the collector at or below its height; the hit probability is over all blocks, "
             "the energy (translational + rotational) over the hits.", "",
             "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    lines += ["", "Runs: " + "; ".join(f"{r['label']}: {r['folder']} (water level {water(r)}, {r['seconds']:.1f} s)"
                                        for r in runs), ""]
    return "\n".join(lines)


def water(run):
    return "none over the profile" if run["water_level"] is None or run["water_level"] < run["profile"][1].min() \
        else f"{run['water_level']:g} m"


def mark_collectors(axes, runs):
    seen = {}
    for r in runs:
        for c in r["collectors"]:
            seen.setdefault(c["name"], c["x"])
    for name, x in seen.items():
        for ax in axes:
            ax.axvline(x, color="#8b1a1a", ls=":", lw=1.2)
        axes[0].annotate(name, (x, 1.0), xycoords=("data", "axes fraction"), xytext=(3, -3),
                         textcoords="offset points", va="top", ha="left", fontsize=8, color="#8b1a1a")


def x_view(runs):
    """From the profile's start to a little past the farthest x any run's blocks or collectors reach."""
    x0 = min(r["profile"][0][0] for r in runs)
    x1 = max(r["profile"][0][-1] for r in runs)
    far = x0
    for r in runs:
        s = r["stations"]
        crossed = s["x"][s["passing_fraction"] > 0]
        far = max([far, np.max(crossed) if len(crossed) else x0] + [c["x"] for c in r["collectors"]])
    return x0, min(x1, far + 0.15 * (far - x0))


def plot_reach(runs, out):
    fig, (ax, ax_log, ax_p) = plt.subplots(3, 1, figsize=(11, 9.5), sharex=True,
                                           gridspec_kw={"height_ratios": [1, 1, 1.3]})
    for k, r in enumerate(runs):
        s = r["stations"]
        floor = 1.0 / max(1, r["trajectories"])
        lw = max(1.0, 3.8 - 1.6 * k)  # the first runs wider, so that a line on top of another shows
        ax.plot(s["x"], s["reach_probability"], color=f"C{k}", lw=lw, label=r["label"])
        ax_log.plot(s["x"], np.where(s["reach_probability"] > 0, s["reach_probability"], np.nan), color=f"C{k}",
                    lw=lw, label=f"{r['label']} (1 block in {r['trajectories']}: {floor:.1g})")
    ax.set_ylabel("reach probability")
    ax.set_title("Probability that a block stops beyond x (the fraction of all blocks)", fontsize=10)
    ax_log.set_yscale("log")
    ax_log.set_ylabel("reach probability (log)")
    ax_log.set_title("The same on a logarithmic scale (no line where no block goes beyond x)", fontsize=10)
    for a in (ax, ax_log):
        a.grid(alpha=0.3, which="both")
        a.legend(fontsize=8, loc="lower left")
    # The profile beneath: the first run's ground, each run's water level.
    px, pz = runs[0]["profile"]
    bottom = pz.min() - 0.08 * (pz.max() - pz.min())
    ax_p.fill_between(px, bottom, pz, color="#b59b7c", label="ground")
    ax_p.plot(px, pz, color="#5b4a36", lw=1.0)
    for k, r in enumerate(runs):
        level = r["water_level"]
        if level is not None and np.any(pz < level):
            ax_p.fill_between(px, pz, level, where=pz < level, interpolate=True, color=f"C{k}", alpha=0.15,
                              label=f"water of '{r['label']}' (level {level:g} m)")
            ax_p.axhline(level, color=f"C{k}", lw=0.8)
        else:
            ax_p.plot([], [], " ", label=f"{r['label']}: no water over the profile")
    ax_p.set_ylim(bottom, pz.max() + 0.1 * (pz.max() - pz.min()))
    ax_p.set_ylabel("z (m)")
    ax_p.set_xlabel("x (m)")
    ax_p.grid(alpha=0.3)
    ax_p.legend(fontsize=8, loc="upper right")
    ax_p.set_title("The slope profile", fontsize=10)
    mark_collectors([ax, ax_log, ax_p], runs)
    ax_p.set_xlim(*x_view(runs))
    fig.suptitle("Reach probability: " + " vs ".join(r["label"] for r in runs), fontsize=11)
    fig.tight_layout()
    path = os.path.join(out, "compare_reach.png")
    save(fig, path)
    plt.close(fig)
    return path


def plot_envelopes(runs, out):
    fig, (ax_v, ax_e) = plt.subplots(2, 1, figsize=(11, 7.5), sharex=True)
    for k, r in enumerate(runs):
        s = r["stations"]
        for ax, key in ((ax_v, "speed"), (ax_e, "kinetic")):
            ax.plot(s["x"], s[key + "_p95"], "-", color=f"C{k}", lw=max(1.0, 2.4 - 0.6 * k),
                    label=f"{r['label']}: 95th percentile")
            ax.plot(s["x"], s[key + "_mean"], "--", color=f"C{k}", lw=1.1, label=f"{r['label']}: mean")
    ax_v.set_ylabel("speed (m/s)")
    ax_v.set_title("Speed among the blocks crossing each station", fontsize=10)
    ax_e.set_yscale("log", nonpositive="mask")
    ax_e.set_ylabel("kinetic energy (J)")
    ax_e.set_title("Translational kinetic energy among the blocks crossing each station (log scale)", fontsize=10)
    ax_e.set_xlabel("x (m)")
    for ax in (ax_v, ax_e):
        ax.grid(alpha=0.3, which="both")
    fig.legend(*ax_v.get_legend_handles_labels(), loc="upper center", ncol=2 * len(runs), fontsize=8,
               bbox_to_anchor=(0.5, 0.955), frameon=False)
    mark_collectors([ax_v, ax_e], runs)
    ax_e.set_xlim(*x_view(runs))
    fig.suptitle("Envelopes along the slope: " + " vs ".join(r["label"] for r in runs)
                 + " (no line where no block crossed)", fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    path = os.path.join(out, "compare_envelopes.png")
    save(fig, path)
    plt.close(fig)
    return path


def write_atomically(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main(out, pairs):
    runs = []
    for p in pairs:
        label, sep, folder = p.partition("=")
        if not sep or not label or not folder:
            raise SystemExit(f"compare_hazard: '{p}' is not label=DIR\n\n{__doc__}")
        runs.append(load(label, folder))
    os.makedirs(out, exist_ok=True)
    header, rows = table(runs)
    figures = [plot_reach(runs, out), plot_envelopes(runs, out)]
    write_atomically(os.path.join(out, "compare.md"), markdown(runs, header, rows))
    summary = {"runs": [{k: v for k, v in r.items() if k not in ("stations", "profile")} for r in runs],
               "table": {"header": header, "rows": rows},
               "figures": [os.path.basename(f) for f in figures]}
    write_atomically(os.path.join(out, "compare.json"), json.dumps(summary, indent=1) + "\n")
    print("compare_hazard: wrote " + ", ".join(figures + [os.path.join(out, "compare.md"),
                                                         os.path.join(out, "compare.json")]))


if __name__ == "__main__":
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2:])
