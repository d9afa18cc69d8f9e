#!/usr/bin/python3
"""The report page: Turmel & Locat's (2008) underwater-rockfall study reproduced by Chute, one section per figure of
the study (Figs. 4 to 10) with the study's claim, Chute's numbers in both modes and a verdict, then what the study
could not do. Reads the result.json that each scenario's figure wrote (python/study/figure.py) and the timing that
scripts/report.sh kept; writes OUT/index.html (figures referenced in their scenario folders) atomically.
Usage: /usr/bin/python3 python/study/report.py OUT"""
import datetime
import html
import json
import os
import platform
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import MODES, write_atomically  # noqa: E402
from figure import SCENARIOS  # noqa: E402

TOPICS = [
    ("rotation free", "Bounces with the rotation free",
     "The study locked the rotation (its mesh modifiers could not turn the block). Immersed mode, water."),
    ("contact at the bed", "Contact at the bed rather than 0.1 m off it",
     "The study's mesh needed two layers of cells under the block, so its contact was 10 cm from the bed; it "
     "expected an overpressure in the squeezed water to brake the block before a contact at the bed."),
    ("force split", "The force on the block split into its pressure, viscous and turbulent parts",
     "The study's eqs. 10-15. 'parts - total' is how far the surface-stress parts sum from the force the "
     "immersed forcing (or the body-fitted faces) gives: the open issue 'trustworthy forces' tracks the gap."),
    ("wet restitution", "Wet restitution: what the CFD gives against the dry 0.8 the study assumed",
     "The study took the wet restitution equal to the dry one (Stokes number above 1000). The dry-equivalent "
     "coefficient is the one a dry lumped model would need to rebound as high as the CFD block does."),
    ("grid convergence", "Grid convergence of the headline numbers",
     "Half and 1.5 times the cells each way (domain.refinement), the study's grid in the middle."),
]

STYLE = """
body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; color: #222; line-height: 1.4; }
table { border-collapse: collapse; margin: 0.6em 0 1.2em; font-size: 0.9em; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.5em; vertical-align: top; }
th { background: #eee; }
td.agrees { background: #dff3df; } td.disagrees { background: #f8dddd; } td.na { background: #f3f3f3; }
figure { margin: 1em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.9em; color: #444; } .quick { background: #fff3cd; padding: 0.5em; }
.note { font-size: 0.9em; color: #444; }
"""

# A person's check, run by the page itself: every figure loaded and every claim row filled. The headless-Chromium
# test (tests/report/check_page.py) reads the result from the rendered page's body attributes.
CHECK = """
<script>
window.addEventListener("load", function () {
  var images = document.querySelectorAll("img");
  var loaded = 0;
  images.forEach(function (img) { if (img.complete && img.naturalWidth > 0) loaded += 1; });
  var empty = 0;
  document.querySelectorAll("tr.claim td").forEach(function (td) { if (td.textContent.trim() === "") empty += 1; });
  document.body.setAttribute("data-figures", loaded + "/" + images.length);
  document.body.setAttribute("data-claims", document.querySelectorAll("tr.claim").length);
  document.body.setAttribute("data-empty-cells", empty);
});
</script>
"""


def esc(x):
    return html.escape(str(x))


def verdict_class(v):
    return {"agrees": "agrees", "disagrees": "disagrees"}.get(v, "na")


def claims_table(results, with_scenario):
    rows = ["<table><tr>" + ("<th>figure</th>" if with_scenario else "") +
            "<th>the study's claim</th><th>study</th><th>agrees if</th>" +
            "".join(f"<th>Chute, {m}</th><th>verdict</th>" for m in MODES) + "</tr>"]
    for d in results:
        for c in d["claims"]:
            cells = ([f"<td>{esc(d['title'])}</td>"] if with_scenario else []) + [
                f"<td>{esc(c['claim'])}<br><span class='note'>{esc(c['source'])}</span></td>",
                f"<td>{esc(c['study'])}</td>", f"<td>{esc(c['band'])}</td>"]
            for m in MODES:
                v = c["verdict " + m]
                cells += [f"<td>{esc(c[m])}</td>", f"<td class='{verdict_class(v)}'>{esc(v)}</td>"]
            rows.append("<tr class='claim'>" + "".join(cells) + "</tr>")
    return "\n".join(rows) + "</table>"


def table_html(t):
    out = [f"<p><b>{esc(t['title'])}</b></p><table><tr>" + "".join(f"<th>{esc(h)}</th>" for h in t["header"]) +
           "</tr>"]
    out += ["<tr>" + "".join(f"<td>{esc(x)}</td>" for x in row) + "</tr>" for row in t["rows"]]
    out.append("</table>")
    if t["note"]:
        out.append(f"<p class='note'>{esc(t['note'])}</p>")
    return "\n".join(out)


FJORD_HEADING = "Beyond the study: rockfall hazard in a fjord"
# The fjord section's figures (examples/fjord_wall/run's folders under OUT/fjord_wall) and their captions.
FJORD_FIGURES = [
    ("water/profile.png", "With the water: the profile (the fjord shaded), sample paths (flights blue, slides "
     "orange), where the blocks stopped and the probability that a block stops beyond x."),
    ("dry/profile.png", "The same slope dry (the water level below the profile)."),
    ("compare_reach.png", "Reach probability against x, water and dry, on a linear and a logarithmic scale, with "
     "the profile beneath."),
    ("compare_envelopes.png", "Speed and translational kinetic energy along the slope, 95th percentile and mean "
     "among the blocks crossing each station, water and dry."),
    ("water/collectors.png", "With the water: the energies of the blocks that hit each collector."),
]


def fjord_section(out, quick):
    """The rockfall hazard of the study's block in a fjord (examples/fjord_wall/run into OUT/fjord_wall), water and
    dry: what it is, the comparison's table (compare.json) and its figures; nothing if it was not run."""
    path = os.path.join(out, "fjord_wall", "compare.json")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        d = json.load(f)
    model = ""
    summary = os.path.join(out, "fjord_wall", "water", "summary.txt")
    if os.path.exists(summary):
        model = next((line.strip() for line in open(summary) if line.strip().startswith("water level")), "")
    runs = {r["label"]: r for r in d["runs"]}
    n = sorted({r["trajectories"] for r in d["runs"]})
    section = [f"<h2 id='fjord_wall'>{esc(FJORD_HEADING)}</h2>",
               "<p>The study's block (0.3 m, 2500 kg/m<sup>3</sup>) falling off a 40 m rock cliff into a fjord, down "
               "a talus under the water to 40 m depth and onto a muddy seabed (examples/fjord_wall). Not CFD: "
               f"{' and '.join(str(x) for x in n)} Monte Carlo trajectories per run of the lumped block "
               "(<code>chute hazard</code>: release point and speed, restitution, friction and the ground's "
               "roughness drawn for each block and impact), whose wet model (drag, added mass, buoyancy and the "
               "wet restitution) is calibrated by Chute's CFD runs of the study's block "
               "(data/calibration/study_block.yaml). <b>water</b> is the case as written; <b>dry</b> is the same "
               "slope with the water level below it. A collector is hit by a block that passes it at or below its "
               "height.</p>",
               "<p class='note'>How far to trust the wet runs: the calibrated lumped model, braked near the ground "
               "by the water it squeezes out (its impact speeds within 6 % of the CFD's on the bed), whose wet "
               "restitution grows with the wake over the fall and which on slopes carries the lift of oblique "
               "impacts and the water's push along the slope (measured at 30 degrees), reproduces CFD runs it was "
               "not fitted to within 15 % for near-normal impacts: the 30 degree slope at another impact speed "
               "(+2.0 % in height, -6.4 % in runout) and the 1 m block at the same contact distance over size "
               "(-0.7 %); an impact at 49 degrees from the normal is off by -39 % in height, a block arriving along "
               "the slope (the impacts a hazard run meets most) by -38 %; flown from the release as here, its "
               "first bounce after a drop onto the 30 degree slope is a third too high (with the bed's law on "
               "slopes, model.slope_law=false, 20-40 % too low: the two runs bracket it); steeper than 30 degrees it is "
               "an extrapolation (the talus here is 35 degrees; at 45 degrees the CFD's block is lifted by the "
               "water in its flight, -71 %): docs/validation.md, \"Hazard analysis\".</p>"]
    if model:
        section.append(f"<p class='note'>The water run's settings (its summary.txt): {esc(model)}.</p>")
    section.append(table_html({"title": "Water (with the slope law, and with the bed's law on every slope: the "
                                        "bracket of the talus's bounces) against dry: how the blocks ended, where "
                                        "they stopped, what they brought to the collectors", "header": d["table"]["header"],
                               "rows": d["table"]["rows"],
                               "note": "Stopping x: percentiles over all blocks (a block past the profile's end "
                                       "counted at its last x). Hit energy: translational and rotational, over the "
                                       "hits; – where none."}))
    for fig, caption in FJORD_FIGURES:
        section.append(f"<figure><img src='fjord_wall/{esc(fig)}' alt='{esc(caption)}'>"
                       f"<figcaption>{esc(caption)}</figcaption></figure>")
    seconds = ", ".join(f"{esc(label)} {r['seconds']:.1f} s" for label, r in runs.items())
    section.append(f"<p class='note'>Wall time of the trajectories: {seconds}. Run it alone: "
                   "<code>examples/fjord_wall/run" + (" --trajectories 2000" if quick else "") +
                   "</code>; the table as Markdown: "
                   "<a href='fjord_wall/compare.md'>fjord_wall/compare.md</a>.</p>")
    return section


def machine():
    cpu = ""
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next((line.split(":", 1)[1].strip() for line in f if line.startswith("model name")), "")
    except OSError:
        pass
    return f"{os.cpu_count()} cores, {cpu or platform.processor()}"


def commit():
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                              cwd=os.path.dirname(os.path.abspath(__file__))).stdout.strip()
    except OSError:
        return "unknown"


def main(out):
    results = []
    for scenario in SCENARIOS:
        path = os.path.join(out, scenario, "result.json")
        if not os.path.exists(path):
            raise SystemExit(f"report: {path} is missing: run examples/{scenario}/run first")
        with open(path) as f:
            results.append(json.load(f))
    timing = {}
    if os.path.exists(os.path.join(out, "timing.txt")):
        for line in open(os.path.join(out, "timing.txt")):
            name, seconds = line.split()
            timing[name] = int(seconds)
    quick = any(d["quick"] for d in results)
    page = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
            "<title>Chute: Turmel & Locat (2008) underwater rockfall, reproduced</title>",
            f"<style>{STYLE}</style>{CHECK}</head><body>",
            "<h1>Underwater rockfall (Turmel &amp; Locat 2008) reproduced by Chute</h1>",
            f"<p>Chute {esc(commit())}, {datetime.date.today().isoformat()}, {esc(machine())}. Every scenario in "
            "both ways of carrying the block: <b>immersed</b> (the block on a fixed Cartesian grid) and "
            "<b>body-fitted</b> (the block a hole in the grid, with the study's mesh modifiers: layers of cells "
            "added and removed around it). k-epsilon throughout, 20 cells across the block, rotation locked and "
            "contact 0.1 m off the bed as in the study, Rn = Rt = 0.8. Command: <code>scripts/report.sh</code>"
            + (" --quick" if quick else "") + ".</p>"]
    if quick:
        page.append("<p class='quick'>--quick: half the cells each way (10 across the block). The numbers check "
                    "the chain from the runs to this page; they are not the study's comparison.</p>")
    page.append("<h2>The study's claims</h2>")
    page.append(claims_table(results, True))
    for d in results:
        page.append(f"<h2 id='{esc(d['scenario'])}'>{esc(d['title'])}</h2>")
        for fig in d["figures"]:
            page.append(f"<figure><img src='{esc(d['scenario'])}/{esc(fig['file'])}' alt='{esc(fig['caption'])}'>"
                        f"<figcaption>{esc(fig['caption'])}</figcaption></figure>")
        page.append(claims_table([d], False))
        page += [table_html(t) for t in d["tables"] if not t.get("topic")]
        page += [f"<p class='note'>{esc(n)}</p>" for n in d["notes"]]
        runs = ", ".join(f"{r['label']} ({r['wall']:.0f} s)" for r in d["runs"])
        seconds = timing.get(d["scenario"])
        page.append(f"<p class='note'>Runs: {esc(runs)}. "
                    + (f"This scenario took {seconds} s here. " if seconds is not None else "")
                    + f"Run it alone: <code>examples/{esc(d['scenario'])}/run"
                    + (" --quick" if quick else "") + f"</code>; its summary: "
                    f"<a href='{esc(d['scenario'])}/summary.md'>{esc(d['scenario'])}/summary.md</a>.</p>")
    page.append("<h2>Beyond the study</h2>")
    for topic, heading, intro in TOPICS:
        tables = [t for d in results for t in d["tables"] if t.get("topic") == topic]
        page.append(f"<h3>{esc(heading)}</h3><p class='note'>{esc(intro)}</p>")
        page += [table_html(t) for t in tables] or ["<p class='note'>Not run (--quick).</p>"]
    page += fjord_section(out, quick)
    page.append("<h2>Time taken</h2><p class='note'>The runs' own wall times (what each scenario costs from "
                "scratch; a run shared by two scenarios is counted in each) and the time this call of "
                "scripts/report.sh spent (finished runs are reused).</p><table><tr><th>scenario</th>"
                "<th>its runs (s)</th><th>this call (s)</th></tr>")
    total = 0.0
    for d in results:
        runs = sum(r["wall"] for r in d["runs"] if r["wall"] == r["wall"])
        total += runs
        page.append(f"<tr><td>{esc(d['scenario'])}</td><td>{runs:.0f}</td>"
                    f"<td>{timing.get(d['scenario'], 'n/a')}</td></tr>")
    page.append(f"<tr><td><b>all</b></td><td><b>{total:.0f}</b></td><td><b>{sum(timing.values())}</b></td></tr>"
                "</table>")
    page.append("</body></html>")
    write_atomically(os.path.join(out, "index.html"), "\n".join(page))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    main(sys.argv[1])
