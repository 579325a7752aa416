#!/bin/bash
# The size distribution on the constant-kernel duct: a sizeDistribution cloud
# function with integer bins k = 1..30 at three probes and over a cellZone (the last 5
# cells); its time average matches the exact n_k(t = x/u) of the homogeneous Smoluchowski
# equation with inception (averaged over the probe's cell, the zone's x range) bin by bin
# within the 95 % intervals for correlated samples, its sum (bins, under- and overflow) is
# M0 of the same cells from the moment samples, and the solver's CSV averages are those of
# the samples. The report's plot in diameter (dN/dlog10 d against d) carries the same numbers.
#   psdDuct.sh n endTime
. "$(dirname "$0")/caseLib.sh"
n="${1:-256}"; endTime="${2:-2.0}"

case=$(newCase constantKernelDuct psdDuct)
cd "$case"
# the tail of the duct, x in [0.18, 0.2] (5 cells), as a cellZone
cat > system/topoSetDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object topoSetDict; }
actions
(
    { name tail; type cellZoneSet; action new; source boxToCell; sourceInfo { box (0.18 -1 -1) (1 1 1); } }
);
DICT
runApplication topoSet
setEntry . constant/coagulationProperties statisticalWeight/n "$n"
setEntry . system/controlDict endTime "$endTime"
setEntry . system/controlDict writeInterval "$endTime"
foamDictionary constant/coagulationProperties -entry cloudFunctions -set "{
    psd
    {
        type            sizeDistribution;
        probes          ((0.098 0.002 0.002) (0.146 0.002 0.002) (0.194 0.002 0.002));
        cellZones       (tail);
        bins            { type integer; K 30; }
        timeStart       0.4;
    }
}" > /dev/null
foamDictionary constant/coagulationProperties -entry particles \
    -add "{ density 1000; massUnit 1e-24; }" > /dev/null
runApplication coagulationFoam
checkBalance log.coagulationFoam
grep -q "Size distribution psd: 4 region(s), 30 bins" log.coagulationFoam \
    || fail "the size distribution function was not constructed"

dir="postProcessing/psd/0"
[ -f "$dir/sizeDistribution.h5" ] || fail "no $dir/sizeDistribution.h5"
last=$(foamListTimes -latestTime 2>/dev/null | tail -1)
for f in sizeDistribution.csv derived.csv regions.csv; do
    [ -s "postProcessing/psd/$endTime/$f" ] || [ -s "postProcessing/psd/$last/$f" ] \
        || fail "no $f at the last write time"
done

$report --case . --out results --psd psd --check-psd-bins 1:30 --check-psd-m0 \
    || fail "the time-averaged PSD is off the exact n_k or its sum off M0"
[ -s results/psd/sizeDistribution.png ] || fail "no PSD plot"
# the plot in diameter (the case's particles: 1000 kg/m3, massUnit 1e-24 kg): every probe's
# dN/dlog10 d at the diameter of each size k, with the exact n_k over the bin's width in
# log10 d, (k - 1/2 to k + 1/2)
[ -s results/psd/sizeDistributionDiameter.png ] || fail "no PSD plot in diameter"
"$COAGULATIONFOAM_PYTHON" - <<'PY' || fail "the PSD in diameter is not the exact one's"
import csv, math, sys
exact = {}
for r in csv.DictReader(open("results/sizeDistribution_psd.csv")):
    if r["column"].startswith("n"):
        exact[(r["name"], int(r["column"][1:]))] = (float(r["exact"]), float(r["mean"]))
worst = 0.0
for r in csv.DictReader(open("results/psd/sizeDistributionDiameter.csv")):
    k = int(r["bin"]) + 1
    d = 1e9 * (6 * k * 1e-24 / (math.pi * 1000)) ** (1 / 3)
    dlog = math.log10((k + 0.5) / (k - 0.5)) / 3
    ex, mean = exact[(r["region"], k - 1)]
    worst = max(worst, abs(float(r["d_nm"]) / d - 1), abs(float(r["exact"]) * dlog / ex - 1),
                abs(float(r["dNdlog10d"]) * dlog / mean - 1) if mean > 0 else 0)
print("PSD in diameter: d, dN/dlog10 d and the exact curve match the mass bins to %.1e" % worst)
sys.exit(0 if worst < 1e-8 else 1)
PY
echo "PASS PSD on the constant duct n=$n endTime=$endTime"
