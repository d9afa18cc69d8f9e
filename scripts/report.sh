#!/usr/bin/env bash
# The study reproduced as one page: runs every scenario of Turmel & Locat (2008) with its examples/<scenario>/run
# script (reusing finished runs; --redo runs them again) and writes OUT/index.html with the figures of the study's
# Figs. 4 to 10, each claim of the study with Chute's numbers in both modes and a verdict, and what the study could
# not do (python/study/report.py); beyond the study, the rockfall hazard of the study's block in a fjord, water and
# dry (examples/fjord_wall/run into OUT/fjord_wall); and the same as OUT/report.pdf when Chromium is installed.
#   scripts/report.sh [--quick] [--redo] [--out DIR] [--no-build]
# It installs what is missing and builds first (scripts/install-deps.sh, scripts/build.sh), so that it works from a
# fresh clone; --no-build skips that (the test that runs it, inside a build).
# Full: about 25 min on 2 cores, into results/study/index.html; --quick (half the cells each way): under 5 min,
# into results/study-quick/index.html (the numbers then check the chain, not the study).
set -euo pipefail
cd "$(dirname "$0")/.."
scenarios=(free_fall_block free_fall_density free_fall_size free_fall_current bounce_bed bounce_bed_1m
           bounce_bed_air_beranger bounce_slope)
# Wall seconds of each scenario's runs on 2 cores (full, measured 2026-11-24), for the time-left estimate.
declare -A expected=([free_fall_block]=270 [free_fall_density]=230 [free_fall_size]=60 [free_fall_current]=40
                     [bounce_bed]=145 [bounce_bed_1m]=35 [bounce_bed_air_beranger]=100 [bounce_slope]=700)
quick=0
out=""
build=1
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1; args+=("$1") ;;
    --redo) args+=("$1") ;;
    --out) out=$2; shift ;;
    --no-build) build=0 ;;
    *) sed -n '2,11p' "$0"; exit 2 ;;
  esac
  shift
done
if [ $build -eq 1 ]; then
  scripts/install-deps.sh
  scripts/build.sh
fi
[ -n "$out" ] || out=results/$([ $quick -eq 1 ] && echo study-quick || echo study)
mkdir -p "$out"
total=0
for s in "${scenarios[@]}"; do total=$(( total + expected[$s] )); done
[ $quick -eq 1 ] && total=$(( total / 8 ))
start=$SECONDS
left=$total
timing=""
for s in "${scenarios[@]}"; do
  printf 'report: %-24s (%d s so far, at most about %d s left: less where runs are reused)\n' "$s" "$(( SECONDS - start ))" "$left"
  t0=$SECONDS
  examples/$s/run "${args[@]}" --out "$out" > "$out/$s.log" 2>&1 || {
    echo "report: $s failed; its log: $out/$s.log" >&2
    tail -5 "$out/$s.log" >&2
    exit 3
  }
  timing+="$s $(( SECONDS - t0 ))"$'\n'
  share=${expected[$s]}
  [ $quick -eq 1 ] && share=$(( share / 8 ))
  left=$(( left > share ? left - share : 0 ))
done
printf '%s' "$timing" > "$out/timing.txt"
# Beyond the study: the rockfall hazard of the study's block in a fjord, water and dry (a few seconds of lumped
# trajectories, not CFD: run again every time), for the page's last section.
fjord=(--out "$out/fjord_wall")
[ $quick -eq 1 ] && fjord+=(--trajectories 2000)
printf 'report: %-24s (%d s so far)\n' fjord_wall "$(( SECONDS - start ))"
examples/fjord_wall/run "${fjord[@]}" > "$out/fjord_wall.log" 2>&1 || {
  echo "report: fjord_wall failed; its log: $out/fjord_wall.log" >&2
  tail -5 "$out/fjord_wall.log" >&2
  exit 3
}
/usr/bin/python3 python/study/report.py "$out"
# The same page as PDF, if Chromium is there (scripts/install-deps.sh installs it for the page's test).
page=$(cd "$out" && pwd)/index.html
if command -v chromium > /dev/null; then
  chromium --headless --no-sandbox --disable-gpu --allow-file-access-from-files --virtual-time-budget=10000 \
    --no-pdf-header-footer --print-to-pdf="$out/report.pdf.tmp" "file://$page" > /dev/null 2>&1 &&
    mv "$out/report.pdf.tmp" "$out/report.pdf" && echo "report: $out/report.pdf"
fi
echo "report: $page ($(( SECONDS - start )) s)"
