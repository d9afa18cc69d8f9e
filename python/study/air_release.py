"""Where to release the block in air so that it meets the slope at the speed the water run measured (the study set
the same speed at contact in air and water, Turmel & Locat 2008, sec. 4.3): a dry fall along gravity of v^2 / (2 g),
whose component across the bed closes the gap to the contact plane.
Usage: /usr/bin/python3 python/study/air_release.py WATER_RUN_FOLDER     prints the centre as [x, y]"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from runs import Run  # noqa: E402

water = Run("water", sys.argv[1])
speed = water.impact_speed()
g = float((water.gravity @ water.gravity) ** 0.5)
fall = speed ** 2 / (2 * g)
block = water.case["bodies"]["block"]
gap_at_impact = float(water.impacts["y_centre"][0])  # the centre's height when the contact meets the bed
centre_y = gap_at_impact + fall * abs(water.down[1])
print(f"[{float(block['centre'][0])},{centre_y:.6f}]")
