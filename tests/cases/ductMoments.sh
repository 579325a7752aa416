#!/bin/bash
# Short constant-kernel duct run with one algorithm: time-averaged M0..M3 against the
# analytic eqs 39-45 (cell averages), and the mass balance closing to round-off.
#   ductMoments.sh ALGORITHM n endTime relTol
. "$(dirname "$0")/caseLib.sh"
algorithm="$1"; n="$2"; endTime="$3"; relTol="$4"

case=$(newCase constantKernelDuct "constantDuct_$algorithm")
cd "$case"
setEntry . constant/coagulationProperties algorithm "$algorithm"
setEntry . constant/coagulationProperties statisticalWeight/n "$n"
setEntry . system/controlDict endTime "$endTime"
setEntry . system/controlDict writeInterval "$endTime"
runApplication coagulationFoam
checkBalance log.coagulationFoam
grep -q "Selecting cell algorithm $algorithm" log.coagulationFoam || fail "algorithm $algorithm not selected"

$report --case . --out results --no-plots --check --check-rel-tol "$relTol" --check-skip-cells 3 \
    || fail "$algorithm moments off the analytic solution by more than $relTol"
echo "PASS constant duct $algorithm n=$n endTime=$endTime tol=$relTol"
