"""What every scenario's figure shares: the study's reference numbers (the folder's reference.csv), the claim rows
with a verdict per mode, the tables beyond the study, and the result a scenario hands to the report page
(result.json, summary.md and its PNGs, all written atomically)."""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (the scenario modules draw with it)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from plot_run import save  # noqa: E402

MODES = ("immersed", "body-fitted")
STYLE = {"immersed": "-", "body-fitted": "--"}


def finish_axes(ax, xlabel, ylabel, title=None, legend_size=8):
    """Labels, grid and legend, the same on every figure of the report."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=legend_size)
    if title:
        ax.set_title(title, fontsize=10)


def read_reference(folder):
    """reference.csv: id, claim, value, low, high, unit, source; the band [low, high] is what agrees (empty: open)."""
    with open(os.path.join(folder, "reference.csv")) as f:
        rows = list(csv.DictReader(f))
    return {r["id"]: r for r in rows}


def within(row, value):
    if value is None or not math.isfinite(value):
        return None
    low = float(row["low"]) if row["low"] else -math.inf
    high = float(row["high"]) if row["high"] else math.inf
    return bool(low <= value <= high)


def fmt(value, unit, digits=3):
    if value is None or not math.isfinite(value):
        return "n/a"
    return f"{value:.{digits}g}" + ("" if unit == "ratio" else f" {unit}")


class Result:
    """A scenario's figures, claims and tables, written to its results folder for the report."""

    def __init__(self, scenario, title, out, quick):
        self.data = {"scenario": scenario, "title": title, "quick": quick, "figures": [], "claims": [],
                     "tables": [], "notes": [], "runs": []}
        self.out = out

    def figure(self, fig, name, caption):
        save(fig, os.path.join(self.out, name))
        plt.close(fig)
        self.data["figures"].append({"file": name, "caption": caption})

    def claim(self, row, values, digits=3):
        """One claim of the study with Chute's number in each mode (values: mode -> number, None: not run)."""
        entry = {"id": row["id"], "claim": row["claim"], "source": row["source"],
                 "study": fmt(float(row["value"]), row["unit"]), "band": band_text(row)}
        for mode in MODES:
            v = values.get(mode)
            entry[mode] = fmt(v, row["unit"], digits) if v is not None else "not run"
            ok = within(row, v) if v is not None else None
            entry["verdict " + mode] = "n/a" if v is None else ("agrees" if ok else "disagrees" if ok is False
                                                                else "no number")
        self.data["claims"].append(entry)

    def table(self, title, header, rows, note="", topic=""):
        """topic: where the report page puts it beyond the study ("force split", "wet restitution", "grid
        convergence", "contact at the bed", "rotation free"); empty: with the scenario's claims."""
        self.data["tables"].append({"title": title, "header": header, "rows": rows, "note": note, "topic": topic})

    def note(self, text):
        self.data["notes"].append(text)

    def runs(self, runs):
        for r in runs.values():
            self.data["runs"].append({"label": r.label, "mode": r.mode, "wall": r.wall,
                                      "folder": os.path.relpath(r.folder, self.out)})

    def write(self):
        write_atomically(os.path.join(self.out, "result.json"), json.dumps(self.data, indent=1))
        write_atomically(os.path.join(self.out, "summary.md"), summary_markdown(self.data))


def band_text(row):
    if row["low"] and row["high"]:
        return f"{row['low']} to {row['high']} {row['unit']}"
    if row["low"]:
        return f"> {row['low']} {row['unit']}"
    if row["high"]:
        return f"< {row['high']} {row['unit']}"
    return ""


def write_atomically(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def summary_markdown(d):
    lines = [f"# {d['title']}", ""]
    if d["quick"]:
        lines += ["(--quick: half the cells each way; the numbers are the chain's check, not the study's)", ""]
    lines += ["| claim | study | agrees if | immersed | body-fitted |", "|---|---|---|---|---|"]
    for c in d["claims"]:
        lines.append(f"| {c['claim']} | {c['study']} | {c['band']} | {c['immersed']} ({c['verdict immersed']}) | "
                     f"{c['body-fitted']} ({c['verdict body-fitted']}) |")
    for t in d["tables"]:
        lines += ["", f"**{t['title']}**", "", "| " + " | ".join(t["header"]) + " |",
                  "|" + "---|" * len(t["header"])]
        lines += ["| " + " | ".join(str(x) for x in row) + " |" for row in t["rows"]]
        if t["note"]:
            lines += ["", t["note"]]
    lines += [""] + [f"- {n}" for n in d["notes"]]
    lines += ["", "| run | mode | wall time (s) |", "|---|---|---|"]
    lines += [f"| {r['label']} | {r['mode']} | {r['wall']:.0f} |" for r in d["runs"]]
    lines += ["", "Figures: " + ", ".join(f["file"] for f in d["figures"]), ""]
    return "\n".join(lines)


def split_row(label, split):
    """A force-split table row: the parts and how far they sum from the total (a)."""
    parts = split["pressure"] + split["viscous"] + split["turbulent"]
    gap = (parts - split["forcing"]) / split["forcing"] if split["forcing"] else math.nan
    return [label, f"{split['forcing']:.1f}", f"{split['pressure']:.1f}", f"{split['viscous']:.2f}",
            f"{split['turbulent']:.2f}", f"{100 * gap:+.1f} %"]


SPLIT_HEADER = ["run", "total (a) (N)", "pressure (N)", "viscous (N)", "turbulent (N)", "parts - total"]
