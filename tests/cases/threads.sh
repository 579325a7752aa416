#!/bin/bash
# The cell step shares the cells among OpenMP threads, and in a serial run the transport
# step shares the particles, taken from list arrays the cloud keeps across the steps.
# Every cell keeps its own random stream, new particles are constructed serially in cell
# order, and the particles that leave are booked and deleted serially in list order, so
# the results must be identical, bit for bit, on 1 and 2 threads and to the reference
# (OptimisationSwitches coagulationCloudMove 1: OpenFOAM's Cloud::move over the linked
# list): fields, particles, event counts and the balance (SWA; DSA2, which also removes
# particles; SWA with particles shrinking away; inflow through the inlet with outflow through
# the outlet).
. "$(dirname "$0")/caseLib.sh"

# runThreads name tutorial endTime writeInterval [entry value]...: the case on 1 and 2
# threads, and the reference (1 thread, Cloud::move)
runThreads()
{
    local name=$1 tutorial=$2 end=$3 write=$4 run threads d
    shift 4
    for run in ref 1 2; do
        threads=${run/ref/1}
        d=$(newCase "$tutorial" "threads_${name}_$run")
        cd "$d"
        local args=("$@")
        for ((i = 0; i < ${#args[@]}; i += 2)); do
            setEntry . constant/coagulationProperties "${args[i]}" "${args[i + 1]}"
        done
        setEntry . system/controlDict endTime "$end"
        setEntry . system/controlDict writeInterval "$write"
        if [ "$run" = ref ]; then
            foamDictionary -entry OptimisationSwitches -add "{ coagulationCloudMove 1; }" \
                system/controlDict > /dev/null
        fi
        OMP_NUM_THREADS=$threads runApplication coagulationFoam
        grep -q "$threads thread(s) for the cell step" log.coagulationFoam \
            || fail "$name: the log does not report $threads thread(s)"
        checkBalance log.coagulationFoam
    done
}

# sameOnThreads name times...: 1 and 2 threads wrote the reference's fields, particles,
# counts and balance
sameOnThreads()
{
    local name=$1 ref="$workDir/threads_$1_ref" run other t f line a b
    shift
    grep -q "Overriding OptimisationSwitches" "$ref/log.coagulationFoam" \
        || fail "$name: the reference run did not take coagulationCloudMove"
    for run in 1 2; do
        other="$workDir/threads_${name}_$run"
        for t in "$@"; do
            for f in M0 M1 M2 M3 lagrangian/coagulationCloud/mass lagrangian/coagulationCloud/weight \
                     lagrangian/coagulationCloud/coordinates
            do
                [ -s "$ref/$t/$f" ] || fail "$name: $t/$f not written"
                cmp -s "$ref/$t/$f" "$other/$t/$f" \
                    || fail "$name: $t/$f differs between the reference and $run thread(s)"
            done
        done
        for line in "coagulation events  " "particles in/incepted/out" "mass initial + inflow"; do
            a=$(grep "$line" "$ref/log.coagulationFoam" | tail -1)
            b=$(grep "$line" "$other/log.coagulationFoam" | tail -1)
            [ -n "$a" ] || fail "$name: no '$line' in the log"
            [ "$a" = "$b" ] || fail "$name: '$line' differs on $run thread(s): '$a' vs '$b'"
        done
    done
    echo "PASS threads $name: fields, particles, event counts and balance on 1 and 2 threads identical to Cloud::move's"
    grep "particles in/incepted/out" "$ref/log.coagulationFoam" | tail -1
}

for alg in SWA DSA2; do
    runThreads "$alg" additiveKernelDuct 0.08 0.04 algorithm "$alg" statisticalWeight/n 1024
    sameOnThreads "$alg" 0.04 0.08
done

# Growth around the jump process, particles shrinking away below a minimum mass (removed in
# the cell step like DSA's merges)
runThreads growth additiveKernelDuct 0.08 0.04 algorithm SWA statisticalWeight/n 1024 \
    growth "{ minimumMass 0.9; shrink { type linear; rate -5; } }"
sameOnThreads growth 0.04 0.08
gone=$(grep "particles gone by shrinking" "$workDir/threads_growth_2/log.coagulationFoam" | tail -1 | awk '{print $6}')
[ "${gone:-0}" -gt 0 ] || fail "growth: no particle shrank away"

# Inflow only: particles enter through the inlet and leave through the outlet
runThreads inflow constantKernelDuct 0.3 0.3 inception/rate 0 inflow/density 1e7 statisticalWeight/n 512
sameOnThreads inflow 0.3
out=$(grep "particles in/incepted/out" "$workDir/threads_inflow_2/log.coagulationFoam" | tail -1 | awk '{print $NF}')
[ "${out:-0}" -gt 0 ] || fail "inflow: no particle left through the outlet"

# Velocity interpolated to the particle and a random walk: the Couette channel of
# case_channels with cellPoint velocity and constant-D dispersion (rebound walls); the walk's
# steps come from per-particle streams, so the threads and Cloud::move agree bit for bit too
for run in ref 1 2; do
    threads=${run/ref/1}
    d=$(newCase constantKernelDuct "threads_couette_$run")
    cd "$d"
    couetteWalkCase
    if [ "$run" = ref ]; then
        foamDictionary -entry OptimisationSwitches -add "{ coagulationCloudMove 1; }" \
            system/controlDict > /dev/null
    fi
    OMP_NUM_THREADS=$threads runApplication coagulationFoam
    checkBalance log.coagulationFoam
    grep -q "velocity interpolation cellPoint" log.coagulationFoam || fail "couette: cellPoint not selected"
done
sameOnThreads couette 0.05 0.1
