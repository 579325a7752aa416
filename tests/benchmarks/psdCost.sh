#!/bin/bash
# The cost of a probe size distribution: the additive-kernel duct (tutorial,
# n and endTime as given, one thread), run alternately without and with a sizeDistribution
# function (three probes, 60 log bins from 1 to 1e6), PAIRS times; prints the wall time of
# each run, the mean relative cost and the bytes the function writes.
#   psdCost.sh [n=2048] [endTime=0.4] [pairs=3] [workDir]
. "$(dirname "$0")/../cases/caseLib.sh"
n="${1:-2048}"; endTime="${2:-0.4}"; pairs="${3:-3}"
[ -n "${4:-}" ] && workDir="$4"
export OMP_NUM_THREADS=1

base=$(newCase additiveKernelDuct psdCost_base)
setEntry "$base" constant/coagulationProperties statisticalWeight/n "$n"
setEntry "$base" system/controlDict endTime "$endTime"

run()   # run name withPsd: prints the wall time (s)
{
    local c="$workDir/psdCost_$1"
    rm -rf "$c"; cp -r "$base" "$c"
    if [ "$2" = 1 ]; then
        foamDictionary "$c/constant/coagulationProperties" -entry cloudFunctions -set "{
            psd
            {
                type        sizeDistribution;
                probes      ((0.031 0.001 0.001) (0.061 0.001 0.001) (0.099 0.001 0.001));
                bins        { type log; min 1; max 1e6; nBins 60; }
                timeStart   0.2;
                density     1000;
                massUnit    1e-24;
            }
        }" > /dev/null
    fi
    local t0 t1
    t0=$(date +%s.%N)
    coagulationFoam -case "$c" > "$c/log.coagulationFoam" 2>&1 || fail "run $1 failed"
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f\n", b - a }'
}

without=(); with=()
for i in $(seq 1 "$pairs"); do
    without+=("$(run "without$i" 0)")
    with+=("$(run "with$i" 1)")
    echo "pair $i: without ${without[-1]} s, with ${with[-1]} s"
done
c="$workDir/psdCost_with1"
bytes=$(du -sb "$c/postProcessing/psd" | awk '{print $1}')
echo "bytes written by the function (postProcessing/psd): $bytes"
ls -l "$c"/postProcessing/psd/*/
for i in $(seq 1 "$pairs"); do
    grep "wall time in the function" "$workDir/psdCost_with$i/log.coagulationFoam" \
        | sed "s/^/with$i: /"
done
echo "${without[*]}" "|" "${with[*]}" | awk -F'|' '{
    n = split($1, a, " "); split($2, b, " ");
    sa = 0; sb = 0; for (i = 1; i <= n; ++i) { sa += a[i]; sb += b[i]; r[i] = b[i]/a[i] - 1 }
    printf "mean wall time: without %.2f s, with %.2f s: cost %+.2f %%;", sa/n, sb/n, 100*(sb/sa - 1)
    printf " per pair:"; for (i = 1; i <= n; ++i) printf " %+.2f %%", 100*r[i]; printf "\n" }'
