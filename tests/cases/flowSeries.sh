#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# coagulationFoam on a flow case's written times (transport/flowSeries), on the
# constant-kernel duct (inception everywhere, no inflow):
#  1. a series whose times all hold the start time's U gives the frozen run's particles
#     bit for bit;
#  2. an inlet velocity u(t) = u0 (1 + a sin(2 pi t/P)), uniform in space: the particles at
#     x at time t are of age s, the smaller of t and the tau with int_{t-tau}^t u = x, so
#     each cell's sampled M0..M3 are the homogeneous constant-kernel solution (eqs 39-45)
#     at that age. Written every P/40 the time means of sample/exact - 1 (t >= tRelax) are
#     within 4 standard errors of 0 (correlated intervals) and 8 % in every cell and moment,
#     and so are their cell means' components at the flow's frequency and its double;
#     written every P/4 the linear interpolation in time is far off, and the check fails;
#  3. a series with a time without U, one that ends before the run, one on another mesh and
#     a folder that is not there are refused with a FatalIOError naming them (a flowSeries
#     inside the function object: case_functionObject).
. "$(dirname "$0")/caseLib.sh"

u0=1; a=0.5; P=0.4

# writeSeries flowCase spacing endTime: U(t) uniform at every multiple of spacing
writeSeries()
{
    "$COAGULATIONFOAM_PYTHON" - "$1" "$2" "$3" "$u0" "$a" "$P" <<'PY'
import math, os, sys
case, dw, end, u0, a, P = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), *map(float, sys.argv[4:7])
k = 0
while k * dw <= end + 1e-12:
    t = k * dw
    name = "%.10g" % t
    os.makedirs(os.path.join(case, name), exist_ok=True)
    u = u0 * (1 + a * math.sin(2 * math.pi * t / P))
    with open(os.path.join(case, name, "U"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
                "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (%.17g 0 0);\n"
                "boundaryField\n{\n    inlet { type fixedValue; value uniform (%.17g 0 0); }\n"
                "    outlet { type zeroGradient; }\n    sides { type empty; }\n}\n" % (u, u))
    k += 1
PY
}

# flowCase dir: a flow case folder with the duct's mesh (the U files added by the caller)
flowCase()
{
    local f
    f=$(newCase constantKernelDuct "$1")
    rm -rf "$f/0"
    echo "$f"
}

# 1. A steady series: the frozen run bit for bit
steady=$(flowCase series_steadyFlow)
for t in 0 0.05 0.1 0.15 0.2; do
    mkdir -p "$steady/$t"; cp "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct/0/U" "$steady/$t/U"
done
frozen=$(newCase constantKernelDuct series_frozen)
series=$(newCase constantKernelDuct series_steady)
for c in "$frozen" "$series"; do
    setEntry "$c" system/controlDict endTime 0.2
    setEntry "$c" system/controlDict writeInterval 0.1
done
foamDictionary -entry transport -add "{ type frozenFlow; flowSeries \"$steady\"; }" \
    "$series/constant/coagulationProperties" > /dev/null
(cd "$frozen" && runApplication coagulationFoam) || fail "frozen run"
(cd "$series" && runApplication coagulationFoam) || fail "steady series run"
grep -q "5 written times from 0 to 0.2" "$series/log.coagulationFoam" || fail "no series line"
for f in "$frozen"/0.2/lagrangian/coagulationCloud/* "$frozen"/0.2/M0 "$frozen"/0.2/M3; do
    cmp -s "$f" "$series/0.2/${f#"$frozen/0.2/"}" || fail "steady series: $f differs"
done
echo "ok steady series: the frozen run's particles bit for bit"

# 2. The sinusoidal inlet velocity, written every P/40 and every P/4
for spacing in 0.01 0.1; do
    flow=$(flowCase "series_sineFlow_$spacing")
    writeSeries "$flow" "$spacing" 2.0
    c=$(newCase constantKernelDuct "series_sine_$spacing")
    setEntry "$c" system/controlDict endTime 2.0
    setEntry "$c" system/controlDict writeInterval 2.0
    setEntry "$c" constant/coagulationProperties splitting Strang
    foamDictionary -entry transport -add "{ type frozenFlow; flowSeries \"$flow\"; }" \
        "$c/constant/coagulationProperties" > /dev/null
    # the start time's U: the series' (it is set from the series at every move)
    cp "$flow/0/U" "$c/0/U"
    (cd "$c" && runApplication coagulationFoam) || fail "sine series $spacing"
    checkBalance "$c/log.coagulationFoam"
    set +e
    PYTHONPATH="$COAGULATIONFOAM_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}" \
        "$COAGULATIONFOAM_PYTHON" "$testsDir/sineDuct.py" "$c" "$u0" "$a" "$P"
    status=$?
    set -e
    if [ "$spacing" = 0.01 ]; then
        [ "$status" = 0 ] || fail "series every P/40: moments off the exact solution at their age"
        echo "ok sine series every P/40: each cell's moments at the exact solution of their age"
    else
        [ "$status" = 3 ] || fail "series every P/4: the interpolation error was not seen ($status)"
        echo "ok sine series every P/4: the linear interpolation's error is seen (the check fails)"
    fi
done

# 3. Refusals
refuse()
{
    local name="$1" expected="$2" entry="$3"
    local c
    c=$(newCase constantKernelDuct "series_bad_$name")
    setEntry "$c" system/controlDict endTime 0.2
    foamDictionary -entry transport -add "$entry" "$c/constant/coagulationProperties" > /dev/null
    (cd "$c" && coagulationFoam > log 2>&1) && fail "$name: not refused"
    grep -q "FOAM FATAL" "$c/log" && grep -q -- "$expected" "$c/log" \
        || { tail -20 "$c/log"; fail "$name: the error does not name '$expected'"; }
}
gap=$(flowCase series_gapFlow)
writeSeries "$gap" 0.05 0.2
rm "$gap/0.1/U"
refuse gap "$gap/0.1\" has no U" "{ type frozenFlow; flowSeries \"$gap\"; }"
short=$(flowCase series_shortFlow)
writeSeries "$short" 0.05 0.1
refuse short "do not cover this run's 0 to 0.2" "{ type frozenFlow; flowSeries \"$short\"; }"
other=$(flowCase series_otherMesh)
sed -i 's/(50 1 1)/(40 1 1)/' "$other/system/blockMeshDict"
(cd "$other" && rm -rf constant/polyMesh && blockMesh > log.blockMesh 2>&1)
writeSeries "$other" 0.05 0.2
refuse otherMesh "is on another mesh" "{ type frozenFlow; flowSeries \"$other\"; }"
refuse missing "not a folder" "{ type frozenFlow; flowSeries \"$workDir/noSuchCase\"; }"
echo "ok refusals: a gap, too short, another mesh, no folder"
echo "PASS flowSeries"
