#!/bin/bash
# Every required entry of constant/coagulationProperties, missing or wrong, stops the
# solver with an OpenFOAM FatalIOError that names the entry (no crash, no default).
. "$(dirname "$0")/caseLib.sh"

base=$(newCase constantKernelDuct badInput_base)
passed=0

# expectFatal name expectedText foamDictionaryArgs...
expectFatal()
{
    local name="$1" expected="$2"; shift 2
    local case="$workDir/badInput_$name"
    rm -rf "$case"; cp -r "$base" "$case"
    (cd "$case" && foamDictionary constant/coagulationProperties "$@" > /dev/null)
    if coagulationFoam -case "$case" > "$case/log" 2>&1; then
        fail "$name: coagulationFoam accepted bad input"
    fi
    grep -q "FOAM FATAL IO ERROR" "$case/log" || { tail -20 "$case/log"; fail "$name: no FatalIOError"; }
    grep -q -- "$expected" "$case/log" || { tail -20 "$case/log"; fail "$name: error does not name '$expected'"; }
    grep -q "coagulationProperties" "$case/log" || fail "$name: error does not name the file"
    passed=$((passed + 1))
    echo "ok $name"
}

expectFatal missingAlgorithm   "algorithm"        -entry algorithm -remove
expectFatal unknownAlgorithm   "DSA3"             -entry algorithm -set DSA3
expectFatal missingKernel      "kernel"           -entry kernel -remove
expectFatal unknownKernel      "quadratic"        -entry kernel/type -set quadratic
expectFatal missingK0          "K0"               -entry kernel/K0 -remove
expectFatal negativeK0         "K0"               -entry kernel/K0 -set -1
expectFatal negativeRate       "rate"             -entry inception/rate -set -3e8
expectFatal missingRate        "rate"             -entry inception/rate -remove
expectFatal zeroMass           "mass"             -entry inception/mass -set 0
expectFatal unknownZone        "flame"            -entry inception/cellZone -set flame
expectFatal missingPatch       "nozzle"           -entry inflow/patches -set "(nozzle)"
expectFatal negativeDensity    "density"          -entry inflow/density -set -1
expectFatal missingN           "'n'"              -entry statisticalWeight/n -remove
expectFatal zeroV1             "SWA"              -entry statisticalWeight/V1/SWA -set 0
expectFatal missingSeed        "seed"             -entry seed -remove
expectFatal negativeSeed       "seed"             -entry seed -set -5
expectFatal missingSampling    "sampling"         -entry sampling -remove
expectFatal badSampleInterval  "sampleInterval"   -entry sampling/sampleInterval -set 1.5e-4
(cd "$base" && foamDictionary constant/coagulationProperties -entry algorithm -set DSA1 > /dev/null)
expectFatal dsaNumberControl   "maxParticlesPerCell" -entry numberControl -set "{ maxParticlesPerCell 100; }"

echo "PASS bad input: $passed cases give a FatalIOError naming the entry"
