#!/bin/bash
# The size distribution on the constant-kernel duct: a sizeDistribution cloud
# function with integer bins k = 1..30 at three probes and over a cellZone (the last 5
# cells); its time average matches the exact n_k(t = x/u) of the homogeneous Smoluchowski
# equation with inception (averaged over the probe's cell, the zone's x range) bin by bin
# within the 95 % intervals for correlated samples, its sum (bins, under- and overflow) is
# M0 of the same cells from the moment samples, and the solver's CSV averages are those of
# the samples.
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
echo "PASS PSD on the constant duct n=$n endTime=$endTime"
