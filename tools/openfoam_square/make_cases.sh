#!/bin/bash
# The OpenFOAM k-epsilon reference of the square cylinder at Re 22,000 (docs/validation.md, "Sharp interface", sixth
# step, point 5): generate (and optionally run) the cases from scratch, in $OUT (default ./openfoam_square_cases).
#   tools/openfoam_square/make_cases.sh                 generate and mesh every case
#   tools/openfoam_square/make_cases.sh run CASE ...    generate, mesh and run the named cases one after the other
# Cases: aligned20 (Chute's examples/square_cylinder_re22000 grid, the square cut out), rot45_20, rot45_30,
# rot22.5_20 (turned squares, an H-grid in the square's frame and a ring of blocks to the domain).
# Needs Debian's OpenFOAM v1912 and numpy: apt-get install -y openfoam python3-numpy. 4-14 min a case on one core.
# Statistics: python3 tools/openfoam_square/analyse.py $OUT/CASE t0 t1
set -e
here=$(cd "$(dirname "$0")" && pwd)
out=$(mkdir -p "${OUT:-openfoam_square_cases}" && cd "${OUT:-openfoam_square_cases}" && pwd)
export WM_PROJECT_DIR=/usr/share/openfoam FOAM_ETC=/usr/share/openfoam/etc
mode=${1:-mesh}; [ $# -gt 0 ] && shift
cases=${*:-aligned20 rot45_20 rot45_30 rot22.5_20}
for c in $cases; do
    python3 "$here/make_cases.py" "$out" "$c"
    cd "$out/$c"
    rm -rf 0 [1-9]* postProcessing constant/polyMesh
    blockMesh > log.blockMesh 2>&1
    checkMesh > log.checkMesh 2>&1 || true
    cp -r 0.orig 0
    setFields > log.setFields 2>&1
    if [ "$mode" = run ]; then
        t0=$(date +%s)
        pimpleFoam > log.pimpleFoam 2>&1 || echo "pimpleFoam failed in $c"
        echo "wall_seconds $(($(date +%s) - t0))" > WALLTIME
        python3 "$here/analyse.py" . > RESULT.txt || true
    fi
done
