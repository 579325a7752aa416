#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Strong scaling on the 2-D sheared box of the scale issue (19; makeScaleBox: 500 cells,
# constant kernel, inception everywhere, about 50 k particles): a serial start of WARM steps
# writes the work per cell over its second half (cloudFunctions { work { type cellWork; } }),
# then every
# configuration goes on from there for STEPS steps:
#   1x1          1 rank, 1 thread            (the serial array path)
#   1x2          1 rank, 2 threads
#   2x1simple    2 ranks x 1 thread, decomposePar simple (2 1 1): equal cell counts
#   2x1work      2 ranks x 1 thread, hierarchical (2 1 1) with weightField coagulationWork
#   2x1cloudMove 2x1work moving with Cloud::move (coagulationCloudMove 1)
#   2x1cut       2 ranks x 1 thread, method manual from workDecomposition: the smallest
#                largest share of coagulationWork (not in the default set)
#   2x1runs      2x1cut with runsPerPart 3: up to 6 runs of cells dealt to the 2 ranks
#                (not in the default set)
# in ROUNDS alternated rounds. Prints per run: wall s, transport and coagulation ms per step
# (the slowest rank), moves/s per rank (and in brackets without the time waited in the
# exchanges' collectives), work and wall balance (max/mean over ranks), particles
# sent per step and kB received per step, and the particle count and mass at the end.
#   tests/benchmarks/parallelScaling.sh [OUTDIR] [ROUNDS=3] [STEPS=1000] [WARM=600] [n=160]
#   CASE=additiveDuct ...       the additive-kernel duct tutorial instead (deltaT 4e-4; the
#                               issue's n = 8192: ... 2 250 250 8192)
#   CONFIGS="1x1 2x1work" ...   a subset of the configurations
#   EVENTCOST=0.53 ...          cellWork's eventCost for the weights (default 1)
#   SAMPLE=1 ...                statistics instead of speed alone: every run samples the
#                               moments from the start time on and has its own seed (an
#                               independent continuation of the common start), and each
#                               configuration's per-cell time averages (coagulationReport,
#                               intervals that see the samples' correlation) are compared with
#                               the 1x1 run of the same round: |difference| / standard error
#                               of the difference, the largest per moment. Continuations of
#                               one start state are positively correlated, so the test is
#                               conservative. The sampling costs time: do not mix these walls
#                               with those of runs without it.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../../etc/functions"
. "$here/scaleBox.sh"
out="${1:-/tmp/parallelScaling}"; rounds="${2:-3}"; steps="${3:-1000}"; warm="${4:-600}"
n="${5:-160}"
# ranks yield their core while they wait, as runParallel (etc/functions) lets them
export OMPI_MCA_mpi_yield_when_idle="${OMPI_MCA_mpi_yield_when_idle:-1}"
mpirunCmd=(mpirun -np 2)
[ "$(id -u)" = 0 ] && mpirunCmd=(mpirun --allow-run-as-root -np 2)
rm -rf "$out"; mkdir -p "$out"
base="$out/base"
if [ "${CASE:-box}" = additiveDuct ]; then
    cp -r "$COAGULATIONFOAM_DIR/tutorials/additiveKernelDuct" "$base"
    (cd "$base" && cleanCase && runApplication blockMesh > /dev/null \
        && foamDictionary -entry functions -remove system/controlDict > /dev/null \
        && foamDictionary -entry sampling/tRelax -set 100 constant/coagulationProperties > /dev/null)
    dt=4e-4
else
    makeScaleBox "$base"
    dt=1e-3
fi
cd "$base"
t0=$(awk -v s="$warm" -v d="$dt" 'BEGIN { print s * d }')
t1=$(awk -v s="$warm" -v m="$steps" -v d="$dt" 'BEGIN { print (s + m) * d }')
foamDictionary -entry endTime -set "$t0" system/controlDict > /dev/null
# two writes: the weights written at the second average over its half of the start
foamDictionary -entry writeInterval -set "$(awk -v s="$warm" -v d="$dt" 'BEGIN { print s * d / 2 }')" system/controlDict > /dev/null
foamDictionary -entry statisticalWeight/n -set "$n" constant/coagulationProperties > /dev/null
foamDictionary -entry cloudFunctions -add "{ work { type cellWork; ${EVENTCOST:+eventCost $EVENTCOST;} } }" \
    constant/coagulationProperties > /dev/null
OMP_NUM_THREADS=2 coagulationFoam > log.warm 2>&1 || { tail log.warm; exit 1; }
foamDictionary -entry endTime -set "$t1" system/controlDict > /dev/null
if [ "${SAMPLE:-0}" = 1 ]; then
    # the averages start where the configurations do (a time before t0 would pull in the
    # start's samples, common to all)
    foamDictionary -entry sampling/tRelax -set "$t0" constant/coagulationProperties > /dev/null
fi
# writeInterval counts from the start time
foamDictionary -entry writeInterval -set "$(awk -v m="$steps" -v d="$dt" 'BEGIN { print m * d }')" system/controlDict > /dev/null

setDecomposition()
{
    cat > system/decomposeParDict <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method $1;
coeffs { n (2 1 1); }
$2
DICT
    [ "${3:-}" = skip ] && return 0
    decomposePar -latestTime -force > log.decomposePar 2>&1 || { tail log.decomposePar; exit 1; }
}

printf "%-13s %3s %8s %10s %10s %10s %8s %8s %9s %8s %9s %12s\n" config round wall_s \
    coag_ms transp_ms moves/s/rk workBal wallBal sent/step kB/step particles mass | tee "$out/runs.txt"
for r in $(seq 1 "$rounds"); do
    for config in ${CONFIGS:-1x1 2x1work 1x2 2x1simple 2x1cloudMove}; do
        c="$out/${config}_$r"
        cp -r "$base" "$c"
        cd "$c"
        case "$config" in
            1x*) ;;
            2x1simple) setDecomposition simple "" ;;
            2x1cut|2x1runs)
                runs=1; [ "$config" = 2x1runs ] && runs=3
                setDecomposition manual "workDecompositionCoeffs { n (2 1 1); runsPerPart $runs; }" skip
                sed -i 's/^coeffs .*/coeffs { dataFile "cellDecomposition"; }/' system/decomposeParDict
                workDecomposition -latestTime > log.workDecomposition 2>&1 \
                    || { tail log.workDecomposition; exit 1; }
                decomposePar -latestTime -force > log.decomposePar 2>&1 || { tail log.decomposePar; exit 1; }
                ;;
            *) setDecomposition hierarchical "weightField coagulationWork;" ;;
        esac
        if [ "${SAMPLE:-0}" = 1 ]; then
            # one seed per run: round r, configuration k -> 1000 r + k + 2 (the start's is 1)
            k=0; for x in ${CONFIGS:-1x1 2x1work 1x2 2x1simple 2x1cloudMove}; do
                [ "$x" = "$config" ] && break; k=$((k + 1)); done
            foamDictionary -entry seed -set $((1000 * r + k + 2)) constant/coagulationProperties > /dev/null
        fi
        [ "$config" = 2x1cloudMove ] && \
            foamDictionary -entry OptimisationSwitches -add "{ coagulationCloudMove 1; }" system/controlDict > /dev/null
        start=$(date +%s.%N)
        case "$config" in
            1x1) OMP_NUM_THREADS=1 coagulationFoam > log 2>&1 ;;
            1x2) OMP_NUM_THREADS=2 coagulationFoam > log 2>&1 ;;
            *) OMP_NUM_THREADS=1 "${mpirunCmd[@]}" coagulationFoam -parallel > log 2>&1 ;;
        esac || { tail log; exit 1; }
        wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
        "$COAGULATIONFOAM_PYTHON" - "$config" "$r" "$wall" log <<'PY' | tee -a "$out/runs.txt"
import re, sys
config, r, wall, log = sys.argv[1:5]
text = open(log).read()
coag, transp = map(float, re.findall(r"coagulation += ([\d.e+-]+) ms, transport = ([\d.e+-]+) ms", text)[-1])
particles = int(re.findall(r"particles in domain += (\d+)", text)[-1])
mass = float(re.findall(r"mass in domain += ([\d.e+-]+)", text)[-1])
err = float(re.findall(r"mass balance error \(rel.\) += ([\d.e+-]+)", text)[-1])
assert abs(err) < 1e-10, "mass balance error %g" % err
rows = re.findall(r"processor\d+: (.*)", text.split("Per processor")[-1]) if "Per processor" in text else []
if rows:
    vals = [list(map(float, row.split())) for row in rows[:2]]
    coag = max(v[2] for v in vals); transp = max(v[3] for v in vals)
    mps = "/".join("%.2fM" % (v[4] / 1e6) for v in vals)
    if len(vals[0]) > 9:   # and without the exchanges' wait (builds with the column)
        mps += "(" + "/".join("%.2f" % (v[9] / 1e6) for v in vals) + ")"
    wb = float(re.findall(r"work balance \(max/mean\) += ([\d.e+-]+)", text)[-1])
    lb = float(re.findall(r"wall balance \(max/mean\) += ([\d.e+-]+)", text)[-1])
    sent = sum(v[5] for v in vals); kb = sum(v[6] for v in vals)
else:
    mps = "%.2fM" % (float(re.findall(r"particle moves per second += ([\d.e+-]+)", text)[-1]) / 1e6)
    wb = lb = 1.0; sent = kb = 0.0
print("%-13s %3s %8s %10.3f %10.3f %10s %8.3f %8.3f %9.1f %8.2f %9d %12.6g"
      % (config, r, wall, coag, transp, mps, wb, lb, sent, kb, particles, mass))
PY
        if [ "${SAMPLE:-0}" = 1 ]; then
            "$COAGULATIONFOAM_PYTHON" "$COAGULATIONFOAM_DIR/applications/utilities/coagulationReport/coagulationReport.py" \
                --case . --out results --no-plots > log.report 2>&1 || { tail log.report; exit 1; }
        fi
        cd "$out"
    done
done
if [ "${SAMPLE:-0}" = 1 ]; then
    echo "per-cell time averages against the 1x1 run of the same round (largest |z| per moment):"
    "$COAGULATIONFOAM_PYTHON" - "$out" "$rounds" ${CONFIGS:-1x1 2x1work 1x2 2x1simple 2x1cloudMove} <<'PY' | tee "$out/statistics.txt"
import sys
import numpy as np
from coagulationPost import report
out, rounds, configs = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
def load(c, r):
    # the cells in the report's order, by their centres (moments_full.csv has x, y and z)
    d = np.genfromtxt("%s/%s_%d/results/moments_full.csv" % (out, c, r), delimiter=",", names=True)
    return d[report.cell_order(np.column_stack((d["x"], d["y"], d["z"])))]
allz = {}
for r in range(1, rounds + 1):
    ref = load("1x1", r)
    for c in configs:
        if c == "1x1":
            continue
        m = load(c, r)
        for a in "xyz":
            assert np.allclose(m[a], ref[a], atol=1e-9), "different cells"
        zs = []
        for k in range(4):
            se = np.hypot(m["M%d_ci95" % k], ref["M%d_ci95" % k]) / 1.96
            ok = se > 0
            zs.append(np.abs(m["M%d_mean" % k] - ref["M%d_mean" % k])[ok] / se[ok])
        allz.setdefault(c, []).extend(np.concatenate(zs))
        print("  %-13s round %d: largest |z| M0..M3 %s over %d cells"
              % (c, r, " ".join("%.2f" % z.max() for z in zs), len(ref["x"])))
for c, z in allz.items():
    z = np.asarray(z)
    print("  %-13s all rounds: %d comparisons, %d with |z| > 3 (%.1f expected of a normal), largest %.2f"
          % (c, len(z), int((z > 3).sum()), 0.0027 * len(z), z.max()))
PY
fi
echo "median wall per configuration, and speedup against 1x1:"
"$COAGULATIONFOAM_PYTHON" - "$out/runs.txt" <<'PY'
import sys
import numpy as np
rows = [l.split() for l in open(sys.argv[1]).read().splitlines()[1:] if l.strip()]
walls = {}
for r in rows:
    walls.setdefault(r[0], []).append(float(r[2]))
ref = np.median(walls["1x1"])
for k, w in walls.items():
    print("  %-13s %8.2f s  speedup %.2f  (%d runs: %s)"
          % (k, np.median(w), ref / np.median(w), len(w), " ".join("%.1f" % x for x in w)))
PY
