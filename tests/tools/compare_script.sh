#!/usr/bin/env bash
# scripts/compare.sh end to end on two small runs (a square falling 2 s in water, carried body-fitted with the whole
# grid translating and with modifier layers): the table has both runs' terminal speeds and the plot is written; a
# second call reuses the finished runs. Needs build/apps/chute (scripts/build.sh) and Debian's python3 packages.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
base='name: falling_square
domain:
  x: {start: -2.0, end: 2.0, cells: 16}
  Y_LINE
fluid: {density: 1000.0, viscosity: 1.0e-3}
boundaries:
  left: {type: slip}
  right: {type: slip}
  BOUNDARIES
bodies:
  square:
    shape: rectangle
    centre: [0.0, 0.0]
    size: [1.0, 1.0]
    carrier: body_fitted
    GRID_MOTION
    density: 2500.0
    motion: {type: free, lock_x: true, lock_rotation: true}
contact: {distance: 0.1}
numerics: {convection: van_leer, cfl: 0.5}
time: {end: 2.0}
output: {fields_interval: 0.0, plots: false}'
translate=${base/Y_LINE/"y: {start: -3.0, end: 5.0, spacing: clustered, core: [-1.0, 1.0], core_cells: 8, ratio: 1.2, max: 0.5}"}
translate=${translate/BOUNDARIES/"bottom: {type: inflow, velocity: [0.0, 0.0]}
  top: {type: outflow, kind: convective}"}
translate=${translate/GRID_MOTION/"grid_motion: translate"}
translate=${translate/contact: \{distance: 0.1\}/}
layers=${base/Y_LINE/"y: {start: -12.0, end: 5.0, spacing: clustered, core: [-1.0, 1.0], core_cells: 8, ratio: 1.2, max: 0.5}"}
layers=${layers/BOUNDARIES/"bottom: {type: wall}
  top: {type: wall}"}
layers=${layers/GRID_MOTION/"grid_motion: layers"}
printf '%s\n' "$translate" > "$work/translate.yaml"
printf '%s\n' "$layers" > "$work/layers.yaml"
export CHUTE_RANKS=1
"$root/scripts/compare.sh" "$work/out" translate="$work/translate.yaml" layers="$work/layers.yaml" > "$work/first.txt"
grep -q '^| terminal speed, mean t >= 1.5 s (m/s) | [0-9.]* | [0-9.]* ([-+][0-9.]* %) |$' "$work/out/compare.md" ||
  { echo "compare.md has no terminal-speed row for both runs:"; cat "$work/out/compare.md"; exit 1; }
[ -s "$work/out/compare_square.png" ] || { echo "no compare_square.png"; exit 1; }
# A second call reuses the runs (no "running" line) and writes the same table.
"$root/scripts/compare.sh" "$work/out" translate="$work/translate.yaml" layers="$work/layers.yaml" > "$work/second.txt"
! grep -q '^compare: running' "$work/second.txt" || { echo "the finished runs were made again"; exit 1; }
grep -q 'terminal speed' "$work/second.txt"
# A run may change its case's keys: a denser square (3000 against 2500 kg/m^3) falls faster.
"$root/scripts/compare.sh" "$work/out" layers="$work/layers.yaml" \
  "denser=$work/layers.yaml --set bodies.square.density=3000.0" > "$work/third.txt"
grep -q '^#   bodies.square.density=3000.0$' "$work/out/denser/case.yaml" || { echo "the --set did not reach the run"; exit 1; }
grep -q '^| terminal speed, mean t >= 1.5 s (m/s) | [0-9.]* | [0-9.]* (+[0-9.]* %) |$' "$work/out/compare.md" ||
  { echo "the denser square does not fall faster:"; cat "$work/out/compare.md"; exit 1; }
echo "compare_script: ok"; grep 'terminal speed' "$work/out/compare.md"
