#!/usr/bin/env bash
# The study's report end to end at reduced resolution (scripts/report.sh --quick: every scenario's run script, half
# the cells each way), then the page as Chromium shows it (check_page.py: every figure of Figs. 4-10 loaded, every
# claim row filled), then a second call that must reuse every finished run. Needs build/apps/chute, Debian's python3
# packages and chromium (scripts/install-deps.sh). About 3 min on 2 cores.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$root/scripts/report.sh" --quick --no-build --out "$work"
/usr/bin/python3 "$root/tests/report/check_page.py" "$work"
for s in "$work"/*/summary.md; do
  grep -q "^| claim |" "$s" || { echo "study_report_quick: no claims in $s"; exit 1; }
done
"$root/scripts/report.sh" --quick --no-build --out "$work" > "$work/second.txt"
if grep -h "running" "$work"/*.log; then
  echo "study_report_quick: the second call ran again what the first had finished"
  exit 1
fi
echo "study_report_quick: passed"
