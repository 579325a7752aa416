#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Self-test of applications/utilities/coagulationReport (coagulationReport.py and the package
# src/python/coagulationPost it runs on; unit tests of the package: tests/python/test_*.py).
#
# Builds synthetic solver output (HDF5, the solver's layout) in a temporary directory:
# constant-kernel duct moments (paper §3.1, I = 3e8, K0 = 1e-5, 50 cells of 4e-3) equal to
# the exact cell averages of eqs (39)-(45) times (1 + 0.01 N(0,1)), split over two
# "processor" files by cells plus one overlapping "restart" file; the superseded samples in
# the overlap are corrupted so that a wrong restart merge fails the check.  Then runs the
# report with --check (must pass), on data scaled by 1.1 (must fail), single-value checks,
# pooled realisations, an additive-kernel case, and the error exits.
#
# Usage: bash tests/python/test_coagulationReport.sh      (last line: "N passed, N failed")
set -u

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=/dev/null
. "$HERE/selfTestLib.sh" coagulationReportTest
REPORT="$ROOT/applications/utilities/coagulationReport/coagulationReport.py"

# ---------------------------------------------------------------- synthetic data generator
cat > "$TMP/make_case.py" <<'EOF'
"""make_case.py CASE LAYOUT [--scale S] [--seed N] [--kernel constant|additive]
LAYOUT: split  (proc0 + proc1 by cells, t in [0, 2]; restart of proc0 cells, t in [1.5, 3];
                proc0's samples at t >= 1.5 multiplied by 10: they must be superseded)
        single (one file, all cells, t in [0, 1])
"""
import argparse, os, sys
import numpy as np
import h5py

ap = argparse.ArgumentParser()
ap.add_argument("case"); ap.add_argument("layout")
ap.add_argument("--scale", type=float, default=1.0)
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--kernel", default="constant")
a = ap.parse_args()
rng = np.random.default_rng(a.seed)

if a.kernel == "constant":
    I, K0, n, V1, nc, dx, dts, dtsplit, trelax = 3e8, 1e-5, 256, 1.25e-8, 50, 4e-3, 5e-3, 1e-4, 0.4
else:
    I, K0, n, V1, nc, dx, dts, dtsplit, trelax = 1e5, 1.06e-2, 2048, 7.8125e-5, 50, 2e-3, 4e-3, 4e-4, 0.2
lo = np.arange(nc) * dx
hi = lo + dx
xc = 0.5 * (lo + hi)

if a.kernel == "constant":
    # exact cell averages from antiderivatives (independent of coagulationPost's quadrature)
    A = np.sqrt(I * K0 / 2.0)
    def P(x):  # antiderivatives of m0..m3 (u = 1)
        return np.stack([np.sqrt(2 * I / K0) * np.log(np.cosh(A * x)) / A,
                         I * x**2 / 2,
                         I * x**2 / 2 + K0 * I**2 * x**4 / 12,
                         I * x**2 / 2 + K0 * I**2 * x**4 / 4 + K0**2 * I**3 * x**6 / 30])
    avg = (P(hi) - P(lo)) / dx                      # (4, nc)
else:
    from coagulationPost import analytic
    avg = analytic.cell_average("additiveDuct", lo, hi, I, K0)
    avg[1] = I * xc                                 # eq. (50), exact

centres = np.stack([xc, np.full(nc, 5e-3), np.full(nc, 5e-3)], axis=1)
d = os.path.join(a.case, "postProcessing", "coagulationSamples")
os.makedirs(d, exist_ok=True)

def write(name, cells, times, corrupt_from=None):
    cells = np.asarray(cells)
    m = avg.T[cells][None, :, :] * (1 + 0.01 * rng.standard_normal((len(times), len(cells), 4)))
    m *= a.scale
    if corrupt_from is not None:
        m[times >= corrupt_from - 1e-9] *= 10.0
    with h5py.File(os.path.join(d, name), "w") as f:
        f["cellCentres"] = centres[cells]
        f["time"] = np.asarray(times, dtype=float)
        f["moments"] = m
        for k, v in dict(n=n, V1=V1, K0=K0, inceptionRate=I, seed=a.seed, splitDeltaT=dtsplit,
                         sampleInterval=dts, tRelax=trelax).items():
            f.attrs[k] = v
        f.attrs["algorithm"] = "SWA"
        f.attrs["kernel"] = a.kernel

if a.layout == "split":
    c0 = rng.permutation(np.arange(0, nc // 2))   # unsorted cell order in the file
    c1 = np.arange(nc // 2, nc)
    t_first = np.arange(0, 401) * dts              # 0 .. 2.0
    t_restart = 1.5 + np.arange(0, 301) * dts      # 1.5 .. 3.0 (different rounding)
    write("proc0.h5", c0, t_first, corrupt_from=1.5)
    write("proc1.h5", c1, t_first)
    write("a_restart_proc0.h5", c0[::-1], t_restart)   # sorts first by name
elif a.layout == "single":
    write("samples.h5", np.arange(nc), np.arange(0, 201) * dts)   # 0 .. 1.0
else:
    sys.exit("unknown layout " + a.layout)
EOF

mk() { "$PY" "$TMP/make_case.py" "$@"; }

# ---------------------------------------------------------------- coagulationPost.analytic
if "$PY" - <<'EOF'
import sys
import numpy as np
from coagulationPost import analytic as a
bad = []
m = a.additive_duct(np.array([0.099]), 1e5, 1.06e-2)[:, 0]
if abs(m[1] - 9.9e3) > 1e-6 * 9.9e3: bad.append("additive m1(0.099) = %g" % m[1])
if not 8.8e7 <= m[2] <= 9.1e7: bad.append("additive m2(0.099) = %g" % m[2])
x = np.linspace(0, 0.2, 51)
c = a.constant_duct(x, 3e8, 1e-5)
o = a.duct_ode("constant", x, 3e8, 1e-5)
err = np.max(np.abs(o[:, 1:] / c[:, 1:] - 1))
if err > 1e-7: bad.append("constant duct ODE vs closed form: %g" % err)
lo = np.arange(50) * 4e-3; hi = lo + 4e-3
av = a.cell_average("constantDuct", lo, hi, 3e8, 1e-5)
ex = 3e8 * 0.5 * (lo + hi) + 1e-5 * 3e8**2 / 3 * (hi**4 - lo**4) / (4 * 4e-3)
if np.max(np.abs(av[2] / ex - 1)) > 1e-12: bad.append("cell average of m2")
lo2, hi2 = a.cell_edges(np.array([0.006, 0.002, 0.01]))
if not (np.allclose(lo2, [0.004, 0.0, 0.008]) and np.allclose(hi2, [0.008, 0.004, 0.012])):
    bad.append("cell_edges %s %s" % (lo2, hi2))
print("\n".join(bad) if bad else "m1(0.099) = %.6g, m2(0.099) = %.6g" % (m[1], m[2]))
sys.exit(1 if bad else 0)
EOF
then ok "analytic: additive sanity values, constant-duct ODE = closed form, cell averages"
else ko "analytic reference values"; fi

# ---------------------------------------------------------------- constant duct, split + restart
C="$TMP/constantDuct"
mk "$C" split --seed 11 || ko "generator (split)"
run_expect "constant duct --check (split cells + overlapping restart)" 0 "$TMP/check.log" -- \
    "$PY" "$REPORT" --case "$C" --check --check-rel-tol 0.03 --check-skip-cells 3 \
    --check-moments 0,1,2,3
grep -q "check passed" "$TMP/check.log" && ok "check reports success" || ko "no 'check passed' line"

for f in moments.csv moments_full.csv summary.json moments.png normalisedStdDev.png relativeError.png; do
    [ -s "$C/results/$f" ] && ok "output $f written" || ko "output $f missing"
done

if "$PY" - "$C/results" <<'EOF'
import sys, csv, json
import numpy as np
d = sys.argv[1]
bad = []
with open(d + "/moments.csv") as f:
    rows = list(csv.reader(f))
if rows[0] != "x,M0_mean,M0_ci95,M1_mean,M1_ci95,M2_mean,M2_ci95,M3_mean,M3_ci95".split(","):
    bad.append("moments.csv header %s" % rows[0])
x = np.array([float(r[0]) for r in rows[1:]])
if len(x) != 50: bad.append("%d rows, expected 50" % len(x))
if not np.all(np.diff(x) > 0): bad.append("cells not sorted by x")
full = np.genfromtxt(d + "/moments_full.csv", delimiter=",", names=True)
cnt = full["M1_count"]
# t in [0.4, 3.0] every 5e-3 for the restarted cells, [0.4, 2.0] for the others
if not (np.all(cnt[:25] == 521) and np.all(cnt[25:] == 321)):
    bad.append("sample counts %s" % np.unique(cnt))
for k in range(4):
    mean, ci, a = full["M%d_mean" % k], full["M%d_ci95" % k], full["M%d_analytic" % k]
    r = full["M%d_ci95_iid" % k] / (1.96 * 0.01 * a / np.sqrt(cnt))
    if np.any(np.abs(r - 1) > 0.25): bad.append("M%d ci95_iid off: %s" % (k, r))
    # independent samples: the correlated-sample interval is about the iid one, a little
    # wider (its window at least the residence time x/u, up to 40 samples at the outlet,
    # is taken where it gives the larger tau_int, and t has N/(2M+1) dof), n_eff ~ count
    r = ci / full["M%d_ci95_iid" % k]
    if np.any(r < 0.8) or np.any(r > 3.0) or not 1.0 <= np.median(r) <= 1.35:
        bad.append("M%d ci95 / ci95_iid %s" % (k, r))
    if abs(np.median(full["M%d_neff" % k] / cnt) - 1) > 0.25:
        bad.append("M%d n_eff / count %s" % (k, full["M%d_neff" % k] / cnt))
    nsd = full["M%d_normStdDev" % k]          # sqrt(256) * 0.01 = 0.16
    if np.any(np.abs(nsd / 0.16 - 1) > 0.25): bad.append("M%d normalised sd %s" % (k, nsd))
    z = (mean - a) / (ci / 1.96)
    if np.any(np.abs(z) > 5): bad.append("M%d means off by %s sd" % (k, np.max(np.abs(z))))
s = json.load(open(d + "/summary.json"))
if s["realisations"] != 1 or s["analytic"] != "constantDuct" or s["algorithm"] != "SWA":
    bad.append("summary %s" % {k: s[k] for k in ("realisations", "analytic", "algorithm")})
if bad: print("\n".join(bad))
sys.exit(1 if bad else 0)
EOF
then ok "CSV layout, x order, restart-merged sample counts, ci95, normalised sd, summary"
else ko "CSV / statistics contents"; fi

run_expect "single-cell check: last cell M1 = I x" 0 "$TMP/v1.log" -- \
    "$PY" "$REPORT" --case "$C" --no-plots --check-cell-index -1 --check-moment 1 \
    --check-value 5.94e7 --check-value-rel-tol 0.003
run_expect "single-cell checks, repeated pairs, one wrong by 1 %" 1 "$TMP/v2.log" -- \
    "$PY" "$REPORT" --case "$C" --no-plots --check-cell-index -1 --check-moment 1 \
    --check-value 5.94e7 --check-value 6.0e7 --check-value-rel-tol 0.003
grep -q "CHECK FAILED cell 49" "$TMP/v2.log" && ok "failing single-cell check is reported" \
    || ko "no 'CHECK FAILED cell 49' line"
run_expect "--t-end 1.0 window" 0 "$TMP/tend.log" -- \
    "$PY" "$REPORT" --case "$C" --no-plots --t-end 1.0 --out "$TMP/tend" --check \
    --check-skip-cells 3
"$PY" -c "
import numpy as np, sys
c = np.genfromtxt('$TMP/tend/moments_full.csv', delimiter=',', names=True)['M0_count']
sys.exit(0 if np.all(c == 121) else 1)" && ok "--t-end limits the samples (121 per cell)" \
    || ko "--t-end sample count"

# ---------------------------------------------------------------- scaled by 1.1 must fail
S="$TMP/constantDuctScaled"
mk "$S" split --seed 12 --scale 1.1 || ko "generator (scaled)"
run_expect "values scaled by 1.1 fail --check" 1 "$TMP/scaled.log" -- \
    "$PY" "$REPORT" --case "$S" --no-plots --check --check-rel-tol 0.03 --check-skip-cells 3 \
    --check-moments 0,1,2,3
grep -q "CHECK FAILED" "$TMP/scaled.log" && ok "scaled failure lists failing cells" \
    || ko "no CHECK FAILED line for scaled data"

# ---------------------------------------------------------------- pooled realisations
mk "$TMP/r1" single --seed 21 && mk "$TMP/r2" single --seed 22 || ko "generator (realisations)"
run_expect "pooled realisations --check" 0 "$TMP/pool.log" -- \
    "$PY" "$REPORT" --no-plots --out "$TMP/pooled" --realisations "$TMP/r1" "$TMP/r2" --check \
    --check-skip-cells 3
"$PY" -c "
import json, sys, numpy as np
c = np.genfromtxt('$TMP/pooled/moments_full.csv', delimiter=',', names=True)['M2_count']
s = json.load(open('$TMP/pooled/summary.json'))
sys.exit(0 if np.all(c == 242) and s['realisations'] == 2 else 1)" \
    && ok "realisations pooled (242 samples per cell, 2 realisations)" || ko "pooling counts"

# pooled statistics = those of all in-window samples put together (numpy, computed here from
# the files): realisations with different means (scale 1.2), so that the spread between them
# counts; mean, sample sd (N - 1), count and ci95_iid = 1.96 sd/sqrt(N) to round-off, and
# ci95 from the two realisation means (Student t, 1 dof)
mk "$TMP/r3" single --seed 23 --scale 1.2 || ko "generator (realisation r3)"
run_expect "pooled realisations of different means" 0 "$TMP/pool3.log" -- \
    "$PY" "$REPORT" --no-plots --analytic none --out "$TMP/pooled3" --realisations "$TMP/r1" "$TMP/r3"
if "$PY" - "$TMP/pooled3/moments_full.csv" "$TMP/r1" "$TMP/r3" <<'EOF'
import sys
import h5py
import numpy as np
res = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
parts = []
for case in sys.argv[2:]:
    with h5py.File(case + "/postProcessing/coagulationSamples/samples.h5", "r") as f:
        t, m, x = f["time"][:], f["moments"][:], f["cellCentres"][:, 0]
        keep = t >= f.attrs["tRelax"] - 1e-9
        parts.append(m[keep][:, np.argsort(x), :])
allm = np.concatenate(parts)                      # [samples][cells sorted by x][k]
bad = []
for k in range(4):
    d = allm[:, :, k]
    want = {"mean": d.mean(axis=0), "sd": d.std(axis=0, ddof=1), "count": np.full(d.shape[1], len(d)),
            "ci95_iid": 1.96 * d.std(axis=0, ddof=1) / np.sqrt(len(d)),
            # two realisations: t_{0.975, 1} sd(realisation means) / sqrt(2)
            "ci95": 12.706204736174698 * np.abs(parts[0][:, :, k].mean(axis=0)
                                                - parts[1][:, :, k].mean(axis=0)) / 2}
    for key, v in want.items():
        got = res["M%d_%s" % (k, key)]
        err = np.max(np.abs(got / v - 1))
        if not err < 1e-9:
            bad.append("M%d_%s off by %.3g (relative)" % (k, key, err))
print("\n".join(bad) if bad else "pooled mean, sd, count, ci95_iid of %d samples and ci95 of 2 realisations exact" % len(allm))
sys.exit(1 if bad else 0)
EOF
then ok "pooled mean, sd (N-1), count, ci95 equal those of the samples put together"
else ko "pooled statistics of realisations with different means"; fi

# ---------------------------------------------------------------- additive kernel, auto reference
A="$TMP/additiveDuct"
mk "$A" single --seed 31 --kernel additive || ko "generator (additive)"
run_expect "additive duct: auto reference, Table 1/2 style cell checks" 0 "$TMP/add.log" -- \
    "$PY" "$REPORT" --case "$A" --check --check-skip-cells 3 \
    --check-cell-index -1 --check-moment 1 --check-value 9.90e3 --check-value-rel-tol 0.003 \
    --check-moment 2 --check-value 9.0e7 --check-value-rel-tol 0.03

# ---------------------------------------------------------------- error exits
mkdir -p "$TMP/empty/postProcessing/coagulationSamples"
run_expect "no HDF5 file: error exit" 2 "$TMP/empty.log" -- "$PY" "$REPORT" --case "$TMP/empty"
grep -q "no HDF5 sample file" "$TMP/empty.log" && ok "no-file message" || ko "no-file message"
B="$TMP/broken"
mk "$B" single --seed 41 || ko "generator (broken)"
"$PY" -c "
import h5py; f = h5py.File('$B/postProcessing/coagulationSamples/samples.h5', 'a'); del f['moments']"
run_expect "file without /moments: error exit" 2 "$TMP/broken.log" -- "$PY" "$REPORT" --case "$B"
grep -q "lacks dataset /moments" "$TMP/broken.log" && ok "missing-dataset message" \
    || ko "missing-dataset message"
run_expect "--check without analytic reference: error exit" 2 "$TMP/noana.log" -- \
    "$PY" "$REPORT" --case "$C" --no-plots --analytic none --check --out "$TMP/noana"

finish
