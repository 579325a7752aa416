#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# The coagulationCloud function object inside OpenFOAM's own transient solvers, on the
# constant-kernel duct (uniform flow, inflow and inception):
#  1. inside scalarTransportFoam (which keeps U as read): the same particles and moment
#     fields as coagulationFoam, bit for bit, at every written time, with both splittings;
#     a restart from a written time continues the run bit for bit; decomposed on two
#     processors, the same particles as coagulationFoam -parallel; a split step every two
#     time steps of half the step (executeInterval 2), coagulationFoam's particles;
#  2. inside pimpleFoam (which solves for U each step): the time-averaged M0..M3 against the
#     analytic eqs 39-45 within the duct tests' tolerance (Lie), and with an inlet velocity
#     u0 (1 + a sin(2 pi t/P)) each cell's moments at the exact solution of their age
#     (Strang, sineDuct.py); balances closed;
#  3. a steady solver's case (ddtSchemes steadyState), a velocity the solver does not have,
#     a transport flowSeries, an executeInterval that the writes do not fit and a timeEnd before
#     endTime are refused with a FatalIOError naming the entry; an incomplete start time
#     stops the run (a FatalError that OpenFOAM's function-object list would only warn of).
. "$(dirname "$0")/caseLib.sh"
. "$(dirname "$0")/functionObjectCases.sh"

# 1. Frozen flow: coagulationFoam and the function object in scalarTransportFoam
for splitting in Lie Strang; do
    ref=$(newCase constantKernelDuct "fo_coagulationFoam_$splitting")
    foc=$(newCase constantKernelDuct "fo_scalarTransport_$splitting")
    for c in "$ref" "$foc"; do
        setEntry "$c" constant/coagulationProperties splitting "$splitting"
        setEntry "$c" system/controlDict endTime 0.2
        setEntry "$c" system/controlDict writeInterval 0.1
        foamDictionary -case "$c" "$c/system/controlDict" -entry functions/momentAverages \
            -remove > /dev/null
    done
    (cd "$ref" && runApplication coagulationFoam) || fail "coagulationFoam ($splitting)"
    scalarTransport "$foc"
    fo "$foc"
    (cd "$foc" && runApplication scalarTransportFoam) || fail "scalarTransportFoam ($splitting)"
    checkBalance "$foc/log.scalarTransportFoam"
    for t in 0.1 0.2; do
        [ -d "$ref/$t/lagrangian/coagulationCloud" ] || fail "no particles in $ref/$t"
        for f in "$ref/$t"/lagrangian/coagulationCloud/* "$ref/$t"/M0 "$ref/$t"/M1 "$ref/$t"/M2 \
                 "$ref/$t"/M3; do
            g="$foc/$t/${f#"$ref/$t/"}"
            [ -f "$g" ] || fail "$splitting: the function object wrote no $g"
            cmp -s "$f" "$g" || fail "$splitting: $g differs from coagulationFoam's"
        done
    done
    echo "ok $splitting: the function object in scalarTransportFoam gives coagulationFoam's particles and moments bit for bit at t = 0.1 and 0.2"
done

# 1b. A restart of the solver from a time the function object wrote continues the run bit
#     for bit (the case of 1 with Strang splitting ran 0 -> 0.2 uninterrupted)
rst=$(newCase constantKernelDuct fo_restart)
setEntry "$rst" constant/coagulationProperties splitting Strang
setEntry "$rst" system/controlDict endTime 0.1
setEntry "$rst" system/controlDict writeInterval 0.1
foamDictionary -case "$rst" "$rst/system/controlDict" -entry functions/momentAverages \
    -remove > /dev/null
scalarTransport "$rst"
fo "$rst"
(cd "$rst" && runApplication scalarTransportFoam) || fail "restart: the first run"
[ -f "$rst/0.1/uniform/coagulationCloudComplete" ] || fail "restart: 0.1 not marked complete"
setEntry "$rst" system/controlDict endTime 0.2
(cd "$rst" && mv log.scalarTransportFoam log.first && runApplication scalarTransportFoam) \
    || fail "restart: the second run"
for f in "$foc"/0.2/lagrangian/coagulationCloud/* "$foc"/0.2/M0 "$foc"/0.2/M3; do
    g="$rst/0.2/${f#"$foc/0.2/"}"
    cmp -s "$f" "$g" || fail "restart: $g differs from the uninterrupted run's"
done
checkBalance "$rst/log.scalarTransportFoam"
echo "ok restart: 0 -> 0.1, then 0.1 -> 0.2, gives the uninterrupted run's particles bit for bit"

# 1d. A split step every 2 time steps (executeInterval 2) of a solver at deltaT/2 gives
#     coagulationFoam's particles at deltaT bit for bit (the random streams count split steps)
half=$(newCase constantKernelDuct fo_everyTwo)
setEntry "$half" constant/coagulationProperties splitting Strang
setEntry "$half" system/controlDict endTime 0.2
setEntry "$half" system/controlDict writeInterval 0.1
setEntry "$half" system/controlDict deltaT 5e-5
foamDictionary -case "$half" "$half/system/controlDict" -entry functions/momentAverages \
    -remove > /dev/null
scalarTransport "$half"
fo "$half" "executeInterval 2;"
(cd "$half" && runApplication scalarTransportFoam) || fail "executeInterval 2"
checkBalance "$half/log.scalarTransportFoam"
for t in 0.1 0.2; do
    for f in "$ref/$t"/lagrangian/coagulationCloud/* "$ref/$t"/M0 "$ref/$t"/M3; do
        g="$half/$t/${f#"$ref/$t/"}"
        cmp -s "$f" "$g" || fail "executeInterval 2: $g differs from coagulationFoam's at twice the step"
    done
done
echo "ok executeInterval 2 at deltaT 5e-5: coagulationFoam's particles at deltaT 1e-4 bit for bit"

# 1c. Decomposed on 2 processors: the function object in scalarTransportFoam -parallel gives
#     coagulationFoam -parallel's particles bit for bit (particles cross the processor
#     boundary)
for solver in coagulationFoam scalarTransportFoam; do
    c=$(newCase constantKernelDuct "fo_parallel_$solver")
    setEntry "$c" system/controlDict endTime 0.2
    setEntry "$c" system/controlDict writeInterval 0.2
    foamDictionary -case "$c" "$c/system/controlDict" -entry functions/momentAverages \
        -remove > /dev/null
    if [ "$solver" = scalarTransportFoam ]; then scalarTransport "$c"; fo "$c"; fi
    (cd "$c" && runApplication decomposePar && runParallel -np 2 "$solver") \
        || fail "parallel $solver"
    checkBalance "$c/log.$solver"
done
par="$workDir/fo_parallel_coagulationFoam"; pfo="$workDir/fo_parallel_scalarTransportFoam"
for p in 0 1; do
    n=0
    for f in "$par/processor$p/0.2/lagrangian/coagulationCloud"/*; do
        g="$pfo/processor$p/0.2/lagrangian/coagulationCloud/$(basename "$f")"
        cmp -s "$f" "$g" || fail "parallel: $g differs from coagulationFoam's"
        n=$((n + 1))
    done
    [ "$n" -gt 0 ] || fail "parallel: no particles on processor $p"
done
echo "ok parallel: 2 processors, the function object gives coagulationFoam -parallel's particles bit for bit"

# 2. pimpleFoam solving the uniform flow (Lie splitting): the duct's analytic moments
c=$(pimpleCase fo_pimpleFoam)
setEntry "$c" constant/coagulationProperties splitting Lie
foamDictionary -case "$c" "$c/system/controlDict" -entry functions/momentAverages -add "$(
    foamDictionary -case "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct" \
        "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct/system/controlDict" \
        -entry functions/momentAverages -value)" > /dev/null
(cd "$c" && runApplication pimpleFoam) || fail "pimpleFoam"
checkBalance "$c/log.pimpleFoam"
grep -q "coagulationCloud particles: time 1.2, particles = " "$c/log.pimpleFoam" \
    || fail "pimpleFoam: no step of the function object at t = 1.2"
(cd "$c" && $report --case . --out results --no-plots --check --check-rel-tol 0.08 \
    --check-skip-cells 3 --check-sigma 4) \
    || fail "pimpleFoam: moments off the analytic solution by more than 0.08"
echo "ok pimpleFoam (Lie): the duct's analytic moments within 8 % (4 standard errors), balances closed"

# 2b. pimpleFoam with the inlet velocity u(t) = u0 (1 + a sin(2 pi t/P)) (Strang splitting):
#     each cell's moments at the exact solution of their age (sineDuct.py)
c=$(pimpleCase fo_pimpleSine)
setEntry "$c" constant/coagulationProperties splitting Strang
setEntry "$c" 0/U boundaryField/inlet "{ type uniformFixedValue; uniformValue sine; uniformValueCoeffs { frequency 2.5; amplitude 0.5; scale (1 0 0); level (1 0 0); } value uniform (1 0 0); }"
(cd "$c" && runApplication pimpleFoam) || fail "pimpleFoam, sine inlet"
checkBalance "$c/log.pimpleFoam"
PYTHONPATH="$COAGULATIONFOAM_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}" \
    "$COAGULATIONFOAM_PYTHON" "$testsDir/sineDuct.py" "$c" 1 0.5 0.4 \
    || fail "pimpleFoam, sine inlet: moments off the exact solution at their age"
echo "ok pimpleFoam (Strang), sine inlet: each cell's moments at the exact solution of their age"

# 3. Refusals
bad=$(newCase constantKernelDuct fo_steady)
scalarTransport "$bad"
fo "$bad"
setEntry "$bad" system/fvSchemes ddtSchemes/default steadyState
setEntry "$bad" system/controlDict endTime 1e-3
(cd "$bad" && scalarTransportFoam > log 2>&1) && fail "a steady solver was not refused"
grep -q "FOAM FATAL IO ERROR" "$bad/log" && grep -q "steadyState" "$bad/log" \
    && grep -q "controlDict" "$bad/log" || { tail -20 "$bad/log"; fail "steady: no named error"; }
bad=$(newCase constantKernelDuct fo_noU)
scalarTransport "$bad"
fo "$bad" "U Ugas;"
setEntry "$bad" system/controlDict endTime 1e-3
(cd "$bad" && scalarTransportFoam > log 2>&1) && fail "a missing velocity was not refused"
grep -q "FOAM FATAL IO ERROR" "$bad/log" && grep -q "'Ugas' (entry 'U')" "$bad/log" \
    || { tail -20 "$bad/log"; fail "no velocity: no named error"; }
bad=$(newCase constantKernelDuct fo_series)
scalarTransport "$bad"
fo "$bad"
foamDictionary -entry transport -add "{ type frozenFlow; flowSeries \"$bad\"; }" \
    "$bad/constant/coagulationProperties" > /dev/null
setEntry "$bad" system/controlDict endTime 1e-3
(cd "$bad" && scalarTransportFoam > log 2>&1) && fail "a flow series in the function object was not refused"
grep -q "FOAM FATAL IO ERROR" "$bad/log" && grep -q "Entry 'flowSeries'" "$bad/log" \
    || { tail -20 "$bad/log"; fail "flow series: no named error"; }
for entry in "executeInterval 3;" "timeEnd 5e-4;"; do
    bad=$(newCase constantKernelDuct fo_control)
    scalarTransport "$bad"
    fo "$bad" "$entry"
    setEntry "$bad" system/controlDict endTime 1e-3
    (cd "$bad" && scalarTransportFoam > log 2>&1) && fail "'$entry' was not refused"
    grep -q "FOAM FATAL IO ERROR" "$bad/log" && grep -q "${entry%% *}" "$bad/log" \
        || { tail -20 "$bad/log"; fail "'$entry': no named error"; }
done
# a FatalError (not an IO one) while the cloud is made stops the run: OpenFOAM's list of
# function objects would make it a warning and run on without the particles
bad=$(newCase constantKernelDuct fo_incomplete)
scalarTransport "$bad"
fo "$bad"
cp -r "$rst/0.1" "$bad/0.1"
rm "$bad/0.1/uniform/coagulationCloudComplete"
setEntry "$bad" system/controlDict endTime 0.11
(cd "$bad" && scalarTransportFoam > log 2>&1) && fail "an incomplete start time was not refused"
grep -q "FOAM FATAL ERROR" "$bad/log" && grep -q "is incomplete" "$bad/log" \
    || { tail -20 "$bad/log"; fail "incomplete start time: no error"; }
echo "ok refusals: steady solver, missing velocity, a flow series, stepping less often or ending early, an incomplete start time"
echo "PASS functionObject"
