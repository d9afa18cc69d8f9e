#!/usr/bin/env bash
# Runs the cases of one scenario (the immersed case and its body-fitted versions, or water and air) and writes one
# comparison: OUT/compare.md (a table of what users compare, with each run's difference from the first) and
# OUT/compare_<body>.png (python/compare_runs.py). The documented equivalent of `chute compare`.
#   scripts/compare.sh OUT LABEL=CASE.yaml [LABEL=CASE.yaml ...]     (after scripts/build.sh)
# Example: scripts/compare.sh results/compare_free_fall immersed=examples/free_fall_block/case.yaml \
#            layers=examples/free_fall_block/body_fitted_layers.yaml
# A run may change its case's keys: 'air=examples/bounce_bed/case.yaml --set fluid.density=1.2' (one argument).
# Each run goes to OUT/<label>; a finished run (its summary.txt there) is reused: delete the folder to redo it.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { sed -n '2,10p' "$0"; exit 2; }
out=$1
shift
ranks=${CHUTE_RANKS:-$(( $(nproc) > 1 ? 2 : 1 ))}
runs=()
for pair in "$@"; do
  label=${pair%%=*}
  read -r -a run_args <<< "${pair#*=}"  # the case, then any --set key=value
  case_file=${run_args[0]:-}
  [ "$label" != "$pair" ] && [ -f "$case_file" ] || { echo "compare: '$pair' is not LABEL=CASE.yaml with an existing case"; exit 2; }
  dir="$out/$label"
  if [ ! -f "$dir/summary.txt" ]; then
    echo "compare: running $case_file -> $dir"
    mpirun --allow-run-as-root --oversubscribe -np "$ranks" build/apps/chute run "${run_args[@]}" --out "$dir" --no-plots > /dev/null
  fi
  runs+=("$label=$dir")
done
/usr/bin/python3 python/compare_runs.py "$out" "${runs[@]}"
