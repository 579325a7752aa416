#!/bin/bash
# A run restarted from a written time continues the same random sequence: the
# restarted run's final particles and moments equal the uninterrupted run's. Inception and
# inflow through the inlet both draw random numbers (the cells' and the inlet faces' streams).
# The per-patch totals carried over the restart (0.1/uniform/coagulationPatchBalance) give the
# uninterrupted run's patches.csv at 0.2; the particles leaving have coagulated, so a patch's
# mass, number and particle count differ and each must be read back into its own entry.
. "$(dirname "$0")/caseLib.sh"

full=$(newCase constantKernelDuct restart_full)
cd "$full"
setEntry . constant/coagulationProperties inflow/density 1e7
setEntry . system/controlDict endTime 0.2
setEntry . system/controlDict writeInterval 0.1
runApplication coagulationFoam

split=$(newCase constantKernelDuct restart_split)
cd "$split"
setEntry . constant/coagulationProperties inflow/density 1e7
setEntry . system/controlDict endTime 0.1
setEntry . system/controlDict writeInterval 0.1
runApplication -s first coagulationFoam
setEntry . system/controlDict endTime 0.2
runApplication -s restart coagulationFoam
grep -q "Create mesh for time = 0.1" log.coagulationFoam.restart || fail "did not restart from 0.1"
grep "particles in/incepted/out" log.coagulationFoam.restart | tail -1 | awk '{ exit !($4 > 0) }' \
    || fail "no inflow"

for f in M0 M1 M2 M3 lagrangian/coagulationCloud/mass lagrangian/coagulationCloud/weight \
         lagrangian/coagulationCloud/coordinates
do
    cmp -s "$full/0.2/$f" "$split/0.2/$f" || fail "0.2/$f differs between the full and the restarted run"
done
balance="$COAGULATIONFOAM_PYTHON $testsDir/../python/patchBalance.py"
$balance "$full/log.coagulationFoam" --csv "$full/postProcessing/coagulationBalance/patches.csv" \
    || fail "full run: the outlet's line does not add up to the totals"
$balance "$split/log.coagulationFoam.restart" --start "$split/0.1/uniform/coagulationPatchBalance" \
    --csv "$split/postProcessing/coagulationBalance/patches.csv" \
    || fail "restarted run: the outlet's line less the start's does not add up to the run's totals"
"$COAGULATIONFOAM_PYTHON" - "$full/postProcessing/coagulationBalance/patches.csv" \
    "$split/postProcessing/coagulationBalance/patches.csv" <<'PY' || fail "patches.csv after the restart differs from the full run's"
import csv, sys
rows = [{r["patch"]: r for r in csv.DictReader(open(f)) if r["time"] == "0.2"} for f in sys.argv[1:3]]
assert rows[0] and rows[0].keys() == rows[1].keys(), (rows[0].keys(), rows[1].keys())
for patch, a in rows[0].items():
    b = rows[1][patch]
    assert a["particles"] == b["particles"], (patch, a, b)
    for q in ("number", "mass"):
        assert abs(float(a[q]) - float(b[q])) <= 1e-12 * abs(float(a[q])), (patch, q, a, b)
    n, num, m = float(a["particles"]), float(a["number"]), float(a["mass"])
    print("%s at 0.2: %d particles, number %.6g, mass %.6g (as the full run)" % (patch, n, num, m))
    assert m > 1.2 * num, "the particles leaving have hardly coagulated (mass/number %.3f)" % (m / num)
PY
# With growth and particles shrinking away: the cell step's growth follows the written
# masses exactly (written with all their digits), so a restart changes nothing either
for run in full split; do
    d=$(newCase additiveKernelDuct "restart_growth_$run")
    cd "$d"
    setEntry . constant/coagulationProperties statisticalWeight/n 512
    setEntry . constant/coagulationProperties growth "{ minimumMass 0.9; shrink { type linear; rate -5; } }"
    setEntry . system/controlDict writeInterval 0.04
    if [ $run = full ]; then
        setEntry . system/controlDict endTime 0.08
        runApplication coagulationFoam
    else
        setEntry . system/controlDict endTime 0.04
        runApplication -s first coagulationFoam
        setEntry . system/controlDict endTime 0.08
        runApplication -s restart coagulationFoam
        grep -q "Create mesh for time = 0.04" log.coagulationFoam.restart || fail "growth: did not restart from 0.04"
    fi
done
for f in M0 M1 M2 M3 growthRate lagrangian/coagulationCloud/mass lagrangian/coagulationCloud/weight \
         lagrangian/coagulationCloud/coordinates
do
    cmp -s "$workDir/restart_growth_full/0.08/$f" "$workDir/restart_growth_split/0.08/$f" \
        || fail "growth: 0.08/$f differs between the full and the restarted run"
done
# sources.csv counts from the case's first start: after the restart, the full run's rows
"$COAGULATIONFOAM_PYTHON" - "$workDir/restart_growth_full/postProcessing/coagulationBalance/sources.csv" \
    "$workDir/restart_growth_split/postProcessing/coagulationBalance/sources.csv" <<'PY' \
    || fail "growth: sources.csv after the restart differs from the full run's"
import csv, sys
rows = [{r["source"]: r for r in csv.DictReader(open(f)) if r["time"] == "0.08"} for f in sys.argv[1:3]]
assert sorted(rows[0]) == ["growth", "inception", "inflow", "loss"], rows[0].keys()
for source, a in rows[0].items():
    b = rows[1][source]
    assert a["particles"] == b["particles"], (source, a, b)
    for q in ("number", "mass"):
        assert abs(float(a[q]) - float(b[q])) <= 1e-12 * abs(float(a[q])), (source, q, a, b)
    print("%s at 0.08: %s particles, number %.6g, mass %.6g (as the full run)"
          % (source, a["particles"], float(a["number"]), float(a["mass"])))
assert float(rows[0]["growth"]["mass"]) < 0 and int(rows[0]["loss"]["particles"]) > 0
PY
grep "particles gone by shrinking" "$workDir/restart_growth_full/log.coagulationFoam" | tail -1 \
    | awk '{ exit !($6 > 0) }' || fail "growth: no particle shrank away"
echo "PASS restart with growth: 0.08/M0..M3, growthRate, all particles and sources.csv identical after a restart from 0.04"

n=$(grep -c . "$full/0.2/lagrangian/coagulationCloud/mass" || true)
[ "$n" -gt 0 ] || fail "no particles written"
echo "PASS restart: 0.2/M0..M3, all particles and patches.csv identical after a restart from 0.1 (inception and inflow)"
