#!/bin/bash
# decomposePar + mpirun -np 2: particles cross the processor boundary, the mass balance
# closes, and the time-averaged moments agree with the analytic solution as in serial.
. "$(dirname "$0")/caseLib.sh"

# compareMoments a.csv b.csv: two independent runs' time-averaged moments (coagulationReport's
# moments.csv) agree within their statistical error in every cell and moment: |difference|
# < 4 standard errors of the difference (each run's ci95 allows for the time correlation);
# prints the largest |z| per moment
compareMoments()
{
    "$COAGULATIONFOAM_PYTHON" - "$1" "$2" <<'PY'
import sys, numpy as np
p = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
s = np.genfromtxt(sys.argv[2], delimiter=",", names=True)
assert np.allclose(p["x"], s["x"]), "different cells"
worst = 0.0
for k in range(4):
    d = p[f"M{k}_mean"] - s[f"M{k}_mean"]
    se = np.hypot(p[f"M{k}_ci95"], s[f"M{k}_ci95"]) / 1.96
    z = np.abs(d[1:]) / se[1:]          # the first cell's M2, M3 can have zero variance
    worst = max(worst, z.max())
    print(f"M{k}: largest |parallel - serial| = {z.max():.2f} standard errors")
sys.exit(0 if worst < 4 else 1)
PY
}

case=$(newCase constantKernelDuct parallel)
cd "$case"
setEntry . constant/coagulationProperties statisticalWeight/n 1024
setEntry . system/controlDict endTime 0.7
setEntry . system/controlDict writeInterval 0.7
runApplication decomposePar
runParallel -np 2 coagulationFoam
checkBalance log.coagulationFoam
ls postProcessing/coagulationSamples/*processor1.h5 > /dev/null || fail "no per-processor samples"
$report --case . --out results --no-plots --check --check-rel-tol 0.08 --check-skip-cells 3 \
    || fail "parallel moments off the analytic solution"
runApplication reconstructPar -latestTime
[ -f 0.7/M1 ] || fail "reconstructPar wrote no 0.7/M1"

# The same case in serial: the two runs' time averages agree within their statistical
# error in every cell and moment (|difference| < 4 standard errors of the difference)
serial=$(newCase constantKernelDuct parallel_serial)
cp constant/coagulationProperties "$serial/constant/coagulationProperties"
cp system/controlDict "$serial/system/controlDict"
cd "$serial"
setEntry . constant/coagulationProperties seed 2     # an independent realisation
runApplication coagulationFoam
$report --case . --out results --no-plots > log.report || fail "serial report failed"
compareMoments "$case/results/moments.csv" "$serial/results/moments.csv" \
    || fail "parallel and serial moments differ"
echo "PASS parallel run on 2 processors: balance closed, consistent with the analytic and the serial run"

# The same case dealt to the 2 ranks as 6 alternating runs of cells of unequal length
# (method manual, a hand-written cellDecomposition): 5 processor faces along the duct, so
# every particle crosses between the ranks up to 5 times and both ranks send (with simple's
# one cut and the flow along +x only processor0 does). Its time averages agree with the
# serial run's as the simple decomposition's do.
runs=$(newCase constantKernelDuct parallel_runs)
cp "$case/constant/coagulationProperties" "$runs/constant/coagulationProperties"
cp "$case/system/controlDict" "$runs/system/controlDict"
cd "$runs"
nCells=$(grep "nCells:" log.blockMesh | awk '{print $2}')
[ "$nCells" = 50 ] || fail "runs: the duct has $nCells cells, the runs below deal 50"
{
    echo 'FoamFile { version 2.0; format ascii; class labelList; location "constant"; object cellDecomposition; }'
    echo "$nCells"
    echo "("
    # cells along x (blockMesh numbers them so): runs of 7, 12, 5, 10, 9, 7 cells
    for run in "0 7" "1 12" "0 5" "1 10" "0 9" "1 7"; do
        read -r rank length <<< "$run"
        for ((i = 0; i < length; ++i)); do echo "$rank"; done
    done
    echo ")"
} > constant/cellDecomposition
foamDictionary -entry method -set manual system/decomposeParDict > /dev/null
foamDictionary -entry coeffs -set '{ dataFile "cellDecomposition"; }' system/decomposeParDict > /dev/null
runApplication decomposePar
procFaces=$(grep "^Number of processor faces = " log.decomposePar | awk '{print $NF}')
[ "$procFaces" = 5 ] || fail "runs: decomposePar made ${procFaces:-no} processor faces, 5 expected"
runParallel -np 2 coagulationFoam
checkBalance log.coagulationFoam
$report --case . --out results --no-plots > log.report || fail "runs: report failed"
read -r sent0 sent1 <<< "$(grep -E "^ +processor[01]: " log.coagulationFoam | tail -2 | awk '{print $7}' | tr '\n' ' ')"
awk -v a="${sent0:-0}" -v b="${sent1:-0}" 'BEGIN { exit !(a > 0 && b > 0) }' \
    || fail "runs: particles sent per step $sent0 (processor0), $sent1 (processor1): both should send"
zRuns=$(compareMoments "$runs/results/moments.csv" "$serial/results/moments.csv") \
    || { echo "$zRuns"; fail "runs: decomposed and serial moments differ"; }
echo "$zRuns"
echo "PASS 6 alternating runs of cells on 2 ranks ($procFaces processor faces; particles sent per step" \
     "$sent0 by processor0, $sent1 by processor1): balance closed, largest |z| against serial" \
     "$(echo "$zRuns" | awk '{printf "%s%s %s", (NR > 1 ? ", " : ""), $1, $(NF-2)}')"

# The array transport in a decomposed run hands the particles that reach a
# processor patch over in bulk and appends what arrives, so its list is the one Cloud::move
# leaves: on 2 ranks both paths give the same particles and counts bit for bit. The Couette
# channel of case_channels (cellPoint velocity, constant-D walk, rebound walls) decomposed
# across the flow, so that the advection and the walk both cross the processor patch.
for path in array cloudMove; do
    d=$(newCase constantKernelDuct "parallel_couette_$path")
    cd "$d"
    couetteWalkCase
    if [ "$path" = cloudMove ]; then
        foamDictionary -entry OptimisationSwitches -add "{ coagulationCloudMove 1; }" \
            system/controlDict > /dev/null
    fi
    runApplication decomposePar
    runParallel -np 2 coagulationFoam
    checkBalance log.coagulationFoam
done
a="$workDir/parallel_couette_array"; b="$workDir/parallel_couette_cloudMove"
grep -q "Overriding OptimisationSwitches" "$b/log.coagulationFoam" \
    || fail "couette: the Cloud::move run did not take coagulationCloudMove"
for p in processor0 processor1; do
    for t in 0.05 0.1; do
        for f in M0 M3 lagrangian/coagulationCloud/mass lagrangian/coagulationCloud/weight \
                 lagrangian/coagulationCloud/coordinates; do
            [ -s "$a/$p/$t/$f" ] || fail "couette: $p/$t/$f not written"
            cmp -s "$a/$p/$t/$f" "$b/$p/$t/$f" \
                || fail "couette: $p/$t/$f differs between the array path and Cloud::move"
        done
    done
done
for line in "coagulation events  " "particles in/incepted/out" "mass initial + inflow"; do
    [ "$(grep "$line" "$a/log.coagulationFoam" | tail -1)" = "$(grep "$line" "$b/log.coagulationFoam" | tail -1)" ] \
        || fail "couette: '$line' differs between the array path and Cloud::move"
done
sent=$(grep "processor0: " "$a/log.coagulationFoam" | tail -1 | awk '{print $7}')
awk -v s="${sent:-0}" 'BEGIN { exit !(s > 0) }' || fail "couette: no particle crossed the processor patch"
echo "PASS array transport on 2 ranks: particles and counts identical to Cloud::move's ($sent sent per step by processor0)"

# A serial start that goes on decomposed (restart from a complete time), the decomposition
# weighted by the work per cell (cellWork -> decomposeParDict weightField): on the duct the
# work grows downstream, so equal cell counts (simple) leave one rank with most of it, the
# weighted decomposition does not. The balance is of counts (particles and events), so the
# same on every run with these seeds.
start=$(newCase constantKernelDuct parallel_work_start)
cd "$start"
setEntry . constant/coagulationProperties statisticalWeight/n 1024
foamDictionary -entry cloudFunctions -add "{ work { type cellWork; } }" \
    constant/coagulationProperties > /dev/null
setEntry . system/controlDict endTime 0.3
setEntry . system/controlDict writeInterval 0.15
runApplication coagulationFoam
[ -s 0.3/coagulationWork ] || fail "no 0.3/coagulationWork"
# cellWork's cost fit (coag::CostFit over the timed cells): a line at each of the 2 writes,
# eventCost and its error finite numbers (the value itself follows the machine's load: on a
# clean clone under ctest -j2 one interval gave -0.39 +- 0.45, the other 0.74 +- 0.07)
fits=$(grep -c "^Cloud function cellWork: \(no \)\?cost fit" log.coagulationFoam || true)
[ "$fits" = 2 ] || fail "cellWork printed $fits cost fit lines, 2 writes"
grep "^    eventCost = " log.coagulationFoam | awk '
    { n++; if ($3 !~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/ || $5 !~ /^[0-9.]+(e[-+]?[0-9]+)?$/) bad++ }
    END { exit !(n > 0 && bad == 0) }' \
    || fail "cellWork's cost fit: no eventCost, or one that is not a finite number"
echo "cellWork's cost fit on the serial start: $(grep "^    eventCost = " log.coagulationFoam | awk '{printf "%s%s +- %s", (NR > 1 ? ", " : ""), $3, $5}')"
for method in simple weighted; do
    d="$workDir/parallel_work_$method"
    rm -rf "$d"; cp -r "$start" "$d"; cd "$d"
    rm log.coagulationFoam
    if [ "$method" = weighted ]; then
        foamDictionary -entry method -set hierarchical system/decomposeParDict > /dev/null
        foamDictionary -entry weightField -add coagulationWork system/decomposeParDict > /dev/null
    fi
    runApplication decomposePar -latestTime
    setEntry . system/controlDict endTime 0.35
    setEntry . system/controlDict writeInterval 0.05
    runParallel -np 2 coagulationFoam
    checkBalance log.coagulationFoam
    grep "work balance" log.coagulationFoam | tail -1 | awk '{print $NF}' > balance
    echo "$method: cells $(grep "Number of cells = " log.decomposePar | awk '{print $NF}' | tr '\n' ' ')work balance $(cat balance)"
done
bs=$(cat "$workDir/parallel_work_simple/balance"); bw=$(cat "$workDir/parallel_work_weighted/balance")
awk -v s="$bs" -v w="$bw" 'BEGIN { exit !(s > 1.3 && w < 1.1) }' \
    || fail "work balance (max/mean over ranks): simple $bs (expected > 1.3), weighted $bw (expected < 1.1)"
echo "PASS weighted decomposition from a serial start: work balance $bw against $bs with equal cell counts"

# workDecomposition (method manual): the smallest largest share of the same weights, never
# above that of OpenFOAM's weighted hierarchical (which the utility runs and prints first),
# and decomposePar takes its cellDecomposition; an unknown
# keyword in its coefficients is a fatal error naming the entry
d="$workDir/parallel_work_manual"
rm -rf "$d"; cp -r "$start" "$d"; cd "$d"
cat > system/decomposeParDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method manual;
coeffs { dataFile "cellDecomposition"; }
workDecompositionCoeffs { n (2 1 1); }
DICT
runApplication workDecomposition -latestTime
balances=$(grep "work balance" log.workDecomposition | awk '{print $NF}' | tr '\n' ' ')
read -r hierarchical optimal <<< "$balances"
awk -v c="$hierarchical" -v o="$optimal" 'BEGIN { exit !(o > 0 && o <= c * (1 + 1e-12)) }' \
    || fail "workDecomposition: balance $optimal above weighted hierarchical's $hierarchical"
runApplication decomposePar -latestTime
cells=$(grep "Number of cells = " log.decomposePar | awk '{print $NF}' | tr '\n' ' ')
foamDictionary -entry workDecompositionCoeffs/nn -add 2 system/decomposeParDict > /dev/null
workDecomposition -latestTime > log.bad 2>&1 && fail "workDecomposition took an unknown keyword"
grep -q "Unknown keyword 'nn'" log.bad || fail "workDecomposition: no error naming the keyword"
echo "PASS workDecomposition: cells $cells work balance $optimal (weighted hierarchical $hierarchical)"

# runsPerPart 3: up to 6 runs of cells dealt to the 2 ranks, never above the cut's balance,
# every cell on a rank (decomposePar's counts add up); runsPerPart 0 is refused by name
foamDictionary -entry workDecompositionCoeffs/nn -remove system/decomposeParDict > /dev/null
foamDictionary -entry workDecompositionCoeffs/runsPerPart -add 3 system/decomposeParDict > /dev/null
workDecomposition -latestTime > log.workDecomposition.runs 2>&1 \
    || { tail log.workDecomposition.runs; fail "workDecomposition with runsPerPart 3 failed"; }
dealt=$(grep "work balance" log.workDecomposition.runs | tail -1 | awk '{print $NF}')
awk -v r="$dealt" -v o="$optimal" 'BEGIN { exit !(r > 0 && r <= o * (1 + 1e-12)) }' \
    || fail "workDecomposition runsPerPart 3: balance $dealt above the cut's $optimal"
decomposePar -latestTime -force > log.decomposePar.runs 2>&1 \
    || { tail log.decomposePar.runs; fail "decomposePar refused the dealt runs"; }
total=$(grep "Number of cells = " log.decomposePar.runs | awk '{s += $NF} END {print s}')
meshCells=$(grep "^    processor" log.workDecomposition.runs | head -2 | awk '{gsub(",", "", $3); s += $3} END {print s}')
[ "$total" = "$meshCells" ] && [ "$total" -gt 0 ] \
    || fail "decomposePar after runsPerPart 3: $total cells on the ranks, $meshCells in the mesh"
foamDictionary -entry workDecompositionCoeffs/runsPerPart -set 0 system/decomposeParDict > /dev/null
workDecomposition -latestTime > log.bad 2>&1 && fail "workDecomposition took runsPerPart 0"
grep -q "Entry 'runsPerPart' 0" log.bad || fail "workDecomposition: no error naming runsPerPart"
echo "PASS workDecomposition runsPerPart 3: balance $dealt (cut $optimal), $(grep 'processor boundary faces' log.workDecomposition.runs | tail -1 | awk '{print $NF}') processor boundary faces"
