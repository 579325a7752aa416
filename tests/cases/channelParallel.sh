#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# The turbulent channel tutorial from the real pipeline, coarsened (50 x 10 x 10 cells, a
# 0.2 s run): simpleFoam -> coagulationFoam with cellPoint velocity, turbulent dispersion
# and stick walls, in serial and decomposed on 2 ranks. Both close their mass
# balance with deposition; the two runs are independent realisations (the streams are
# keyed by processor), so their time-averaged moments agree within the runs' intervals
# cell by cell (at most 15 % of the cell-moments outside the 95 % intervals of the
# difference, none beyond 5 standard errors), and so do the particles deposited on each
# wall and leaving through the outlet after the flush (Poisson intervals, |z| < 4). The
# report's slices and line of the decomposed run hold the cells' own statistics.
. "$(dirname "$0")/caseLib.sh"

serial="$workDir/channel_serial"
rm -rf "$serial"; mkdir -p "$workDir"
cp -r "$COAGULATIONFOAM_DIR/tutorials/turbulentChannel" "$serial"
cd "$serial"
cleanCase; rm -rf 0 results; (cd flow && cleanCase && rm -rf 0)
for d in system flow/system; do
    sed -i 's/(100 20 20)/(50 10 10)/' $d/blockMeshDict
done
setEntry flow system/controlDict endTime 250
setEntry flow system/controlDict writeInterval 250
setEntry . system/controlDict endTime 0.2
setEntry . system/controlDict writeInterval 0.2
(cd flow && cp -r 0.orig 0 && runApplication blockMesh && runApplication simpleFoam) >&2
parallel="$workDir/channel_parallel"
rm -rf "$parallel"; cp -r "$serial" "$parallel"

runApplication blockMesh
runApplication topoSet
latest=$(cd flow && foamListTimes -latestTime -noZero)
rm -rf 0 && mkdir 0 && for f in U nut k epsilon; do cp "flow/$latest/$f" 0/; done
cp -r 0 "$parallel/"
runApplication coagulationFoam
checkBalance log.coagulationFoam
grep -q "deposited lowerWall" log.coagulationFoam || fail "serial: nothing deposited"
$report --case . --out results --no-plots --analytic none > log.report || fail "serial report"

cd "$parallel"
runApplication blockMesh
runApplication topoSet
runApplication decomposePar
runParallel -np 2 coagulationFoam
checkBalance log.coagulationFoam
ls postProcessing/coagulationSamples/*processor1.h5 > /dev/null || fail "no per-processor samples"
$report --case . --out results --no-plots --analytic none > log.report || fail "parallel report"

"$COAGULATIONFOAM_PYTHON" - "$serial" "$parallel" <<'PY' || fail "serial and decomposed runs differ"
import csv, sys
import numpy as np
ser, par = sys.argv[1], sys.argv[2]
a = np.genfromtxt(ser + "/results/moments_full.csv", delimiter=",", names=True)
b = np.genfromtxt(par + "/results/moments_full.csv", delimiter=",", names=True)
ka = {tuple(np.round([r["x"], r["y"], r["z"]], 9)): i for i, r in enumerate(a)}
pairs = [(ka[k], j) for j, r in enumerate(b)
         if (k := tuple(np.round([r["x"], r["y"], r["z"]], 9))) in ka]
ia, ib = np.array(pairs).T
zs = []
for k in range(4):
    ma, mb = a["M%d_mean" % k][ia], b["M%d_mean" % k][ib]
    se = np.hypot(a["M%d_ci95" % k][ia], b["M%d_ci95" % k][ib]) / 1.96
    ok = np.isfinite(se) & (se > 0) & (a["M%d_neff" % k][ia] > 10) & (b["M%d_neff" % k][ib] > 10)
    z = (ma - mb)[ok] / se[ok]
    zs.append(z)
    print("M%d: %d cells, %.1f %% outside 95 %%, largest |z| %.2f, mean z %+.2f"
          % (k, ok.sum(), 100 * np.mean(np.abs(z) > 1.96), np.abs(z).max(), z.mean()))
z = np.concatenate(zs)
good = np.mean(np.abs(z) > 1.96) <= 0.15 and np.abs(z).max() < 5 and len(z) > 1000

def left(case):
    rows = list(csv.DictReader(open(case + "/postProcessing/coagulationBalance/patches.csv")))
    times = sorted({float(r["time"]) for r in rows})
    return {r["patch"]: float(r["particles"]) for r in rows if float(r["time"]) == times[-1]}
la, lb = left(ser), left(par)
for p in ("lowerWall", "upperWall", "sideWalls", "outlet"):
    n1, n2 = la.get(p, 0), lb.get(p, 0)
    zz = (n1 - n2) / np.sqrt(max(n1 + n2, 1))
    print("%s: serial %d, decomposed %d computational particles, z = %+.2f" % (p, n1, n2, zz))
    good &= abs(zz) < 4 and n1 > 50
sys.exit(0 if good else 1)
PY
# The report's pictures of a 3-D mesh, on the decomposed run (its samples merged in another
# order than the mesh's cells): the default slice (through the middle, across the thinnest
# extent), a slice across the channel on a layer of faces, and a line along its axis; each
# CSV holds the cells' own values of moments_full.csv, the slice's colour ranges are its
# cells' ranges, the line's cells tile it in order
$report --case . --out pictures --analytic none > log.reportDefault || fail "default pictures"
[ -f pictures/slice_z0.025.png ] || fail "no default slice"
$report --case . --out pictures --analytic none --slice x=0.1 \
    --line "(0 0.025 0.02)" "(0.5 0.025 0.02)" > log.reportPictures || fail "pictures"
"$COAGULATIONFOAM_PYTHON" - <<'PY' || fail "the slices and the line"
import numpy as np
full = np.genfromtxt("pictures/moments_full.csv", delimiter=",", names=True)
key = {tuple(np.round([r["x"], r["y"], r["z"]], 9)): r for r in full}
good = True
for name, count, at in (("slice_z0.025", 500, ("z", 0.0225)), ("slice_x0.1", 100, ("x", 0.095))):
    rows = np.genfromtxt("pictures/%s.csv" % name, delimiter=",", names=True, skip_header=2)
    ref = [key[tuple(np.round([r["x"], r["y"], r["z"]], 9))] for r in rows]
    m0 = np.array([r["M0_mean"] for r in ref])
    head = open("pictures/%s.csv" % name).readline()
    lo, hi = [float(v) for v in head.split("M0 ", 1)[1].split(",")[0].split()]
    ok = (len(rows) == count and np.allclose(rows[at[0]], at[1])
          and np.allclose(rows["M0"], m0, rtol=1e-9)
          and np.isclose(lo, m0.min()) and np.isclose(hi, m0.max()))
    print("%s: %d cells at %s = %g, M0 as moments_full.csv, range %g..%g: %s"
          % (name, len(rows), at[0], at[1], lo, hi, "ok" if ok else "FAIL"))
    good &= ok
rows = np.genfromtxt("pictures/line1.csv", delimiter=",", names=True, skip_header=1)
ref = [key[tuple(np.round([r["x"], r["y"], r["z"]], 9))] for r in rows]
ok = (len(rows) == 50 and np.isclose(rows["s_in"][0], 0) and np.isclose(rows["s_out"][-1], 0.5)
      and np.allclose(rows["s_in"][1:], rows["s_out"][:-1]) and np.all(np.diff(rows["x"]) > 0)
      and np.allclose(rows["M1"], [r["M1_mean"] for r in ref], rtol=1e-9)
      and np.allclose(rows["M1_ci95"], [r["M1_ci95"] for r in ref], rtol=1e-9))
print("line1: %d cells from s = %g to %g, M1 and its interval as moments_full.csv: %s"
      % (len(rows), rows["s_in"][0], rows["s_out"][-1], "ok" if ok else "FAIL"))
sys_exit = 0 if (good and ok) else 1
raise SystemExit(sys_exit)
PY

echo "PASS channel: serial and 2-rank runs of the real pipeline agree, balances closed with deposition; the report's slices and line"
