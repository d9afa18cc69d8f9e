#!/usr/bin/env bash
# README command 1: install dependencies, build, run the default example with plots.
#   scripts/setup-and-run.sh [CASE.yaml] [chute run options...]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
case_file=${1:-examples/free_fall_block/case.yaml}
shift || true
ranks=${CHUTE_RANKS:-$(( $(nproc) > 1 ? 2 : 1 ))}
mpirun --allow-run-as-root --oversubscribe -np "$ranks" build/apps/chute run "$case_file" "$@"
