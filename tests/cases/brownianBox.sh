#!/bin/bash
# A closed box at rest whose temperature rises linearly, 300 K to 900 K across it (x), with
# the transition Brownian kernel on the cell's T: every cell is a closed cell at its own
# temperature. 6 x 16 cells, 1000 particles of 10 nm (1800 kg/m3) per cell at 1e17 per m3;
# at t = 0.005 and 0.01 s each column's M0, over its 16 independent cells, against the
# discrete Smoluchowski reference at the column's T (plugFlowReference along a gas at rest
# in time: a constant-T axis crossed at 1 m/s), a 99.9 % t-interval; M1
# exact in every cell (nothing moves, no source). ${1:-T}: the temperature entry (a planted
# bug runs it with a uniform one, 'T 600', and must fail).
. "$(dirname "$0")/caseLib.sh"
tEntry="${1:-T}"
reference="$COAGULATIONFOAM_BUILD/applications/studies/plugFlowReference"
[ -x "$reference" ] || fail "no $reference (./Allwmake)"
# the case writers and readers of the random-walk tests (dispersionCases.py)
export PYTHONPATH="$COAGULATIONFOAM_DIR/tests/cases:$COAGULATIONFOAM_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}"

c=$(newCase constantKernelDuct brownianBox)
cd "$c"
rm -rf constant/polyMesh log.blockMesh
"$COAGULATIONFOAM_PYTHON" - <<'PY'
from dispersionCases import HEADER, block_mesh, zero_velocity
nx, ny = 6, 16
patches = {"walls": ("wall", ["left", "right", "bottom", "top"]),
           "frontAndBack": ("empty", ["frontAndBack"])}
open("system/blockMeshDict", "w").write(block_mesh(nx, ny, 6e-3, 16e-3, patches))
open("0/U", "w").write(zero_velocity(patches))
# T linear in x, 300 K in the first column of cells and 900 K in the last
T = [300.0 + 600.0 * i / (nx - 1) for j in range(ny) for i in range(nx)]
open("0/T", "w").write(HEADER.format(cls="volScalarField", obj="T")
    + "dimensions [0 0 0 1 0 0 0];\ninternalField nonuniform List<scalar> %d (%s);\n"
      "boundaryField\n{\n    walls { type zeroGradient; }\n    frontAndBack { type empty; }\n}\n"
    % (len(T), " ".join(repr(t) for t in T)))
open("constant/coagulationProperties", "w").write(HEADER.format(cls="dictionary", obj="coagulationProperties") + """
algorithm SWA;
splitting Lie;
kernel { type Brownian; regime transition; T TENTRY; p 1e5; }
particles { density 1800; massUnit 9.42e-22; }
inception { rate 0; mass 1; }
statisticalWeight { n 1000; V1 1e-17; }
seed 11;
sampling { tRelax 1; sampleInterval 0.001; }
initialPopulation { numberDensity 1e17; mass 1; }
""")
PY
sed -i "s/TENTRY/$tEntry/" constant/coagulationProperties
runApplication blockMesh
setEntry . system/controlDict deltaT 0.001
setEntry . system/controlDict endTime 0.01
setEntry . system/controlDict writeInterval 0.005
setEntry . system/controlDict writeFormat ascii
foamDictionary -entry functions -remove system/controlDict > /dev/null 2>&1 || true
runApplication coagulationFoam
checkBalance log.coagulationFoam
# each column's closed cell: a parcel at the column's T crossing x = t at U = 1 m/s
for T in 300 420 540 660 780 900; do
    mkdir -p "reference/$T"
    printf '0 %s 1e5 1\n0.005 %s 1e5 1\n0.01 %s 1e5 1\n' $T $T $T > "reference/$T/axis"
    "$reference" "reference/$T/axis" "reference/$T" --density 1800 --massUnit 9.42e-22 \
        --n0 1e17 --regime transition --L 200 > /dev/null || fail "plugFlowReference failed at $T K"
done
"$COAGULATIONFOAM_PYTHON" - <<'PY' || fail "a column is off the closed-cell solution at its temperature"
import sys
import numpy as np
from scipy import stats
from dispersionCases import read_field
nx, ny = 6, 16
ok = True
for t in ("0.005", "0.01"):
    m0 = np.broadcast_to(read_field(".", t, "M0"), nx * ny).reshape(ny, nx)
    m1 = np.broadcast_to(read_field(".", t, "M1"), nx * ny).reshape(ny, nx)
    if np.max(np.abs(m1 / 1e17 - 1)) > 1e-12:
        print("M1 not conserved at", t, m1.min(), m1.max()); ok = False
    for i in range(nx):
        T = 300.0 + 600.0 * i / (nx - 1)
        ref = np.genfromtxt("reference/%d/plugFlow.csv" % round(T), delimiter=",", names=True)
        r = ref["M0"][np.abs(ref["t"] - float(t)) < 1e-12][0]
        col = m0[:, i]
        se = col.std(ddof=1) / np.sqrt(ny)
        half = stats.t.ppf(0.9995, ny - 1) * se
        z = (col.mean() - r) / se
        good = abs(col.mean() - r) <= half
        ok &= good
        print("t %s T %5.0f K: M0 %.5e +- %.2e, reference %.5e (z = %+.2f) %s"
              % (t, T, col.mean(), half, r, z, "ok" if good else "OFF"))
sys.exit(0 if ok else 1)
PY
echo "PASS brownianBox: each column at the closed-cell solution of its temperature"
