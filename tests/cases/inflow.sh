#!/bin/bash
# Inflow through the inlet patch with density c_in and no inception: the mass balance
# inflow - outflow = change in the domain closes, and in the steady state the mass
# density M1 equals c_in everywhere (coagulation conserves mass; u = 1).
. "$(dirname "$0")/caseLib.sh"
cIn=1e7

case=$(newCase constantKernelDuct inflow)
cd "$case"
setEntry . constant/coagulationProperties inception/rate 0
setEntry . constant/coagulationProperties inflow/density $cIn
setEntry . constant/coagulationProperties statisticalWeight/n 2048
setEntry . constant/coagulationProperties sampling/tRelax 0.3
setEntry . system/controlDict endTime 0.6
setEntry . system/controlDict writeInterval 0.6
runApplication coagulationFoam
checkBalance log.coagulationFoam
grep "particles in/incepted/out" log.coagulationFoam | tail -1 | awk '{ if ($4 <= 0) exit 1 }' \
    || fail "no particles injected"

$report --case . --out results --no-plots --analytic none > log.report || fail "report failed"
# moments.csv: x, M0_mean, M0_ci95, M1_mean, M1_ci95, ...: every cell's M1 within 5 % of c_in
awk -F, -v c=$cIn 'NR > 1 { e = ($4 - c)/c; if (e < 0) e = -e; if (e > 0.05) { print "cell x=" $1 " M1=" $4; bad++ } }
    END { exit bad > 0 }' results/moments.csv || fail "inflow mass density off c_in = $cIn"
echo "PASS inflow: balance closed, M1 = c_in within 5 % in every cell"
