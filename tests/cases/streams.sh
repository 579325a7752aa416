#!/bin/bash
# The random streams: every cell of every processor, at every step, draws its own numbers
# (streamSeed mixes seed, processor, cell, time index, purpose). With U = 0 and K0 = 1e-30 a
# cell is a box of pure inception: its particle count N = M0 V/W is a Poisson process of
# rate I V/W, independent of every other cell's. So
#   - no two cells (on one processor, or the same local cell on two processors) have the
#     same count series (a seed without the cell or the processor makes them equal);
#   - across the 50 cells var(N)/mean(N) is 1 (a seed without the time index repeats one
#     step's draws every step: var/mean ~ the number of steps); with the fixed seed 1 it
#     must lie in [0.5, 1.8] (chi2(49)/49 falls outside with probability 0.18 %);
#   - mean(N) is the Poisson mean I V T/W (within 5 standard errors);
#   - every processor's particle weight is W = Vref/(n V1) with Vref = the mean cell volume
#     over the whole mesh, not over a processor's cells.
. "$(dirname "$0")/caseLib.sh"

setUp()
{
    setEntry . 0/U internalField "uniform (0 0 0)"
    setEntry . 0/U boundaryField/inlet/value "uniform (0 0 0)"
    setEntry . constant/coagulationProperties kernel/K0 1e-30
    setEntry . constant/coagulationProperties statisticalWeight/n 1024
    setEntry . constant/coagulationProperties sampling/tRelax 0
    setEntry . system/controlDict endTime 0.05
    setEntry . system/controlDict writeInterval 0.05
}

serial=$(newCase constantKernelDuct streams_serial)
cd "$serial"
setUp
runApplication coagulationFoam
checkBalance log.coagulationFoam

parallel=$(newCase constantKernelDuct streams_parallel)
cd "$parallel"
setUp
runApplication decomposePar
runParallel -np 2 coagulationFoam
checkBalance log.coagulationFoam

"$COAGULATIONFOAM_PYTHON" - "$serial" "$parallel" <<'PY' || fail "random streams not independent"
import glob, sys
import h5py
import numpy as np
serial, parallel = sys.argv[1], sys.argv[2]
I, n, V1, dt, T = 3e8, 1024, 1.25e-8, 1e-4, 0.05
V = 4e-3 ** 3                       # every cell of the duct; Vref = V
W = V / (n * V1)
bad = []

def counts(path):
    f = h5py.File(path, "r")
    w = float(f.attrs["particleWeight"])
    if abs(w / W - 1) > 1e-12:
        bad.append("%s: particleWeight %.17g, expected Vref/(n V1) = %.17g" % (path, w, W))
    N = f["moments"][:, :, 0] * V / w              # [sample][cell]
    if np.abs(N - np.round(N)).max() > 1e-6:
        bad.append("%s: M0 V/W is not a particle count" % path)
    return np.round(N).astype(np.int64).T          # [cell][sample]

def same_rows(a, b=None):
    if b is None:
        return [(i, j) for i in range(len(a)) for j in range(i + 1, len(a)) if np.array_equal(a[i], a[j])]
    return [(i, i) for i in range(len(a)) if np.array_equal(a[i], b[i])]

N = counts(glob.glob(serial + "/postProcessing/coagulationSamples/samples_0.h5")[0])
if N.shape != (50, 10):
    bad.append("serial samples %s, expected 50 cells x 10" % (N.shape,))
final = N[:, -1].astype(float)
mean, disp = final.mean(), final.var(ddof=1) / final.mean()
expected = I * V * T / W
print("serial: mean count %.2f (Poisson mean %.2f), var/mean %.3f" % (mean, expected, disp))
if abs(mean - expected) > 5 * np.sqrt(expected / len(final)):
    bad.append("mean count %.2f, expected %.2f" % (mean, expected))
if not 0.5 <= disp <= 1.8:
    bad.append("var/mean of the counts %.3f: the steps' draws are not independent" % disp)
pairs = same_rows(N)
if pairs:
    bad.append("%d pairs of cells with the same count series, e.g. %s" % (len(pairs), pairs[:3]))

p = [counts(f) for f in sorted(glob.glob(parallel + "/postProcessing/coagulationSamples/samples_0_processor*.h5"))]
if len(p) != 2:
    bad.append("%d processor sample files, expected 2" % len(p))
else:
    for i, q in enumerate(p):
        if same_rows(q):
            bad.append("processor %d: cells with the same count series" % i)
    pairs = same_rows(p[0], p[1])
    print("parallel: %d of %d local cells with the same series on both processors" % (len(pairs), len(p[0])))
    if pairs:
        bad.append("%d local cells have the same count series on both processors" % len(pairs))
print("\n".join(bad) if bad else "streams independent, weights Vref/(n V1)")
sys.exit(1 if bad else 0)
PY
echo "PASS streams: cells, processors and steps draw independent numbers; W = Vref/(n V1) on every processor"
