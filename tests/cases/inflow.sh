#!/bin/bash
# Inflow through the inlet patch with density c_in and no inception: the mass balance
# inflow - outflow = change in the domain closes, the outlet's line adds up to the totals at
# every write, the booked inflow is c_in times the inlet's flux times t within its Poisson
# interval, and in the steady state the mass density M1 equals c_in everywhere (coagulation
# conserves mass; u = 1); also with steps of a third of a cell.
. "$(dirname "$0")/caseLib.sh"
cIn=1e7
endTime=0.6

case=$(newCase constantKernelDuct inflow)
cd "$case"
setEntry . constant/coagulationProperties inception/rate 0
setEntry . constant/coagulationProperties inflow/density $cIn
setEntry . constant/coagulationProperties statisticalWeight/n 2048
setEntry . constant/coagulationProperties sampling/tRelax 0.3
setEntry . system/controlDict endTime $endTime
setEntry . system/controlDict writeInterval $endTime
runApplication coagulationFoam
checkBalance log.coagulationFoam
# The inflow booked over [0, t]: the inlet is the duct's end face, h x h (blockMeshDict's scale
# and h), with U = (u 0 0) on it, so Q = u (scale h)^2; patchBalance.py --inflow checks the
# entering particles against their Poisson mean c_in Q t/W within 4 standard deviations (5 %
# fewer particles are about 10 of them) and their mass against the count times W m_in.
scale=$(foamDictionary -entry scale -value system/blockMeshDict)
h=$(foamDictionary -entry h -value system/blockMeshDict)
uIn=$(foamDictionary -entry boundaryField/inlet/value -value 0/U | tr -d '()' | awk '{print $2}')
mIn=$(foamDictionary -entry inflow/mass -value constant/coagulationProperties)
QT=$(awk -v u="$uIn" -v s="$scale" -v h="$h" -v t="$endTime" 'BEGIN { printf "%.17g", u*(s*h)^2*t }')
"$COAGULATIONFOAM_PYTHON" "$testsDir/../python/patchBalance.py" log.coagulationFoam \
    --csv postProcessing/coagulationBalance/patches.csv --inflow "$cIn" "$QT" "$mIn" \
    || fail "the outlet's line does not add up to the totals, or the booked inflow is off c_in Q t"

$report --case . --out results --no-plots --analytic none > log.report || fail "report failed"
# moments.csv: x, M0_mean, M0_ci95, M1_mean, M1_ci95, ...: every cell's M1 within 4 % of c_in
# (about 4 of a cell's standard deviations, ci95/1.96 ~ 0.9 %)
awk -F, -v c=$cIn 'NR > 1 { e = ($4 - c)/c; if (e < 0) e = -e; if (e > 0.04) { print "cell x=" $1 " M1=" $4; bad++ } }
    END { exit bad > 0 }' results/moments.csv || fail "inflow mass density off c_in = $cIn"
# Pooled over the cells (equal volumes, all downstream of the residence time L/u = 0.2 < tRelax):
# the mass in the duct over its volume, i.e. W m_in times the particles that entered within the
# last residence time, Poisson with mean n_d = c_in (scale h)^2 L / W; the time average over
# the sample window has at most that variance. Within 4 standard deviations c_in/sqrt(n_d).
L=$(foamDictionary -entry L -value system/blockMeshDict)
W=$(grep -o "weight per new particle [^,]*" log.coagulationFoam | head -1 | awk '{print $NF}')
awk -F, -v c=$cIn -v n="$(awk -v c=$cIn -v s="$scale" -v h="$h" -v L="$L" -v W="$W" 'BEGIN { print c*(s*h)^2*s*L/W }')" \
    'NR > 1 { s += $4; k++ }
     END { sd = c/sqrt(n); z = (s/k - c)/sd
           printf "pooled M1 of %d cells: %.6g, c_in %g (relative %.4f, sd %.4f, z = %.2f)\n", k, s/k, c, s/k/c - 1, sd/c, z
           exit !(z <= 4 && z >= -4) }' results/moments.csv || fail "pooled M1 off c_in = $cIn"
# Steps of a third of a cell (Courant number 0.3125): an entering particle's place is its
# point on the face plus the distance it travelled since crossing it, uniform over the step;
# started on the face instead, the particles of a step travel together and sit on a lattice
# 1.25 mm apart, 3 or 4 points in a 4 mm cell, and M1 in the cells alternates by about 25 %.
# No coagulation (kernel none, mass 1): M1 = M0 = c_in in every cell, within 4 % (a cell holds
# about 256 particles, ~75 independent ones over the window: about 0.7 %).
coarse=$(newCase constantKernelDuct inflow_coarseStep)
cd "$coarse"
setEntry . constant/coagulationProperties inception/rate 0
setEntry . constant/coagulationProperties kernel "{ type none; }"
setEntry . constant/coagulationProperties inflow/density $cIn
setEntry . constant/coagulationProperties statisticalWeight/n 2048
setEntry . constant/coagulationProperties sampling/tRelax 0.3
setEntry . system/controlDict deltaT 1.25e-3
setEntry . system/controlDict endTime $endTime
setEntry . system/controlDict writeInterval $endTime
runApplication coagulationFoam
checkBalance log.coagulationFoam
$report --case . --out results --no-plots --analytic none > log.report || fail "report failed (coarse steps)"
awk -F, -v c=$cIn 'NR > 1 { e = ($4 - c)/c; if (e < 0) e = -e; if (e > m) m = e; if (e > 0.04) { print "cell x=" $1 " M1=" $4; bad++ } }
    END { printf "coarse steps: largest |M1/c_in - 1| %.4f\n", m; exit bad > 0 }' results/moments.csv \
    || fail "coarse steps: M1 off c_in = $cIn (the entering particles' places?)"
echo "PASS inflow: balance closed, outlet line = totals, booked inflow = c_in Q t, M1 = c_in within 4 % per cell and pooled within 4 sd; the same per cell with coarse steps"
