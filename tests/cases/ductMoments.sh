#!/bin/bash
# Short constant-kernel duct run with one algorithm: time-averaged M0..M3 against the
# analytic eqs 39-45 (cell averages), and the mass balance closing to round-off.
#   ductMoments.sh ALGORITHM n endTime relTol [graded]
# graded: cells growing 4x in length along the duct (simpleGrading 4): the weight counts
# physical particles and the cell volume enters the rates, so grading changes the noise, not
# the answer.
. "$(dirname "$0")/caseLib.sh"
algorithm="$1"; n="$2"; endTime="$3"; relTol="$4"; graded="${5:-}"

case=$(newCase constantKernelDuct "constantDuct_$algorithm$graded")
cd "$case"
if [ "$graded" = graded ]; then
    sed -i 's/simpleGrading (1 1 1)/simpleGrading (4 1 1)/' system/blockMeshDict
    rm -rf constant/polyMesh log.blockMesh
    runApplication blockMesh
    grep -q "simpleGrading (4 1 1)" system/blockMeshDict || fail "the mesh is not graded"
fi
setEntry . constant/coagulationProperties algorithm "$algorithm"
setEntry . constant/coagulationProperties statisticalWeight/n "$n"
setEntry . system/controlDict endTime "$endTime"
setEntry . system/controlDict writeInterval "$endTime"
runApplication coagulationFoam
checkBalance log.coagulationFoam
grep -q "Selecting cell algorithm $algorithm" log.coagulationFoam || fail "algorithm $algorithm not selected"

# 47 cells x 4 moments at one tolerance: M3 near the inlet has a 95 % interval up to 6 % of
# the mean (graded, n = 512), so a moment outside the tolerance must also be 4 standard errors
# off to fail (a bias, not one stream's luck: cell 8's M3 came out +8.2 % at 2.6 standard
# errors once the random engine changed)
$report --case . --out results --no-plots --check --check-rel-tol "$relTol" --check-skip-cells 3 \
    --check-sigma 4 \
    || fail "$algorithm moments off the analytic solution by more than $relTol"
echo "PASS constant duct $algorithm $graded n=$n endTime=$endTime tol=$relTol"
