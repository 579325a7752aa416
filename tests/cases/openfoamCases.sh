# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# OpenFOAM's own tutorials with particles (case_openfoamTutorials,
# tests/benchmarks/pipeCyclicTransport.sh). Needs etc/functions (openfoamTutorial,
# runApplication).

# inflowParticles file inlet walls tRelax sampleInterval: coagulationProperties of 10 nm
# particles (1800 kg/m3) entering through the patch inlet at 1e12 /m3, a constant kernel, the
# turbulent walk (nut/Sct), sticking on the patch walls
inflowParticles()
{
    cat > "$1" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object coagulationProperties; }
algorithm       SWA;
splitting       Strang;
particles       { density 1800; massUnit 9.42e-22; }
kernel          { type constant; K0 3e-11; }
inception       { rate 0; mass 1; }
inflow          { patches ($2); density 1e12; mass 1; }
statisticalWeight { n 1; V1 2e-11; }
seed            1;
sampling        { tRelax $4; sampleInterval $5; }
dispersion      { type turbulent; Sct 0.7; }
patchInteraction { patches { $3 stick; } }
DICT
}

# pipeCyclicCase DIR [walls]: OpenFOAM's simpleFoam/pipeCyclic (a pipe sector whose sides are a
# rotational cyclicAMI pair; its coded swirl inlet given as cylindricalInletVelocity, since
# coded conditions are not compiled as root) converged in DIR/flow, and in DIR the particles
# on that flow: coagulationFoam, particles entering with the flow, the turbulent walk,
# sticking walls, deltaT 0.01 to t = 1 (100 steps, a write at 0.5 and 1). With 'walls' the
# sides are rebounding walls instead (the same flow).
pipeCyclicCase()
(
    set -e
    pc="$1"
    rm -rf "$pc" && mkdir -p "$pc"
    openfoamTutorial incompressible/simpleFoam/pipeCyclic "$pc/flow"
    cd "$pc/flow"
    # the coded swirl, U = (1, 2 Cf x (1 0 0)): a rotation of -2 rad/s = -60/pi rpm about x
    "$COAGULATIONFOAM_PYTHON" - <<'PY'
s = open("0.orig/U").read()
i = s.index("    inlet\n")
j = s.index("    }\n", s.index("#};", i)) + 6
s = s[:i] + """    inlet
    {
        type            cylindricalInletVelocity;
        axis            (1 0 0);
        origin          (0 0 0);
        axialVelocity   constant 1;
        radialVelocity  constant 0;
        rpm             constant -19.098593171027442;
        value           $internalField;
    }
""" + s[j:]
open("0.orig/U", "w").write(s)
PY
    runApplication blockMesh
    runApplication topoSet
    runApplication refineHexMesh c0 -overwrite
    rm -rf 0 && cp -r 0.orig 0
    runApplication simpleFoam
    latest=$(foamListTimes -latestTime -noZero)
    [ -n "$latest" ] || { echo "pipeCyclic: simpleFoam wrote no time" >&2; exit 1; }
    cd "$pc"
    cp -r flow/constant flow/system .
    rm -rf constant/polyMesh/sets
    mkdir 0 && for f in U nut k epsilon p; do cp "flow/$latest/$f" 0/; done
    inflowParticles constant/coagulationProperties inlet walls 0.5 0.01
    cat > system/controlDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application     coagulationFoam;
libs            (turbulenceModels incompressibleTurbulenceModels);
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         1;
deltaT          0.01;
writeControl    timeStep;
writeInterval   50;
writeFormat     binary;
runTimeModifiable false;
DICT
    [ "${2:-}" = walls ] || return 0
    # the sides as walls: the boundary file and every field's entries on them
    "$COAGULATIONFOAM_PYTHON" - <<'PY'
import glob, re
p = "constant/polyMesh/boundary"
s = open(p).read()
for side in ("side1", "side2"):
    i = s.index("    %s\n" % side)
    j = s.index("}", i)
    n = re.search(r"nFaces\s+(\d+);", s[i:j]).group(1)
    start = re.search(r"startFace\s+(\d+);", s[i:j]).group(1)
    s = s[:i] + ("    %s\n    {\n        type wall;\n        inGroups List<word> 1(wall);\n"
                 "        nFaces %s;\n        startFace %s;\n    " % (side, n, start)) + s[j:]
open(p, "w").write(s)
walls = {"U": "noSlip", "nut": "nutkWallFunction; value uniform 0",
         "k": "kqRWallFunction; value uniform 0.1",
         "epsilon": "epsilonWallFunction; value uniform 0.1"}
for f in glob.glob("0/*"):
    s = open(f).read()
    for side in ("side1", "side2"):
        i = s.index("    %s" % side)
        j = s.index("}", i)
        s = s[:i] + "    %s\n    {\n        type %s;\n    " % (
            side, walls.get(f.split("/")[-1], "zeroGradient")) + s[j:]
    open(f, "w").write(s)
c = "constant/coagulationProperties"
s = open(c).read().replace("walls stick;", "walls stick; \"side.*\" rebound;")
open(c, "w").write(s)
PY
)
