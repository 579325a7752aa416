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
#     inside the function object: case_functionObject);
#  4. a gap of purged writes is refused naming its times (maxGap accepts it; a maxGap not
#     above 0 or without a flowSeries is refused); 5. a flow run
#     never reconstructed is named as such;
#  6. the interpolation at a quarter of an interval, of U and of a model's field (kS of surface
#     growth), against the exact linear interpolation.
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

# uniformU dir ux: the duct's U in the folder dir (made), uniform (ux 0 0) inside and at the inlet
uniformU()
{
    mkdir -p "$1"
    sed "s/uniform (1 0 0)/uniform ($2 0 0)/g" "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct/0/U" \
        > "$1/U"
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

# 4. Purged writes (purgeWrite leaves 0 and the last few times): a gap longer than three
#    spacings of the series is refused, naming its two times; maxGap accepts it
purged=$(flowCase series_purgedFlow)
writeSeries "$purged" 0.02 0.2
(cd "$purged" && rm -rf 0.02 0.04 0.06 0.08 0.1 0.12)
refuse purged "between 0 and 0.14" "{ type frozenFlow; flowSeries \"$purged\"; }"
grep -q "maxGap 0.14" "$workDir/series_bad_purged/log" || fail "purged: no maxGap advice"
c="$workDir/series_bad_purged"
setEntry "$c" constant/coagulationProperties transport/maxGap 0.14
(cd "$c" && coagulationFoam > log 2>&1) || { tail -20 "$c/log"; fail "purged: maxGap 0.14 refused"; }
echo "ok purged series: the gap 0 to 0.14 refused, accepted with maxGap"
# (a series of two times has no gap to compare: the entry is checked all the same)
two=$(flowCase series_twoTimesFlow)
writeSeries "$two" 0.2 0.2
refuse negativeGap "Entry 'maxGap' = -1" "{ type frozenFlow; flowSeries \"$two\"; maxGap -1; }"
refuse gapWithoutSeries "no 'flowSeries'" "{ type frozenFlow; maxGap 0.1; }"
echo "ok maxGap: not a time > 0, or without flowSeries: refused"

# 5. A flow run decomposed and never reconstructed: the error says so
decomposed=$(flowCase series_decomposedFlow)
writeSeries "$decomposed" 0.05 0.2
mkdir -p "$decomposed/processor0" "$decomposed/processor1"
for t in 0.05 0.1 0.15 0.2; do mv "$decomposed/$t" "$decomposed/processor0/$t"; done
refuse decomposed "reconstructPar" "{ type frozenFlow; flowSeries \"$decomposed\"; }"
echo "ok decomposed flow: the error names reconstructPar"

# 6. The interpolation itself: at a quarter of an interval U is 3/4 of the earlier written
#    field and 1/4 of the later one. U of 1, 2 and 1 m/s at 0, 0.1 and 0.2; the run writes
#    U of its time every 0.025
steps=$(flowCase series_stepsFlow)
uniformU "$steps/0" 1; uniformU "$steps/0.1" 2; uniformU "$steps/0.2" 1
c=$(newCase constantKernelDuct series_quarter)
setEntry "$c" system/controlDict endTime 0.2
setEntry "$c" system/controlDict writeInterval 0.025
setEntry "$c" system/controlDict writeFormat ascii
setEntry "$c" constant/coagulationProperties splitting Strang
foamDictionary -entry transport -add "{ type frozenFlow; flowSeries \"$steps\"; }" \
    "$c/constant/coagulationProperties" > /dev/null
(cd "$c" && runApplication coagulationFoam) || fail "the stepped series"
"$COAGULATIONFOAM_PYTHON" - "$c" <<'PY' || fail "U is not the series' linear interpolation"
import re, sys
case = sys.argv[1]
for t in ("0.025", "0.075", "0.125", "0.175"):
    s = open("%s/%s/U" % (case, t)).read()
    u = float(re.search(r"internalField\s+uniform\s+\(([^ ]+)", s).group(1))
    tm = float(t)
    exact = 1 + tm / 0.1 if tm < 0.1 else 2 - (tm - 0.1) / 0.1
    print("U at %s: %.15g, the interpolation: %.15g" % (t, u, exact))
    if abs(u / exact - 1) > 1e-12:
        sys.exit(1)
PY
echo "ok the series' U at a quarter and three quarters of its intervals"

# ... and for a field a model reads: surface growth at the rate kS of the series (1e-4, 3e-4,
#    1e-4 kg/(m2 s) at 0, 0.04, 0.08; U = 0) on particles of 10 nm: d(t) = d0 + 2 K(t)/rho with
#    K the integral of the interpolated kS, exact at every write (the growth is set at the
#    middle of each of its half steps, exact for kS linear within a step)
rates=$(flowCase series_ratesFlow)
for tk in "0 1e-4" "0.04 3e-4" "0.08 1e-4"; do
    set -- $tk
    uniformU "$rates/$1" 0
    cat > "$rates/$1/kS" <<DICT
FoamFile { version 2.0; format ascii; class volScalarField; object kS; }
dimensions [1 -2 -1 0 0 0 0];
internalField uniform $2;
boundaryField { inlet { type zeroGradient; } outlet { type zeroGradient; } sides { type empty; } }
DICT
done
c=$(newCase constantKernelDuct series_growthRate)
cp "$rates/0/U" "$c/0/U"
setEntry "$c" system/controlDict deltaT 1e-3
setEntry "$c" system/controlDict endTime 0.08
setEntry "$c" system/controlDict writeInterval 0.01
setEntry "$c" system/controlDict writeFormat ascii
setEntry "$c" system/controlDict writePrecision 17
foamDictionary -entry functions -remove "$c/system/controlDict" > /dev/null
props="$c/constant/coagulationProperties"
setEntry "$c" constant/coagulationProperties kernel "{ type none; }"
setEntry "$c" constant/coagulationProperties inception "{ rate 0; mass 1; }"
setEntry "$c" constant/coagulationProperties sampling "{ tRelax 1; sampleInterval 0.01; }"
setEntry "$c" constant/coagulationProperties splitting Strang
foamDictionary "$props" -entry particles -add "{ density 1800; }" > /dev/null
foamDictionary "$props" -entry initialPopulation -add "{ numberDensity 1e12; diameter 1e-8; }" > /dev/null
foamDictionary "$props" -entry growth -add "{ coat { type surface; rate kS; } }" > /dev/null
foamDictionary "$props" -entry transport -add "{ type frozenFlow; flowSeries \"$rates\"; }" > /dev/null
setEntry "$c" constant/coagulationProperties statisticalWeight "{ n 4; V1 1e-12; }"
(cd "$c" && runApplication coagulationFoam) || fail "surface growth from the series' kS"
checkBalance "$c/log.coagulationFoam"
PYTHONPATH="$testsDir:$COAGULATIONFOAM_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}" \
    "$COAGULATIONFOAM_PYTHON" - "$c" <<'PY' || fail "the growth is not that of the series' kS in time"
import sys
import numpy as np
from dispersionCases import read_field
case, rho, d0 = sys.argv[1], 1800.0, 1e-8
def K(t):
    """The integral of kS, linear between 1e-4 at 0, 3e-4 at 0.04 and 1e-4 at 0.08."""
    if t <= 0.04:
        return 1e-4 * t + 2e-4 * t * t / 0.08
    return K(0.04) + 3e-4 * (t - 0.04) - 2e-4 * (t - 0.04) ** 2 / 0.08
worst = 0
for t in ("0.01", "0.02", "0.03", "0.05", "0.07", "0.08"):
    mass = np.asarray(read_field(case, t, "M1")) / np.asarray(read_field(case, t, "M0"))
    d = (6 * mass / (np.pi * rho)) ** (1 / 3)
    exact = d0 + 2 * K(float(t)) / rho
    worst = max(worst, np.abs(d / exact - 1).max())
print("surface growth from the series' kS: the diameters exact to %.1e at 6 writes" % worst)
sys.exit(0 if worst < 1e-10 else 1)
PY
echo "ok the series' kS at every step: the diameters of its integral in time"
echo "PASS flowSeries"
