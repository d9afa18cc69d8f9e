#!/usr/bin/env python3
"""Writes profile.csv: a fjord wall in 100 segments (x, z, material of the segment starting at the row).

A rock cliff from 40 m above the fjord down to the water (about 60 degrees, steps of a few metres), a talus of
blocks under the water (about 35 degrees) down to 40 m depth, and a muddy seabed that flattens out over 150 m.
The irregularities are deterministic (a sum of sines), so the file is reproducible:
    python3 examples/fjord_wall/make_profile.py > examples/fjord_wall/profile.csv
"""
import math

rows = []
def add(x, z, material):
    rows.append((x, z, material))

# Cliff: 0..24 m, 40 m -> 0 m, 20 segments.
for i in range(20):
    x = 24.0 * i / 20
    z = 40.0 - 40.0 * i / 20 + 0.6 * math.sin(1.7 * i)
    add(x, z, "rock")
# Talus under water: 24..81 m, 0 -> -40 m (35 degrees), 30 segments.
for i in range(30):
    x = 24.0 + 57.0 * i / 30
    z = -40.0 * i / 30 + 0.1 * math.sin(2.3 * i)
    add(x, z, "talus")
# Seabed: 81..250 m, from -40 m flattening to -46 m, 50 segments (mud).
for i in range(51):
    x = 81.0 + 169.0 * i / 50
    z = -40.0 - 6.0 * (1.0 - math.exp(-(x - 81.0) / 40.0)) + 0.05 * math.sin(1.3 * i)
    add(x, z, "mud")
print("x,z,material")
for x, z, m in rows:
    print(f"{x:.4f},{z:.4f},{m}")
