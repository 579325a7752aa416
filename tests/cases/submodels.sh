#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Short cases (a second or two each) for the paths of the OpenFOAM layer that the duct
# tutorials do not take, each closing a gap that a planted bug went through
# (tests/regression/plantedBugs):
#   wall       a 3-D duct with wall sides and the flow U = (0 1 0) straight into a wall, pure
#              inception: the three rows of cells below the wall hold the particles born
#              below them and carried up (exact expectation, Poisson), and the particles
#              that reached the wall within a step were mirrored back, none rests on it
#              (B20: the normal velocity removed instead of mirrored leaves them on the
#              wall; B28: the reflection not reset per move sends other particles down)
#   twoInlets  two inlet patches side by side, inflow through both: each row of cells
#              downstream of its inlet carries M1 = c_in (B23: every listed patch resolved
#              to the first feeds one row twice and the other not at all)
#   cellZone   inception in a cellZone (the downstream half of the duct): upstream of it,
#              with U along the duct, no cell ever holds a particle (B24: a zone ignored)
#   weights    the weight per particle W = Vref/(n V1) with the algorithm's own V1 for SWA,
#              DSA1 and DSA2 (the sample file's attributes V1 and particleWeight; B22)
#   threeRanks the duct at rest (U = 0) with a constant-D walk and pure inception, cut into
#              3 ranks along x: the middle rank has two processor patches, and a particle
#              walking back from the third rank must arrive on the one it crossed. The
#              steady profile is symmetric: the particles in the first and last thirds agree
#              within their Poisson interval (B97: arrivals placed on the first processor
#              patch send every particle that walks back from the third rank to the first
#              rank's side)
#   submodels.sh [name...]   run only the named cases (default: all)
. "$(dirname "$0")/caseLib.sh"

only=("$@")
want() { [ "${#only[@]}" -eq 0 ] || [[ " ${only[*]} " == *" $1 "* ]]; }
passed=0

# runSolver name: the solver in the current case, at most 120 s (a stuck particle fails the
# test rather than hanging it)
runSolver()
{
    local rc=0
    timeout 120 coagulationFoam > log.coagulationFoam 2>&1 || rc=$?
    [ "$rc" -eq 0 ] || { tail -20 log.coagulationFoam; fail "$1: coagulationFoam exit $rc (124: no end within 120 s)"; }
}

# The sample file of a serial run
samples() { echo "$1/postProcessing/coagulationSamples/samples_0.h5"; }

# ---- wall: rebound
if want wall; then
    c=$(newCase constantKernelDuct submodels_wall)
    cd "$c"
    sed -i 's/(50 1 1)/(10 4 4)/; s/type empty;/type wall;/' system/blockMeshDict
    rm -rf constant/polyMesh log.blockMesh
    runApplication blockMesh
    setEntry . 0/U internalField "uniform (0 1 0)"
    setEntry . 0/U boundaryField/inlet/value "uniform (0 1 0)"
    setEntry . 0/U boundaryField/sides "{ type noSlip; }"
    setEntry . constant/coagulationProperties kernel/K0 1e-30
    setEntry . constant/coagulationProperties statisticalWeight/n 1024
    setEntry . constant/coagulationProperties sampling/tRelax 0
    setEntry . system/controlDict endTime 0.02
    setEntry . system/controlDict writeInterval 0.02
    setEntry . system/controlDict writeFormat ascii
    runSolver wall
    checkBalance log.coagulationFoam
    "$COAGULATIONFOAM_PYTHON" - "$c" <<'PY' || fail "wall: rebound wrong"
import re, sys
import h5py
import numpy as np
case = sys.argv[1]
I, u, dt, K = 3e8, 1.0, 1e-4, 200           # inception rate, U_y, deltaT, steps
h, H, A, Vc = 1e-3, 4e-3, 0.2 * 4e-3, 2e-8  # row height, duct width, row area (x z), cell volume
f = h5py.File(case + "/postProcessing/coagulationSamples/samples_0.h5", "r")
W = float(f.attrs["particleWeight"])
y = f["cellCentres"][:, 1]
N = f["moments"][-1, :, 0] * Vc / W        # particles per cell at t = K dt
bad = []
# Rows below the wall band hold the particles born below them and carried up: born in
# step m uniformly over [0, H], moved s = (K - m + 1) u dt by the end
s = u * dt * np.arange(1, K + 1)
for j in range(3):
    overlap = np.clip(np.minimum((j + 1) * h - s, H) - np.maximum(j * h - s, 0), 0, None).sum()
    expected = I * dt * A / W * overlap
    n = N[np.abs(y - (j + 0.5) * h) < 1e-9].sum()
    z = (n - expected) / np.sqrt(expected)
    print("wall: row %d (y = %.4g): %d particles, expected %.1f (z = %.1f)" % (j, (j + 0.5) * h, n, expected, z))
    if abs(z) > 5:
        bad.append("row %d" % j)
# The particles that reached the wall y = H were mirrored back into the cell: none rests
# on the wall (a particle reaches distance < 1e-12 by chance with probability ~1e-8)
text = open(case + "/0.02/lagrangian/coagulationCloud/positions").read()
p = np.array(re.findall(r"\(([-0-9.e+]+) ([-0-9.e+]+) ([-0-9.e+]+)\)", text), dtype=float)
onWall = int((H - p[:, 1] < 1e-12).sum())
print("wall: %d of %d particles within 1e-12 of the wall y = H" % (onWall, len(p)))
if len(p) < 1000 or onWall > 1:
    bad.append("particles on the wall")
sys.exit(1 if bad else 0)
PY
    passed=$((passed + 1)); echo "ok wall"
fi

# ---- twoInlets: patch selection
if want twoInlets; then
    c=$(newCase constantKernelDuct submodels_twoInlets)
    cd "$c"
    # two blocks side by side (y), each with its own inlet; walls above and below
    "$COAGULATIONFOAM_PYTHON" - system/blockMeshDict <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
head = s[:s.index("vertices")]
s = head + """vertices
(
    (0 0 0) ($L 0 0) ($L $h 0) (0 $h 0) (0 0 $h) ($L 0 $h) ($L $h $h) (0 $h $h)
    ($L 0.008 0) (0 0.008 0) ($L 0.008 $h) (0 0.008 $h)
);
blocks
(
    hex (0 1 2 3 4 5 6 7) (50 1 1) simpleGrading (1 1 1)
    hex (3 2 8 9 7 6 10 11) (50 1 1) simpleGrading (1 1 1)
);
boundary
(
    inletA { type patch; faces ((0 4 7 3)); }
    inletB { type patch; faces ((3 7 11 9)); }
    outlet { type patch; faces ((1 2 6 5) (2 8 10 6)); }
    walls  { type wall;  faces ((0 1 5 4) (9 11 10 8)); }
    sides  { type empty; faces ((0 3 2 1) (4 5 6 7) (3 9 8 2) (7 6 10 11)); }
);
"""
open(p, "w").write(s)
PY
    rm -rf constant/polyMesh log.blockMesh
    runApplication blockMesh
    setEntry . 0/U boundaryField "{ inletA { type fixedValue; value uniform (1 0 0); } inletB { type fixedValue; value uniform (1 0 0); } outlet { type zeroGradient; } walls { type noSlip; } sides { type empty; } }"
    setEntry . constant/coagulationProperties inception/rate 0
    setEntry . constant/coagulationProperties inflow/patches "(inletA inletB)"
    setEntry . constant/coagulationProperties inflow/density 1e7
    setEntry . constant/coagulationProperties statisticalWeight/n 1024
    setEntry . constant/coagulationProperties sampling/tRelax 0
    setEntry . system/controlDict endTime 0.05
    setEntry . system/controlDict writeInterval 0.05
    runSolver twoInlets
    checkBalance log.coagulationFoam
    "$COAGULATIONFOAM_PYTHON" - "$(samples "$c")" <<'PY' || fail "twoInlets: a row's inflow is not c_in"
import sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], "r")
x, y = f["cellCentres"][:, 0], f["cellCentres"][:, 1]
M1 = f["moments"][-1, :, 1]
ok = True
for name, row in (("inletA", y < 0.004), ("inletB", y > 0.004)):
    m = M1[row & (x < 0.04)].mean() / 1e7
    print("twoInlets: row of %s, x < 0.04: M1/c_in = %.3f" % (name, m))
    ok = ok and abs(m - 1) < 0.15
sys.exit(0 if ok else 1)
PY
    passed=$((passed + 1)); echo "ok twoInlets"
fi

# ---- cellZone: inception in a zone only
if want cellZone; then
    c=$(newCase constantKernelDuct submodels_cellZone)
    cd "$c"
    cat > system/topoSetDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object topoSetDict; }
actions
(
    { name flame; type cellZoneSet; action new; source boxToCell; sourceInfo { box (0.1 -1 -1) (1 1 1); } }
);
DICT
    runApplication topoSet
    setEntry . constant/coagulationProperties inception/cellZone flame
    setEntry . constant/coagulationProperties sampling/tRelax 0
    setEntry . system/controlDict endTime 0.02
    setEntry . system/controlDict writeInterval 0.02
    runSolver cellZone
    checkBalance log.coagulationFoam
    grep -q "inception rate 300000000 in 25 cells" log.coagulationFoam || fail "cellZone: the log does not say 25 inception cells"
    "$COAGULATIONFOAM_PYTHON" - "$(samples "$c")" <<'PY' || fail "cellZone: particles upstream of the zone"
import sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], "r")
x = f["cellCentres"][:, 0]
M0 = f["moments"][:, :, 0]
# downstream of x = 0.12 every cell holds ~20 or more particles born in the zone
up, zone = M0[:, x < 0.1], M0[-1, x > 0.12]
print("cellZone: largest M0 upstream of the zone %g (every sample), smallest at x > 0.12 %g" % (up.max(), zone.min()))
sys.exit(0 if up.max() == 0 and zone.min() > 0 else 1)
PY
    passed=$((passed + 1)); echo "ok cellZone"
fi

# ---- weights: W = Vref/(n V1) with each algorithm's V1
if want weights; then
    for alg in SWA DSA1 DSA2; do
        c=$(newCase constantKernelDuct submodels_weights_$alg)
        cd "$c"
        setEntry . constant/coagulationProperties algorithm $alg
        setEntry . constant/coagulationProperties sampling/tRelax 0
        setEntry . system/controlDict endTime 0.005
        setEntry . system/controlDict writeInterval 0.005
        runSolver "weights $alg"
        checkBalance log.coagulationFoam
        V1=$(foamDictionary -entry statisticalWeight/V1/$alg -value constant/coagulationProperties)
        "$COAGULATIONFOAM_PYTHON" - "$(samples "$c")" "$alg" "$V1" <<'PY' || fail "weights: $alg"
import sys
import h5py
f = h5py.File(sys.argv[1], "r")
alg, V1 = sys.argv[2], float(sys.argv[3])
W = 0.004**3 / (256 * V1)
a = f.attrs
print("weights %s: V1 %g (input %g), particleWeight %.17g (Vref/(n V1) = %.17g)"
      % (alg, a["V1"], V1, a["particleWeight"], W))
sys.exit(0 if a["V1"] == V1 and abs(a["particleWeight"] / W - 1) < 1e-12 else 1)
PY
    done
    passed=$((passed + 1)); echo "ok weights"
fi

# ---- threeRanks: arrivals on a rank with two processor patches
if want threeRanks; then
    c=$(newCase constantKernelDuct submodels_threeRanks)
    cd "$c"
    setEntry . 0/U internalField "uniform (0 0 0)"
    setEntry . 0/U boundaryField/inlet/value "uniform (0 0 0)"
    setEntry . constant/coagulationProperties kernel/K0 1e-30
    setEntry . constant/coagulationProperties statisticalWeight/n 64
    setEntry . constant/coagulationProperties sampling/tRelax 0
    foamDictionary -entry dispersion -add "{ type constant; D 1e-3; }" constant/coagulationProperties > /dev/null
    setEntry . system/controlDict deltaT 1e-3
    setEntry . system/controlDict endTime 0.5
    setEntry . system/controlDict writeInterval 0.5
    setEntry . system/decomposeParDict numberOfSubdomains 3
    setEntry . system/decomposeParDict coeffs/n "(3 1 1)"
    runApplication decomposePar
    # at most 120 s, as runSolver (3 ranks on fewer cores: the ranks yield when idle)
    OMPI_MCA_mpi_yield_when_idle=1 timeout 120 mpirun --oversubscribe -np 3 coagulationFoam -parallel \
        > log.coagulationFoam 2>&1 \
        || { tail -20 log.coagulationFoam; fail "threeRanks: coagulationFoam on 3 ranks failed (124: no end within 120 s)"; }
    checkBalance log.coagulationFoam
    "$COAGULATIONFOAM_PYTHON" - "$c" <<'PY' || fail "threeRanks: the profile is not symmetric"
import glob, math, sys
import h5py
import numpy as np
files = sorted(glob.glob(sys.argv[1] + "/postProcessing/coagulationSamples/samples_0_processor*.h5"))
assert len(files) == 3, files
x, N = [], []
for name in files:
    f = h5py.File(name, "r")
    W = float(f.attrs["particleWeight"])
    x.append(f["cellCentres"][:, 0])
    N.append(f["moments"][-1, :, 0] * 0.004**3 / W)   # particles per cell, last sample
x, N = np.concatenate(x), np.concatenate(N)
left, right = N[x < 0.2 / 3].sum(), N[x > 0.4 / 3].sum()
z = (left - right) / math.sqrt(left + right)
print("threeRanks: %d particles in the first third, %d in the last (z = %.2f)" % (left, right, z))
sys.exit(0 if abs(z) <= 4 and left + right > 1000 else 1)
PY
    passed=$((passed + 1)); echo "ok threeRanks"
fi

echo "PASS submodels: $passed cases (rebound, two inlets, cellZone inception, W per algorithm, arrivals on 3 ranks)"
