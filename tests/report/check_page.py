#!/usr/bin/python3
"""Checks the study's report page as a person would see it: renders OUT/index.html in headless Chromium (Debian's
chromium), lets the page's own script count the figures that loaded and the claim cells left empty, and checks
that every figure of the study (Figs. 4 to 10) is there and loaded, that every claim row carries the study's
number, Chute's number in the immersed mode and a verdict in both modes, and that the section beyond the study on the
rockfall hazard in a fjord is there with its figures. Saves what Chromium drew as OUT/page.png.
Usage: /usr/bin/python3 tests/report/check_page.py OUT"""
import os
import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser

# The study's figures and the file each has in the report (python/study/*.py).
STUDY_FIGURES = ["fig4_free_fall.png", "fig4_density.png", "fig4_size.png", "fig5_current.png", "fig6_bed.png",
                 "fig7_bed.png", "fig8_air_beranger.png", "fig9_slope_45.png", "fig10_slope_30.png"]
VERDICTS = {"agrees", "disagrees", "n/a"}
# Beyond the study: the rockfall hazard in a fjord (examples/fjord_wall/run, python/study/report.py), its heading and
# its figures.
FJORD_HEADING = "Beyond the study: rockfall hazard in a fjord"
FJORD_FIGURES = ["fjord_wall/water/profile.png", "fjord_wall/dry/profile.png", "fjord_wall/compare_reach.png",
                 "fjord_wall/compare_envelopes.png", "fjord_wall/water/collectors.png"]


class ClaimRows(HTMLParser):
    """The cells of every <tr class="claim">, the src of every <img> and the text of every <h2>."""

    def __init__(self):
        super().__init__()
        self.rows, self.images, self.cell, self.row = [], [], None, None
        self.headings, self.heading = [], None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "tr" and a.get("class") == "claim":
            self.row = []
        elif tag == "td" and self.row is not None:
            self.cell = ""
        elif tag == "img":
            self.images.append(a.get("src", ""))
        elif tag == "h2":
            self.heading = ""

    def handle_endtag(self, tag):
        if tag == "td" and self.cell is not None:
            self.row.append(self.cell.strip())
            self.cell = None
        elif tag == "tr" and self.row is not None:
            self.rows.append(self.row)
            self.row = None
        elif tag == "h2" and self.heading is not None:
            self.headings.append(self.heading.strip())
            self.heading = None

    def handle_data(self, data):
        if self.cell is not None:
            self.cell += data
        if self.heading is not None:
            self.heading += data


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if shutil.which(name):
            return name
    raise SystemExit("check_page: no chromium (Debian: apt-get install chromium)")


def main(out):
    page = os.path.abspath(os.path.join(out, "index.html"))
    flags = [chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--allow-file-access-from-files",
             "--virtual-time-budget=10000"]
    dom = subprocess.run(flags + ["--dump-dom", "file://" + page], capture_output=True, text=True, timeout=120).stdout
    subprocess.run(flags + ["--window-size=1200,6000", f"--screenshot={os.path.join(out, 'page.png')}",
                            "file://" + page], capture_output=True, timeout=120)
    body = re.search(r"<body([^>]*)>", dom)
    failures = []
    if not body:
        raise SystemExit(f"check_page: Chromium rendered no page from {page}")
    attrs = dict(re.findall(r'data-([a-z-]+)="([^"]*)"', body.group(1)))
    loaded, total = (int(x) for x in attrs.get("figures", "0/0").split("/"))
    if loaded != total or total == 0:
        failures.append(f"{loaded} of {total} figures loaded")
    if attrs.get("empty-cells") != "0":
        failures.append(f"{attrs.get('empty-cells')} empty claim cells")
    parsed = ClaimRows()
    parsed.feed(dom)
    for name in STUDY_FIGURES:
        if not any(src.endswith("/" + name) for src in parsed.images):
            failures.append(f"the study's figure {name} is not on the page")
    if FJORD_HEADING not in parsed.headings:
        failures.append(f"no section '{FJORD_HEADING}'")
    for name in FJORD_FIGURES:
        if name not in parsed.images:
            failures.append(f"the fjord's figure {name} is not on the page")
    if len(parsed.rows) < 10:
        failures.append(f"only {len(parsed.rows)} claim rows")
    for row in parsed.rows:
        # [figure,] claim, study, band, immersed, verdict, body-fitted, verdict
        verdicts, immersed = row[-3::2], row[-4]
        if not set(verdicts) <= VERDICTS:
            failures.append(f"a claim without a verdict: {row}")
        if not re.match(r"-?[0-9]", immersed):
            failures.append(f"a claim without Chute's immersed number: {row}")
    print(f"check_page: {loaded}/{total} figures loaded, {len(parsed.rows)} claim rows, "
          f"{attrs.get('empty-cells')} empty cells; {os.path.join(out, 'page.png')}")
    if failures:
        raise SystemExit("check_page: " + "; ".join(failures))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    main(sys.argv[1])
