#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# The pitzDaily tutorial from its own Allrun, reduced (60 simpleFoam iterations, 200
# particle steps): OpenFOAM's tutorial copied, the flow, coagulationFoam, foamToVTK, the
# report. The balances close; the report draws the 2-D maps (in diameter: the case's
# material reaches it through the samples) and the two lines: the line
# across the channel runs from wall to wall through contiguous cells, and every line cell
# holds its cell's statistics of moments_full.csv; ParaView's picture where pvbatch made one.
. "$(dirname "$0")/caseLib.sh"

c=$(tutorialCase pitzDaily pitzDaily -all)
cd "$c"
openfoamTutorial incompressible/simpleFoam/pitzDaily flow
setEntry flow system/controlDict endTime 60
setEntry flow system/controlDict writeInterval 60
setEntry . system/controlDict endTime 0.01
setEntry . system/controlDict writeInterval 0.01
setEntry . constant/coagulationProperties sampling/tRelax 0.004
setEntry . constant/coagulationProperties sampling/sampleInterval 5e-4
runAllrun
checkBalance log.coagulationFoam
for f in maps.png maps.csv line1.png line1.csv line2.png line2.csv; do
    [ -s "results/$f" ] || fail "no results/$f"
done
[ ! -e results/moments.png ] || fail "profiles along x drawn for a 2-D case"
# the case's material reaches the report through the samples: the maps in diameter, the
# smallest that of the entering 10 nm particles
"$COAGULATIONFOAM_PYTHON" - <<'PY' || fail "the maps' diameters"
import numpy as np
rows = np.genfromtxt("results/maps.csv", delimiter=",", names=True, skip_header=2)
d = rows["meanDiameter"][np.isfinite(rows["meanDiameter"])]
print("diameter of the mean mass: %.4f .. %.4f nm" % (d.min(), d.max()))
raise SystemExit(0 if abs(d.min() - 9.9983) < 1e-3 and d.max() < 20 else 1)
PY
# ParaView's picture where pvbatch ran without error (a failed one is a note: case_paraview
# checks the pictures)
if grep -q "^Running pvbatch coagulationView.py" log.Allrun \
    && ! grep -q "^NOTE: no ParaView picture" log.Allrun; then
    [ -s results/paraview.png ] || fail "pvbatch succeeded but wrote no results/paraview.png"
fi
"$COAGULATIONFOAM_PYTHON" - <<'PY' || fail "the lines"
import numpy as np
full = np.genfromtxt("results/moments_full.csv", delimiter=",", names=True)
key = {tuple(np.round([r["x"], r["y"], r["z"]], 9)): r for r in full}
good = True
for name, length in (("line1", 0.0508), ("line2", 0.3106)):
    rows = np.atleast_1d(np.genfromtxt("results/%s.csv" % name, delimiter=",", names=True,
                                       skip_header=1))
    ref = [key[tuple(np.round([r["x"], r["y"], r["z"]], 9))] for r in rows]
    ok = (len(rows) > 20 and np.isclose(rows["s_in"][0], 0, atol=1e-9)
          and np.isclose(rows["s_out"][-1], length, rtol=1e-6)
          and np.allclose(rows["s_in"][1:], rows["s_out"][:-1], rtol=0, atol=1e-9)
          and np.allclose(rows["M0"], [r["M0_mean"] for r in ref], rtol=1e-9)
          and np.allclose(rows["M0_ci95"], [r["M0_ci95"] for r in ref], rtol=1e-9))
    print("%s: %d cells from s = %g to %g, contiguous, M0 and its interval as moments_full.csv: %s"
          % (name, len(rows), rows["s_in"][0], rows["s_out"][-1], "ok" if ok else "FAIL"))
    good &= ok
raise SystemExit(0 if good else 1)
PY
echo "PASS pitzDaily: the tutorial's pipeline, its maps and lines"
