#!/usr/bin/env bash
# README command 2: install dependencies, build, run the test suite (unit + validation, not "slow").
#   scripts/test.sh            the CI suite
#   scripts/test.sh -L slow    only the long validation runs
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
cd build
if [ $# -eq 0 ]; then
  ctest --output-on-failure -LE slow
else
  ctest --output-on-failure "$@"
fi
