#!/bin/bash
# Transport without coagulation (K0 = 1e-30), off the paper's special values: a graded mesh
# (cell volumes 0.46..1.85 of the mean), U = 2, inflow of mass 3 and inception of mass 2.
# Every particle keeps its mass, so the steady moments are exact and linear in x,
#     M_k(x) = c_in 3^k + I 2^k x/u,
# and every cell's time average must agree with them within its 95 % interval widened
# (|z| <= 6). The balances must close (masses != 1 are booked), and the sample of the last
# step must equal the fields written at that time (ascii, 17 digits).
. "$(dirname "$0")/caseLib.sh"
cIn=1e7; rate=3e8; u=2

case=$(newCase constantKernelDuct transport)
cd "$case"
sed -i 's/simpleGrading (1 1 1)/simpleGrading (4 1 1)/' system/blockMeshDict
rm -rf constant/polyMesh log.blockMesh
runApplication blockMesh
setEntry . 0/U internalField "uniform ($u 0 0)"
setEntry . 0/U boundaryField/inlet/value "uniform ($u 0 0)"
setEntry . constant/coagulationProperties kernel/K0 1e-30
setEntry . constant/coagulationProperties inception/rate $rate
setEntry . constant/coagulationProperties inception/mass 2
setEntry . constant/coagulationProperties inflow/density $cIn
setEntry . constant/coagulationProperties inflow/mass 3
setEntry . constant/coagulationProperties statisticalWeight/n 1024
setEntry . constant/coagulationProperties sampling/tRelax 0.15
setEntry . system/controlDict endTime 0.35
setEntry . system/controlDict writeInterval 0.35
setEntry . system/controlDict writeFormat ascii
runApplication coagulationFoam
checkBalance log.coagulationFoam
grep "particles in/incepted/out" log.coagulationFoam | tail -1 | awk '{ exit !($4 > 0 && $6 > 0 && $8 > 0) }' \
    || fail "no inflow, inception or outflow"
# The outlet's line adds up to the totals; the inflow booked over [0, 0.35] is Poisson with
# mean c_in Q t/W, Q = u h^2 through the 4 mm square inlet, within 4 standard deviations (the
# per-cell moments below allow |z| <= 6 and pass with 5 % fewer particles entering), and of
# mass 3 each; every particle keeps the weight W (no coagulation)
h=$(foamDictionary -entry h -value system/blockMeshDict)
scale=$(foamDictionary -entry scale -value system/blockMeshDict)
QT=$(awk -v u=$u -v s="$scale" -v h="$h" 'BEGIN { printf "%.17g", u*(s*h)^2*0.35 }')
"$COAGULATIONFOAM_PYTHON" "$testsDir/../python/patchBalance.py" log.coagulationFoam \
    --csv postProcessing/coagulationBalance/patches.csv --equal-weights --inflow $cIn "$QT" 3 \
    || fail "the outlet's line off the totals, or the booked inflow off c_in Q t"

# no coagulation: particles never interact, so samples further apart than a cell transit
# (dx/u <= 3.6e-3 s < the sample interval) are independent; no residence-time window
$report --case . --out results --no-plots --analytic none --correlation-time 0 > log.report \
    || fail "report failed"
"$COAGULATIONFOAM_PYTHON" - . $cIn $rate $u <<'PY' || fail "transport moments or samples wrong"
import glob, re, sys
import h5py
import numpy as np
case, c_in, rate, u = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
bad = []

# 1. time averages against M_k = c_in 3^k + I 2^k x/u in every cell
f = np.genfromtxt(case + "/results/moments_full.csv", delimiter=",", names=True)
x = f["x"]
worst = 0.0
for k in range(4):
    exact = c_in * 3.0**k + rate * 2.0**k * x / u
    se = f["M%d_ci95" % k] / 1.96
    z = (f["M%d_mean" % k] - exact) / se
    worst = max(worst, np.abs(z).max())
    # the run resolves 3 %: its samples' sd / sqrt(count) (the correlated-sample interval
    # of 41 samples is up to ~4 times wider, t with few dof)
    if np.any(np.abs(z) > 6) or np.any(f["M%d_ci95_iid" % k] / 1.96 > 0.03 * exact):
        i = int(np.argmax(np.abs(z)))
        bad.append("M%d: cell x=%.4g mean %.6g exact %.6g (z = %.1f, se %.2g)"
                   % (k, x[i], f["M%d_mean" % k][i], exact[i], z[i], se[i]))
print("transport: %d cells, graded %.3g..%.3g, worst |z| = %.2f" % (len(x), np.diff(x).min(), np.diff(x).max(), worst))
if np.diff(x).max() < 2 * np.diff(x).min():
    bad.append("the mesh is not graded")

# 2. the last sample is the state the fields were written from
h = h5py.File(glob.glob(case + "/postProcessing/coagulationSamples/samples_0.h5")[0], "r")
t, m = h["time"][:], h["moments"][:]
if abs(t[-1] - 0.35) > 1e-9:
    bad.append("last sample at t = %g, not 0.35" % t[-1])
for k in range(4):
    text = open("%s/0.35/M%d" % (case, k)).read()
    body = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\(([^)]*)\)", text).group(1)
    field = np.array(body.split(), dtype=float)
    if field.shape != m[-1, :, k].shape or not np.array_equal(field, m[-1, :, k]):
        d = np.abs(field - m[-1, :, k]) / np.abs(field).max() if field.shape == m[-1, :, k].shape else None
        bad.append("0.35/M%d differs from the sample at t = 0.35 (largest rel. diff %s)"
                   % (k, None if d is None else "%.3g" % d.max()))
print("\n".join(bad) if bad else "last sample = written fields M0..M3")
sys.exit(1 if bad else 0)
PY
echo "PASS transport: balances closed, M0..M3 = c_in 3^k + I 2^k x/u in every cell, samples = fields"
