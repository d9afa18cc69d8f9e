#!/usr/bin/env bash
# Configures and builds Chute in ./build (Release, warnings as errors).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCHUTE_WERROR=ON > build-configure.log || { cat build-configure.log; exit 1; }
cmake --build build -j"$(nproc)"
