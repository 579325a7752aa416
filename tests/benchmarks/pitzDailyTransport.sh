#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Transport on a real flow, side by side with OpenFOAM's own tracer cloud: OpenFOAM's
# simpleFoam pitzDaily (the backward-facing step, 12 225 cells; from openfoam-examples, or
# from the OpenFOAM source tarball the bootstrap cached), converged, then
#  - coagulationFoam on the frozen flow: the particles of a uniform initial population (no
#    inception, a constant kernel too weak to matter), stick walls, deltaT 1e-5;
#  - icoUncoupledKinematicParcelFoam (OpenFOAM's tracer cloud) on the same flow from the
#    same start positions: 0.1 um parcels of 1000 kg/m3 (they follow the flow), sphereDrag,
#    cellPoint U, maxCo 0.3, rebounding walls, deltaT 1e-5.
# Each configuration runs STEPS steps, ROUNDS rounds alternated, one core each; the figure
# is particle-steps per second of transport: the mean particle count times the steps over
# the transport's wall time (coagulationFoam: its transport timer; OpenFOAM: the execution
# time of the steps after the first, which is all cloud evolution). Prints every run and the
# median per configuration. BEFORE=<another checkout, built> runs its coagulationFoam beside
# this one's in every round (the configurations it has), for before/after pairs.
#   [BEFORE=DIR] tests/benchmarks/pitzDailyTransport.sh [OUTDIR] [ROUNDS=3] [STEPS=400]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../../etc/functions"
out="${1:-/tmp/pitzDailyTransport}"; rounds="${2:-3}"; steps="${3:-400}"
export OMP_NUM_THREADS=1
rm -rf "$out"; mkdir -p "$out"
py="$COAGULATIONFOAM_PYTHON"

# 1. The flow: pitzDaily by simpleFoam, to convergence
flow="$out/flow"
openfoamTutorial incompressible/simpleFoam/pitzDaily "$flow"
(cd "$flow" && runApplication blockMesh && runApplication simpleFoam) > /dev/null
latest=$(cd "$flow" && foamListTimes -latestTime)
echo "pitzDaily: simpleFoam converged at iteration $latest"

# 2. The particle cases' common part: mesh, schemes, converged U, nut, k, epsilon
base="$out/base"
mkdir -p "$base/0" "$base/constant" "$base/system"
cp -r "$flow/constant/polyMesh" "$base/constant/"
cp "$flow/system/fvSchemes" "$flow/system/fvSolution" "$base/system/"
for f in U nut k epsilon p; do cp "$flow/$latest/$f" "$base/0/"; done
cp "$flow/constant/transportProperties" "$flow/constant/turbulenceProperties" "$base/constant/"
cat > "$base/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application     coagulationFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         $(awk -v s="$steps" 'BEGIN { printf "%.10g", s*1e-5 }');
deltaT          1e-5;
writeControl    timeStep;
writeInterval   $steps;
purgeWrite      0;
writeFormat     ascii;
writePrecision  17;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
logSteps        on;         // the particles of every step, averaged below
libs            (turbulenceModels incompressibleTurbulenceModels);
DICT

# coagulationFoam: a uniform population of about 50 000 particles (the weight of n = 1,
# V1 = 1 is the smallest cell volume, 1.19e-9 m3)
coag="$out/coag"
cp -r "$base" "$coag"
cat > "$coag/constant/coagulationProperties" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object coagulationProperties; }
algorithm       SWA;
splitting       Strang;
kernel          { type constant; K0 1e-30; }
inception       { rate 0; mass 1; }
initialPopulation { numberDensity 4; mass 1; }
statisticalWeight { n 1; V1 1; }
seed            1;
sampling        { tRelax 100; sampleInterval 1e-5; }
transport       { type frozenFlow; interpolationSchemes { U cellPoint; } }
dispersion      { type turbulent; Sct 0.7; }
patchInteraction { patches { upperWall stick; lowerWall stick; } }
DICT

# The start positions of OpenFOAM's cloud: coagulationFoam's initial population after one
# step (cell velocity, no walk), written in ASCII
start="$out/start"
cp -r "$coag" "$start"
foamDictionary -entry endTime -set 1e-5 "$start/system/controlDict" > /dev/null
foamDictionary -entry writeInterval -set 1 "$start/system/controlDict" > /dev/null
foamDictionary -entry dispersion -remove "$start/constant/coagulationProperties" > /dev/null
foamDictionary -entry transport -set "{ type frozenFlow; interpolationSchemes { U cell; } }" \
    "$start/constant/coagulationProperties" > /dev/null
(cd "$start" && runApplication coagulationFoam) > /dev/null
"$py" - "$start/1e-05/lagrangian/coagulationCloud/positions" "$out/positions" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
body = text[text.index("(", text.index("\n", text.index("FoamFile"))) :]
pts = re.findall(r"\(\s*([-+0-9.eE]+)\s+([-+0-9.eE]+)\s+([-+0-9.eE]+)\s*\)", body)
with open(sys.argv[2], "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class vectorField; object kinematicCloudPositions; }\n")
    f.write("%d\n(\n" % len(pts))
    for p in pts:
        f.write("(%s %s %s)\n" % p)
    f.write(")\n")
print(len(pts))
PY
nStart=$(awk 'NR == 2' "$out/positions")
echo "start positions: $nStart"

# OpenFOAM's tracer cloud on the same flow
ofc="$out/openfoam"
cp -r "$base" "$ofc"
foamDictionary -entry application -set icoUncoupledKinematicParcelFoam "$ofc/system/controlDict" > /dev/null
# no write: the timed steps are the cloud's evolution alone
foamDictionary -entry writeInterval -set "$((10*steps))" "$ofc/system/controlDict" > /dev/null
cp "$out/positions" "$ofc/constant/kinematicCloudPositions"
# transient tracking: the cloud takes the flow's steadyState ddt for steady tracking
foamDictionary -entry ddtSchemes/default -set Euler "$ofc/system/fvSchemes" > /dev/null
cat > "$ofc/constant/g" <<'DICT'
FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }
dimensions [0 1 -2 0 0 0 0];
value (0 0 0);
DICT
foamDictionary -entry rhoInf -add "[1 -3 0 0 0 0 0] 1.2" "$ofc/constant/transportProperties" > /dev/null
cat > "$ofc/constant/kinematicCloudProperties" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object kinematicCloudProperties; }
solution
{
    active          true;
    coupled         false;
    transient       yes;
    cellValueSourceCorrection off;
    maxCo           0.3;
    interpolationSchemes { rho cell; U cellPoint; mu cell; }
    integrationSchemes { U Euler; }
}
constantProperties
{
    rho0            1000;
    youngsModulus   1e9;
    poissonsRatio   0.35;
}
subModels
{
    particleForces { sphereDrag; }
    injectionModels
    {
        start
        {
            type            manualInjection;
            massTotal       0;
            parcelBasisType fixed;
            nParticle       1;
            SOI             0;
            positionsFile   "kinematicCloudPositions";
            U0              (10 0 0);
            sizeDistribution { type fixedValue; fixedValueDistribution { value 1e-7; } }
        }
    }
    dispersionModel DISPERSION;
    patchInteractionModel standardWallInteraction;
    standardWallInteractionCoeffs { type rebound; }
    surfaceFilmModel none;
    stochasticCollisionModel none;
    collisionModel  none;
}
cloudFunctions {}
DICT

# 3. The runs, alternated
printf "%-56s %5s %12s %12s\n" configuration round particles "Mpsteps_per_s" | tee "$out/runs.txt"
rate()   # particles steps seconds
{
    awk -v n="$1" -v s="$2" -v t="$3" 'BEGIN { printf "%.3f", n*s/t/1e6 }'
}
before="${BEFORE:-}"
for r in $(seq 1 "$rounds"); do
    for cfg in "cellPoint turbulent StrangSAS" "cellPoint turbulent Strang" \
               "cellPoint turbulent Lie" "cellPoint none Lie" "cell none Lie"; do
      for build in "" ${before:+"$before"}; do
        set -- $cfg
        label="coagulationFoam"
        if [ -n "$build" ]; then
            label="coagulationFoam (before)"
            grep -q "\"$3\"" "$build/src/coagulationModels/clouds/coagulationCloud/coagulationCloud.C" \
                || continue
        fi
        c="$out/run"
        rm -rf "$c"; cp -r "$coag" "$c"
        foamDictionary -entry splitting -set "$3" "$c/constant/coagulationProperties" > /dev/null
        foamDictionary -entry transport -set "{ type frozenFlow; interpolationSchemes { U $1; } }" \
            "$c/constant/coagulationProperties" > /dev/null
        [ "$2" = none ] && foamDictionary -entry dispersion -remove "$c/constant/coagulationProperties" > /dev/null
        if [ -n "$build" ]; then
            (. "$build/etc/bashrc" && coagulationFoam -case "$c") > "$c/log" 2>&1 || { tail "$c/log"; exit 1; }
        else
            coagulationFoam -case "$c" > "$c/log" 2>&1 || { tail "$c/log"; exit 1; }
        fi
        n=$(awk '/^Time = / && /particles = / { s += $NF; k++ } END { printf "%.1f", s/k }' "$c/log")
        ms=$(grep "transport =" "$c/log" | tail -1 | sed 's/.*transport = \([0-9.e+-]*\) ms.*/\1/')
        printf "%-56s %5d %12s %12s\n" "$label $1 $2 $3" "$r" "$n" \
            "$(rate "$n" 1 "$(awk -v m="$ms" 'BEGIN { print m/1e3 }')")" | tee -a "$out/runs.txt"
      done
    done
    for d in stochasticDispersionRAS none; do
        c="$out/run"
        rm -rf "$c"; cp -r "$ofc" "$c"
        sed -i "s/DISPERSION/$d/" "$c/constant/kinematicCloudProperties"
        icoUncoupledKinematicParcelFoam -case "$c" > "$c/log" 2>&1 || { tail -30 "$c/log"; exit 1; }
        read -r n t <<< "$(awk '/Current number of parcels/ { s += $NF; k++ }
            /^ExecutionTime/ { e[++m] = $3 } END { printf "%.1f %.6f", s/k, e[m] - e[1] }' "$c/log")"
        printf "%-56s %5d %12s %12s\n" "OpenFOAM cellPoint $d" "$r" "$n" \
            "$(rate "$n" "$((steps - 1))" "$t")" | tee -a "$out/runs.txt"
    done
done
echo "median per configuration (one core, particle-steps per second, millions):"
"$py" - "$out/runs.txt" <<'PY'
import sys
import numpy as np
rows = [l.rsplit(None, 3) for l in open(sys.argv[1]).read().splitlines()[1:] if l.strip()]
for key in dict.fromkeys(r[0] for r in rows):
    v = [float(r[3]) for r in rows if r[0] == key]
    print("  %-56s %8.3f M  (%d runs)" % (key, np.median(v), len(v)))
PY
