#!/usr/bin/env bash
# Runs the time-step benchmark (bench_step) on 1 and 2 ranks for 256^2, 512^2 and 1024^2 and prints the
# Markdown tables that docs/performance.md quotes. Builds bench_step first if needed.
#
#   bench/run_benchmarks.sh [extra bench_step options]      e.g. --warmup 20 --min-seconds 1
#
# Environment: BUILD_DIR (default <repo>/build), RANKS (default "1 2"), GRIDS (default "256 512 1024"),
# RUNS (default 1: run each rank count this many times; quote the best run).
# Takes about 1-2 minutes per run on the 2-core reference machine; run it on an idle machine.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$repo/build}"
ranks="${RANKS:-1 2}"
grids="${GRIDS:-256 512 1024}"
runs="${RUNS:-1}"

if [[ ! -f "$build/CMakeCache.txt" ]]; then
    cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j2 --target bench_step >/dev/null

bench="$build/bench/bench_step"
mpirun_flags=(--allow-run-as-root --oversubscribe)

echo "# bench_step, $(date '+%Y-%m-%d %H:%M'), $(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo 'no git')"
echo "uptime: $(uptime)"
echo
# shellcheck disable=SC2086  # grids and ranks are word lists
for run in $(seq 1 "$runs"); do
    for np in $ranks; do
        [[ "$runs" -gt 1 ]] && echo "## run $run of $runs, $np rank(s)" && echo
        mpirun "${mpirun_flags[@]}" -np "$np" "$bench" --kernels "$@" $grids
        echo
    done
done
