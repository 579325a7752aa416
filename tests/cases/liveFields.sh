#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# The submodels' cell fields as they change in time: a closed box (the constant-kernel
# duct's mesh, no flow, no inflow) whose inception rate, the field T of scalarTransportFoam,
# grows as r0 + b t by an fvOptions source, so that M0..M2 are the solutions of the closed
# moment equations with that rate (rampBox.py):
#  1. the coagulationCloud function object inside scalarTransportFoam takes the solver's T at
#     every step (linear over the split step): the exact moments within intervals; the
#     solver's write times are the only time folders, each marked complete;
#  2. coagulationFoam, which reads T once from the start time (frozen), misses the ramp: the
#     same check fails;
#  3. coagulationFoam on the written times of run 1 (transport flowSeries) reads T from
#     them, linear in time: the exact moments;
#  4. a field the solver does not register (the function object) and a flow series with a
#     time that lacks T are FatalIOErrors naming the field and the folder; a field registered
#     by readFields is written with the cloud's times, so that a restart finds it;
#  5. kernels (localSaffmanTurner's epsilon, the Brownian kernel's T in a sum) and 6. the
#     turbulent walk's nut on fields that grow in time in a flow series, against the runs at
#     their time means (time rescaling).
. "$(dirname "$0")/caseLib.sh"
. "$(dirname "$0")/functionObjectCases.sh"
r0=3e8
b=6e9
check() { PYTHONPATH="$COAGULATIONFOAM_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}" \
    "$COAGULATIONFOAM_PYTHON" "$testsDir/rampBox.py" "$1" "$r0" "${2:-$b}" "${3:-012}"; }

# rampCase dir: the closed box with inception from the field T, 0 <= t <= 0.1
rampCase()
{
    local c
    c=$(newCase constantKernelDuct "$1")
    sed -i 's/uniform (1 0 0)/uniform (0 0 0)/g' "$c/0/U"
    cat > "$c/0/T" <<DICT
FoamFile { version 2.0; format ascii; class volScalarField; object T; }
dimensions      [0 -3 -1 0 0 0 0];
internalField   uniform $r0;
boundaryField
{
    inlet { type zeroGradient; }
    outlet { type zeroGradient; }
    sides { type empty; }
}
DICT
    cat > "$c/constant/transportProperties" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
DT 0;
DICT
    cat > "$c/system/fvOptions" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object fvOptions; }
ramp
{
    type            scalarSemiImplicitSource;
    selectionMode   all;
    volumeMode      specific;
    injectionRateSuSp { T ($b 0); }
}
DICT
    scalarTransportSchemes "$c" 1e-14
    foamDictionary -case "$c" "$c/constant/coagulationProperties" -entry inflow -remove > /dev/null
    setEntry "$c" constant/coagulationProperties inception "{ type field; field T; mass 1; }"
    setEntry "$c" constant/coagulationProperties sampling "{ tRelax 0; sampleInterval 5e-3; }"
    setEntry "$c" constant/coagulationProperties splitting Strang
    setEntry "$c" system/controlDict deltaT 1e-3
    setEntry "$c" system/controlDict endTime 0.1
    setEntry "$c" system/controlDict writeInterval 0.01
    setEntry "$c" system/controlDict writeFormat ascii
    foamDictionary -case "$c" "$c/system/controlDict" -entry functions/momentAverages \
        -remove > /dev/null
    echo "$c"
}

# fo case: the function object in the case's controlDict, run by scalarTransportFoam
fo()
{
    setEntry "$1" system/controlDict application scalarTransportFoam
    foamDictionary -case "$1" "$1/system/controlDict" -entry functions/particles \
        -add "{ type coagulationCloud; libs (coagulationModels); ${2:-} }" > /dev/null
}

# 1. The function object: the solver's T at every step
live=$(rampCase fo_rampLive)
frozen=$(rampCase fo_rampFrozen)
fo "$live"
(cd "$live" && runApplication scalarTransportFoam) || fail "scalarTransportFoam"
checkBalance "$live/log.scalarTransportFoam"
awk '/^internalField/ { on = 1; next } on == 1 && /^\(/ { on = 2; next }
     on == 2 && /^\)/ { exit !(n == 50) }
     on == 2 { n++; if ($1 < 8.99999e8 || $1 > 9.00001e8) exit 1 }' \
    "$live/0.1/T" || fail "T at 0.1 is not r0 + b t = 9e8 in the 50 cells"
# the solver's write times only, each marked complete by the cloud
times=$(cd "$live" && foamListTimes -withZero | tr '\n' ' ')
[ "$times" = "0 0.01 0.02 0.03 0.04 0.05 0.06 0.07 0.08 0.09 0.1 " ] \
    || fail "time folders other than the write times: $times"
for t in $times; do
    [ "$t" = 0 ] || [ -f "$live/$t/uniform/coagulationCloudComplete" ] \
        || fail "no completion marker in $live/$t"
done
check "$live" || fail "the function object's moments with the solver's T are not the exact ones"
echo "ok: the function object follows the solver's T (the inception rate) step by step"

# 1b. Five steps of 0.02: M1 = int r dt is exact only with the rate of the step's middle,
#     (T_old + T_new)/2; the solver's T at the end of the step gives M1 10 to 17 % high.
#     The same in split steps of two time steps of 0.01 (executeInterval 2): the rate of
#     the split step's middle, between the values at its start and its end
for interval in 1 2; do
    coarse=$(rampCase "fo_rampCoarse$interval")
    fo "$coarse" "executeInterval $interval;"
    setEntry "$coarse" system/controlDict deltaT "$(awk -v n="$interval" 'BEGIN { print 0.02/n }')"
    setEntry "$coarse" system/controlDict writeInterval 0.02
    setEntry "$coarse" constant/coagulationProperties sampling "{ tRelax 0; sampleInterval 0.02; }"
    (cd "$coarse" && runApplication scalarTransportFoam) || fail "scalarTransportFoam (split step 0.02)"
    check "$coarse" "$b" 1 \
        || fail "M1 with split steps of 0.02 is not int r dt: the rate not at the step's middle"
done
echo "ok: the rate at the middle of each split step (M1 exact with split steps of 0.02, 1 and 2 time steps each)"

# 2. Frozen: T read once, the ramp missed (the check must fail)
(cd "$frozen" && runApplication coagulationFoam) || fail "coagulationFoam (frozen)"
set +e
check "$frozen"
rc=$?
set -e
[ "$rc" = 3 ] || fail "the frozen rate passed the ramp's check (exit $rc)"
echo "ok: with T frozen at the start the ramp's check fails, as it must"

# 3. coagulationFoam on the function object run's written times (T not in its own 0/)
series=$(rampCase fo_rampSeries)
rm "$series/0/T"
foamDictionary -case "$series" "$series/constant/coagulationProperties" -entry transport \
    -add "{ type frozenFlow; flowSeries \"../fo_rampLive\"; }" > /dev/null
(cd "$series" && runApplication coagulationFoam) || fail "coagulationFoam (flow series)"
checkBalance "$series/log.coagulationFoam"
check "$series" || fail "the moments with T of the flow series are not the exact ones"
echo "ok: coagulationFoam reads T from the flow series' written times"

# 4. Bad input
bad=$(rampCase fo_rampUnregistered)
fo "$bad"
setEntry "$bad" constant/coagulationProperties inception/field rate
(cd "$bad" && scalarTransportFoam > log.scalarTransportFoam 2>&1) \
    && fail "a field the solver does not register was accepted"
grep -q "reads the field 'rate' (entry 'field'), which the flow solver does not register" \
    "$bad/log.scalarTransportFoam" || fail "no FatalIOError naming the unregistered field"
grep -q "FOAM FATAL IO ERROR" "$bad/log.scalarTransportFoam" || fail "not a FatalIOError"
echo "ok: a field the solver does not register: FatalIOError naming it"
# registered from the time folders by readFields (listed first), the run goes, at rate r0
sed -e 's/object T;/object rate;/' "$bad/0/T" > "$bad/0/rate"
foamDictionary -case "$bad" "$bad/system/controlDict" -entry functions/particles -remove > /dev/null
foamDictionary -case "$bad" "$bad/system/controlDict" -entry functions/rate \
    -add "{ type readFields; libs (fieldFunctionObjects); fields (rate); }" > /dev/null
fo "$bad"
rm "$bad/log.scalarTransportFoam"
(cd "$bad" && runApplication scalarTransportFoam) || fail "scalarTransportFoam with readFields"
check "$bad" 0 || fail "the rate field registered by readFields does not give its rate"
echo "ok: a field registered by readFields (constant rate r0): the exact moments"
# ... written with the cloud's times: a restart from 0.05 finds it there and continues the
#     run bit for bit; a start time without the file is named as what is missing
[ -f "$bad/0.05/rate" ] || fail "the field registered by readFields is not written with 0.05"
rst="$workDir/fo_rampReadFieldsRestart"
rm -rf "$rst"; cp -r "$bad" "$rst"
(cd "$rst" && foamListTimes -rm -time '0.06:' > /dev/null && rm -rf postProcessing log.*)
setEntry "$rst" system/controlDict startFrom latestTime
(cd "$rst" && runApplication scalarTransportFoam) || fail "the restart with readFields from 0.05"
grep -q "Create mesh for time = 0.05" "$rst/log.scalarTransportFoam" || fail "did not restart from 0.05"
for f in "$bad"/0.1/lagrangian/coagulationCloud/* "$bad"/0.1/M0 "$bad"/0.1/M1; do
    cmp -s "$f" "$rst/0.1/${f#"$bad/0.1/"}" || fail "the restart from 0.05: $f differs"
done
(cd "$rst" && foamListTimes -rm -time '0.06:' > /dev/null && rm "0.05/rate" log.*)
(cd "$rst" && scalarTransportFoam > log.scalarTransportFoam 2>&1) \
    && fail "a restart without the readFields field was accepted"
grep -q "The start time 0.05 has no file rate" "$rst/log.scalarTransportFoam" \
    || { tail -20 "$rst/log.scalarTransportFoam"; fail "the error does not name the missing file"; }
echo "ok: the readFields field written with the times: a restart from 0.05 bit for bit; without it, named"

gap=$(rampCase fo_rampGap)
rm "$gap/0/T"
rm -rf "$workDir/fo_rampLiveGap"
cp -r "$live" "$workDir/fo_rampLiveGap"
rm "$workDir/fo_rampLiveGap/0.05/T"
foamDictionary -case "$gap" "$gap/constant/coagulationProperties" -entry transport \
    -add "{ type frozenFlow; flowSeries \"../fo_rampLiveGap\"; }" > /dev/null
(cd "$gap" && coagulationFoam > log.coagulationFoam 2>&1) \
    && fail "a flow series with a gap in T was accepted"
grep -q "fo_rampLiveGap/0.05\" has no T (read by the inception model .field.): the series has a gap" \
    "$gap/log.coagulationFoam" \
    || fail "no FatalIOError naming the time without T"
echo "ok: a flow series whose time 0.05 lacks T: FatalIOError naming the folder"

# 5. A kernel of a field that changes in time: localSaffmanTurner in a closed box of
#    monomers, epsilon(t) = eps0 (1 + 2t/tau) written by this script as a flow series
#    (U = 0). The kernel is c(t) K, c = sqrt(epsilon/nu), so the run at T is the run with c
#    held at its mean over [0, T], (int c dt)/T (time rescaled): the same moments within
#    intervals; the run held at eps0 (the start's, frozen) differs
eps0=1
tau=0.05
stCase()
{
    local c
    c=$(newCase constantKernelDuct "$1")
    sed -i 's/uniform (1 0 0)/uniform (0 0 0)/g' "$c/0/U"
    foamDictionary -case "$c" "$c/constant/coagulationProperties" -entry inflow -remove > /dev/null
    setEntry "$c" constant/coagulationProperties inception "{ rate 0; mass 1; }"
    setEntry "$c" constant/coagulationProperties kernel \
        "{ type localSaffmanTurner; coefficient 6e-11; epsilon epsilon; nu 1e-5; }"
    foamDictionary -case "$c" "$c/constant/coagulationProperties" -entry initialPopulation \
        -add "{ numberDensity 1.25e8; mass 1; }" > /dev/null
    setEntry "$c" constant/coagulationProperties sampling "{ tRelax 0; sampleInterval 0.01; }"
    foamDictionary -case "$c" "$c/constant/coagulationProperties" -entry transport \
        -add "{ type frozenFlow; }" > /dev/null
    setEntry "$c" system/controlDict deltaT 1e-3
    setEntry "$c" system/controlDict endTime 0.1
    setEntry "$c" system/controlDict writeInterval 0.1
    foamDictionary -case "$c" "$c/system/controlDict" -entry functions/momentAverages \
        -remove > /dev/null
    echo "$c"
}
# scalarFile case time name dimensions value
scalarFile()
{
    mkdir -p "$1/$2"
    cat > "$1/$2/$3" <<DICT
FoamFile { version 2.0; format ascii; class volScalarField; object $3; }
dimensions      $4;
internalField   uniform $5;
boundaryField { inlet { type zeroGradient; } outlet { type zeroGradient; } sides { type empty; } }
DICT
}

# seriesStudy name field dimensions start mean makeCase [spread]: name_varying (made by
# makeCase) on the flow series name_flow (U = 0) whose field grows as start (1 + 2t/tau),
# name_mean (an independent realisation, seed 2) with the field held at mean, name_start
# with it held at start; the first must match the second and differ from the third
# (compareRuns.py; spread: the variance of the particles' x)
seriesStudy()
{
    local name="$1" field="$2" dims="$3" start="$4" mean="$5" make="$6" mode="${7:-}"
    local flowDir="$workDir/${name}_flow" varying meanCase startCase t i c rc args=()
    varying=$($make "${name}_varying")
    rm -rf "$flowDir"
    mkdir -p "$flowDir/constant"
    cp -r "$varying/constant/polyMesh" "$flowDir/constant/"
    for i in 0 1 2 3 4 5 6 7 8 9 10; do
        t=$(awk -v i="$i" 'BEGIN { print i/100 }')
        scalarFile "$flowDir" "$t" "$field" "$dims" \
            "$(awk -v t="$t" -v s="$start" -v tau="$tau" 'BEGIN { printf "%.17g", s*(1 + 2*t/tau) }')"
        cp "$varying/0/U" "$flowDir/$t/U"
    done
    foamDictionary -case "$varying" "$varying/constant/coagulationProperties" \
        -entry transport/flowSeries -add "\"../${name}_flow\"" > /dev/null
    meanCase=$($make "${name}_mean")
    setEntry "$meanCase" constant/coagulationProperties seed 2
    scalarFile "$meanCase" 0 "$field" "$dims" "$mean"
    startCase=$($make "${name}_start")
    scalarFile "$startCase" 0 "$field" "$dims" "$start"
    for c in "$varying" "$meanCase" "$startCase"; do
        (cd "$c" && runApplication coagulationFoam) || fail "coagulationFoam in $c"
        checkBalance "$c/log.coagulationFoam"
    done
    if [ "$mode" = spread ]; then
        args=(--spread "$(awk '/^Initial population:/ { print $3 }' "$varying/log.coagulationFoam")")
    fi
    compare() { PYTHONPATH="$COAGULATIONFOAM_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}" \
        "$COAGULATIONFOAM_PYTHON" "$testsDir/compareRuns.py" "${args[@]}" "$1" "$2"; }
    compare "$varying" "$meanCase" \
        || fail "$name: the run on $field growing in time is not the run at its time mean"
    set +e
    compare "$varying" "$startCase"
    rc=$?
    set -e
    [ "$rc" = 3 ] || fail "$name: the run held at the start's $field passed the comparison (exit $rc)"
}

# (int_0^T sqrt(1 + 2t/tau) dt / T)^2, T = 0.1: the factor of the mean of sqrt
sqrtMean=$(awk -v tau="$tau" 'BEGIN { T = 0.1; m = tau/3*((1 + 2*T/tau)^1.5 - 1)/T; printf "%.17g", m*m }')
seriesStudy st epsilon "[0 2 -3 0 0 0 0]" "$eps0" \
    "$(awk -v e="$eps0" -v f="$sqrtMean" 'BEGIN { printf "%.17g", e*f }')" stCase
echo "ok: localSaffmanTurner follows epsilon of the flow series (time rescaling, epsilon mean $sqrtMean)"

# 5b. The same with the gas: free-molecular Brownian coagulation (a part of a sum kernel),
#     K proportional to sqrt(T), T(t) = 300 K (1 + 2t/tau) of a flow series: the run at the
#     mean sqrt(T) (T = 300 K times epsilon's factor above), and not the run at 300 K
gasCase()
{
    local c
    c=$(stCase "$1")
    setEntry "$c" constant/coagulationProperties kernel \
        "{ type sum; kernels { brownian { type Brownian; regime freeMolecular; T T; p 1e5; } } }"
    foamDictionary -case "$c" "$c/constant/coagulationProperties" -entry particles \
        -add "{ density 1800; massUnit 9.42e-22; }" > /dev/null
    setEntry "$c" constant/coagulationProperties initialPopulation "{ numberDensity 3e16; mass 1; }"
    setEntry "$c" constant/coagulationProperties statisticalWeight "{ n 400; V1 5e-17; }"
    echo "$c"
}
seriesStudy gas T "[0 0 0 1 0 0 0]" 300 \
    "$(awk -v f="$sqrtMean" 'BEGIN { printf "%.17g", 300*f }')" gasCase
echo "ok: the Brownian kernel (a part of a sum) follows T of the flow series"

# 6. The turbulent walk on a nut that changes in time: a puff of 20 000 particles in the two
#    middle cells of the duct (no flow, no coagulation), nut(t) = nut0 (1 + 2t/tau) written as
#    a flow series. The spread's variance grows by 2 int D dt, D = nut/Sct, so at T it is the
#    run's with nut held at its mean over [0, T], nut0 (1 + T/tau); the run held at nut0 has
#    a smaller one
nut0=1e-4
puffCase()
{
    local c
    c=$(newCase constantKernelDuct "$1")
    sed -i 's/uniform (1 0 0)/uniform (0 0 0)/g' "$c/0/U"
    foamDictionary -case "$c" "$c/constant/coagulationProperties" -entry inflow -remove > /dev/null
    setEntry "$c" constant/coagulationProperties inception "{ rate 0; mass 1; }"
    setEntry "$c" constant/coagulationProperties kernel "{ type none; }"
    foamDictionary -case "$c" "$c/constant/coagulationProperties" -entry initialPopulation \
        -add "{ numberDensityField n0; mass 1; }" > /dev/null
    foamDictionary -case "$c" "$c/constant/coagulationProperties" -entry dispersion \
        -add "{ type turbulent; Sct 1; nut nut; }" > /dev/null
    foamDictionary -case "$c" "$c/constant/coagulationProperties" -entry transport \
        -add "{ type frozenFlow; interpolationSchemes { U cellPoint; } }" > /dev/null
    setEntry "$c" constant/coagulationProperties sampling "{ tRelax 0; sampleInterval 0.01; }"
    setEntry "$c" system/controlDict deltaT 1e-3
    setEntry "$c" system/controlDict endTime 0.1
    setEntry "$c" system/controlDict writeInterval 0.1
    foamDictionary -case "$c" "$c/system/controlDict" -entry functions/momentAverages \
        -remove > /dev/null
    {
        echo 'FoamFile { version 2.0; format ascii; class volScalarField; object n0; }'
        echo 'dimensions [0 -3 0 0 0 0 0];'
        echo 'internalField nonuniform List<scalar> 50 ('
        for i in $(seq 0 49); do
            if [ "$i" = 24 ] || [ "$i" = 25 ]; then echo 3.125e9; else echo 0; fi
        done
        echo ');'
        echo 'boundaryField { inlet { type zeroGradient; } outlet { type zeroGradient; } sides { type empty; } }'
    } > "$c/0/n0"
    echo "$c"
}
seriesStudy puff nut "[0 2 -1 0 0 0 0]" "$nut0" \
    "$(awk -v n="$nut0" -v tau="$tau" 'BEGIN { printf "%.17g", n*(1 + 0.1/tau) }')" puffCase spread
echo "ok: the turbulent walk follows nut of the flow series"
