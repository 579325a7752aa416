#!/bin/bash
# Short additive-kernel duct, SWA: last cell [0.098, 0.1] M1 against m1 = I x/u = 9.90e3
# (eq 50) and M2 against the paper's SWA limit 9.1e7 (Table 2), mass balance closed.
#   additiveDuct.sh n endTime tolM1 tolM2
. "$(dirname "$0")/caseLib.sh"
n="$1"; endTime="$2"; tolM1="$3"; tolM2="$4"

case=$(newCase additiveKernelDuct additiveDuct_SWA)
cd "$case"
setEntry . constant/coagulationProperties statisticalWeight/n "$n"
setEntry . system/controlDict endTime "$endTime"
setEntry . system/controlDict writeInterval "$endTime"
runApplication coagulationFoam
checkBalance log.coagulationFoam

$report --case . --out results --no-plots \
    --check-cell-index -1 --check-moment 1 --check-value 9.90e3 --check-value-rel-tol "$tolM1" \
    --check-cell-index -1 --check-moment 2 --check-value 9.1e7 --check-value-rel-tol "$tolM2" \
    || fail "additive duct last-cell moments off"
echo "PASS additive duct SWA n=$n endTime=$endTime"
