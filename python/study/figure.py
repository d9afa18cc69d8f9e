#!/usr/bin/python3
"""A scenario's figures, claims and summary from its runs (called by examples/<scenario>/run through
scripts/study-lib.sh): reads OUT/runs.txt and the folder's reference.csv, writes the PNGs, result.json (for the report
page, python/study/report.py) and summary.md into OUT.
Usage: /usr/bin/python3 python/study/figure.py SCENARIO EXAMPLE_FOLDER OUT [--quick]"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bounce  # noqa: E402
import fall  # noqa: E402
import slope  # noqa: E402
from common import Result, read_reference  # noqa: E402
from runs import read_runs  # noqa: E402

# scenario folder -> (title, figure function); the order is the report's.
SCENARIOS = {
    "free_fall_block": ("Free fall of the 0.3 m block (Fig. 4)", fall.free_fall),
    "free_fall_density": ("Block density (Fig. 4)", fall.density),
    "free_fall_size": ("Block size (Fig. 4)", fall.size),
    "free_fall_current": ("A 1 m/s current (Fig. 5)", fall.current),
    "bounce_bed": ("Bouncing on the bed, 0.3 m block (Fig. 6)", bounce.bed_03),
    "bounce_bed_1m": ("Bouncing on the bed, 1 m block (Fig. 7)", bounce.bed_1m),
    "bounce_bed_air_beranger": ("Water against air and the Beranger model (Fig. 8)", bounce.air_beranger),
    "bounce_slope": ("Bouncing on 45 and 30 degree slopes, water against air (Figs. 9 and 10)", slope.slopes),
}


def main(argv):
    if len(argv) < 4 or argv[1] not in SCENARIOS:
        raise SystemExit(__doc__ + "\nscenarios: " + ", ".join(SCENARIOS))
    scenario, folder, out = argv[1], argv[2], argv[3]
    title, draw = SCENARIOS[scenario]
    result = Result(scenario, title, out, "--quick" in argv[4:])
    runs = read_runs(out)
    draw(runs, read_reference(folder), result)
    result.runs(runs)
    result.write()
    print(open(os.path.join(out, "summary.md")).read())


if __name__ == "__main__":
    main(sys.argv)
