# Helpers for the case-level tests (bash).  Each test works in its own folder,
# $COAGULATIONFOAM_TEST_WORKDIR (set by CTest), starting from a tutorial.
set -euo pipefail
testsDir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=/dev/null
. "$testsDir/../../etc/functions"

workDir="${COAGULATIONFOAM_TEST_WORKDIR:-$(mktemp -d)}"
report="$COAGULATIONFOAM_PYTHON $COAGULATIONFOAM_DIR/applications/utilities/coagulationReport/coagulationReport.py"

fail() { echo "FAIL: $*" >&2; exit 1; }

# newCase tutorial dir: a fresh copy of a tutorial in $workDir/dir, with a mesh
newCase()
{
    local dir="$workDir/$2"
    rm -rf "$dir"
    mkdir -p "$workDir"
    cp -r "$COAGULATIONFOAM_DIR/tutorials/$1" "$dir"
    (cd "$dir" && cleanCase && runApplication blockMesh) >&2
    echo "$dir"
}

# tutorialCase tutorial dir [Allclean options]: a fresh copy of a tutorial in $workDir/dir,
# cleaned by its own Allclean (the tests that run its Allrun), on standard output
tutorialCase()
{
    local dir="$workDir/$2"
    rm -rf "$dir"
    mkdir -p "$workDir"
    cp -r "$COAGULATIONFOAM_DIR/tutorials/$1" "$dir"
    (cd "$dir" && ./Allclean "${@:3}") > /dev/null
    echo "$dir"
}

# runAllrun [options]: the tutorial's own ./Allrun in the current folder, logged to
# log.Allrun, failing the test where it fails. These tests check the tutorials' physics, not
# their ParaView picture (case_paraview does): a picture pvbatch cannot make is a note
# (COAGULATIONFOAM_PARAVIEW_OPTIONAL=1), shown here, not a failure
runAllrun()
{
    COAGULATIONFOAM_PARAVIEW_OPTIONAL=1 ./Allrun "$@" > log.Allrun 2>&1 \
        || { tail -n 30 log.Allrun; fail "Allrun"; }
    grep "^NOTE: no ParaView picture" log.Allrun || :
}

# setEntry case file entry value
setEntry()
{
    foamDictionary -case "$1" "$1/$2" -entry "$3" -set "$4" > /dev/null
}

# checkBalance log: the mass balance closes to round-off and no particle is lost
checkBalance()
{
    local log="$1"
    local err
    err=$(grep "mass balance error" "$log" | tail -1 | awk '{print $NF}')
    [ -n "$err" ] || fail "no mass balance line in $log"
    awk -v e="$err" 'BEGIN { exit !(e < 1e-12 && e > -1e-12) }' \
        || fail "mass balance error $err in $log"
    grep "particle balance error" "$log" | awk '{ if ($NF != 0) exit 1 }' \
        || fail "particle balance error in $log"
    echo "mass balance error $err, particle balance exact"
}

# couetteWalkCase: in a copy of a tutorial (the current folder), the Couette channel of
# case_channels with cellPoint velocity and a constant-D walk (rebound walls), n = 512,
# t = 0..0.1, writes at 0.05 and 0.1 (case_threads, case_parallel)
couetteWalkCase()
{
    rm -rf constant/polyMesh log.blockMesh
    PYTHONPATH="$COAGULATIONFOAM_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}" \
        "$COAGULATIONFOAM_PYTHON" "$COAGULATIONFOAM_DIR/tests/cases/poiseuilleCase.py" setup . couette
    runApplication blockMesh
    setEntry . constant/coagulationProperties statisticalWeight/n 512
    foamDictionary -entry transport -add "{ type frozenFlow; interpolationSchemes { U cellPoint; } }" \
        constant/coagulationProperties > /dev/null
    foamDictionary -entry dispersion -add "{ type constant; D 1e-6; }" constant/coagulationProperties > /dev/null
    setEntry . system/controlDict deltaT 5e-4
    setEntry . system/controlDict endTime 0.1
    setEntry . system/controlDict writeInterval 0.05
}
