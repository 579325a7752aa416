#!/bin/bash
# The cell step shares the cells among OpenMP threads; every cell keeps its own random
# stream and the new particles are constructed serially in cell order, so the results
# must be identical, bit for bit, whatever the thread count (SWA, and DSA2, which also
# removes particles).
. "$(dirname "$0")/caseLib.sh"

for alg in SWA DSA2; do
    for threads in 1 2; do
        d=$(newCase additiveKernelDuct "threads_${alg}_$threads")
        cd "$d"
        setEntry . constant/coagulationProperties algorithm "$alg"
        setEntry . constant/coagulationProperties statisticalWeight/n 1024
        setEntry . system/controlDict endTime 0.08
        setEntry . system/controlDict writeInterval 0.04
        OMP_NUM_THREADS=$threads runApplication coagulationFoam
        grep -q "$threads thread(s) for the cell step" log.coagulationFoam \
            || fail "$alg: the log does not report $threads thread(s)"
        checkBalance log.coagulationFoam
    done
    one="$workDir/threads_${alg}_1" two="$workDir/threads_${alg}_2"
    for t in 0.04 0.08; do
        for f in M0 M1 M2 M3 lagrangian/coagulationCloud/mass lagrangian/coagulationCloud/weight \
                 lagrangian/coagulationCloud/coordinates
        do
            [ -s "$one/$t/$f" ] || fail "$alg: $t/$f not written"
            cmp -s "$one/$t/$f" "$two/$t/$f" || fail "$alg: $t/$f differs between 1 and 2 threads"
        done
    done
    c1=$(grep "coagulation events  " "$one/log.coagulationFoam" | tail -1)
    c2=$(grep "coagulation events  " "$two/log.coagulationFoam" | tail -1)
    [ "$c1" = "$c2" ] || fail "$alg: event counts differ: '$c1' vs '$c2'"
    echo "PASS threads $alg: fields, particles and event counts identical on 1 and 2 threads ($c1)"
done
