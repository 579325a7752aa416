#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Self-test of applications/utilities/coagulationTables (coagulationTables.py).
#
# Builds synthetic ensembles ("rows": folders of realisation_* runs, each with one HDF5 sample
# file in the solver's layout) of the additive-kernel duct of Patterson & Wagner §3.2
# (I = 1e5, K0 = 1.06e-2, u = 1, 50 cells of 2e-3 on [0, 0.1]) and one constant-kernel row
# (§3.1), then runs the tables tool: a good study with --check (must pass, tables checked
# number by number), one spoiled row per acceptance check (must fail that check only), the
# --z-ci widening, the standard error from realisation means (R >= 3) or samples (R < 3), the
# bad-input exits, the constant-kernel figures, realisations of unequal length, --t-end and a
# single run given as a row.
#
# The generated samples are Gaussian (numpy default_rng, fixed seeds) but shifted and scaled
# per realisation, cell and moment so that in the window t >= tRelax
#   * the pooled sample mean of each cell is exactly the prescribed mean mu,
#   * the pooled sample sd is exactly the prescribed sd,
#   * the R realisation means are mu + F sd/sqrt(Ns) c_r, c standardised Gaussian draws
#     (F = 1 unless --between), so that the standard error from the realisation means is
#     exactly F sd/sqrt(R Ns);
# so every check's margin is known in advance and no result depends on the luck of a seed.
# Samples before tRelax are half the mean: a tool that used them would fail the mean checks.
#
# Usage: bash tests/python/test_coagulationTables.sh      (last line: "N passed, N failed")
set -u

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=/dev/null
. "$HERE/selfTestLib.sh" coagulationTablesTest
TABLES="$ROOT/applications/utilities/coagulationTables/coagulationTables.py"

# ---------------------------------------------------------------- synthetic data generator
cat > "$TMP/make_rows.py" <<'EOF'
"""make_rows.py BASE < SPECS

Each line of SPECS (blank lines and # comments skipped) describes one row:
ROW --method SWA|DSA1|DSA2 --n N --realisations R --seed S [options]

Writes BASE/ROW/realisation_k/postProcessing/coagulationSamples/samples.h5, k = 0..R-1.
Additive kernel (default): m1 = I x / u in every cell except the last, whose M1 mean is
--m1-last (SWA default 9.877e3, the tool's reference); M1 sd from eq. (47),
sd = m1 sqrt(u/(I V1 x))/sqrt(n) (times --m1-sd-factor), unless --m1-last-sd; M2 mean
9.1e7 (x/0.099)^3 with last-cell value --m2-last and relative sd 2.09e7/9.1e7 sqrt(2048/n)
(--m2-last-sd overrides the last cell; --m2-sd-no-scaling drops the sqrt(2048/n)).
Constant kernel: closed-form centre values of eqs (39)-(45), M1 sd from eq. (47).
In the window t >= tRelax the pooled sample mean and sd of every cell and moment are exactly
mu and sd; the realisation means scatter about mu by --between * sd/sqrt(samples) (1: as
independent samples would; > 1: like correlated samples).  --last-t-end shortens the last
realisation (the realisation means are then weighted by their sample counts to give mu).
"""
import argparse, json, os, shlex, sys
import numpy as np
import h5py

ap = argparse.ArgumentParser()
ap.add_argument("row")
ap.add_argument("--method", required=True)
ap.add_argument("--n", type=int, required=True)
ap.add_argument("--realisations", type=int, default=3)
ap.add_argument("--seed", type=int, required=True)
ap.add_argument("--kernel", default="additive")
ap.add_argument("--t-end", type=float)
ap.add_argument("--m1-last", type=float)
ap.add_argument("--m1-last-sd", type=float)
ap.add_argument("--m1-sd-factor", type=float, default=1.0)
ap.add_argument("--m2-last", type=float, default=9.1e7)
ap.add_argument("--m2-last-sd", type=float)
ap.add_argument("--m2-sd-no-scaling", action="store_true")
ap.add_argument("--dup-seed", action="store_true", help="realisations 0 and 1 share a seed")
ap.add_argument("--timing", action="store_true", help="write an ensemble.json")
ap.add_argument("--between", type=float, default=1.0)
ap.add_argument("--last-t-end", type=float)


def make(a):
    row = os.path.join(base, a.row)
    rng = np.random.default_rng(a.seed)
    n, R = a.n, a.realisations

    if a.kernel == "additive":
        I, K0, u, nc, dx, dts, dtsplit, trelax = 1e5, 1.06e-2, 1.0, 50, 2e-3, 4e-3, 4e-4, 0.2
        V1 = 7.8125e-5 if a.method == "SWA" else 1e-3 / 3
        t_end = a.t_end if a.t_end is not None else (0.4 if a.method == "SWA" else 1.0)
    else:
        I, K0, u, nc, dx, dts, dtsplit, trelax = 3e8, 1e-5, 1.0, 50, 4e-3, 5e-3, 1e-4, 0.4
        V1 = 1.25e-8
        t_end = a.t_end if a.t_end is not None else 1.0
    x = (np.arange(nc) + 0.5) * dx
    s = np.sqrt(2048.0 / n)
    eq47 = np.sqrt(u / (I * V1 * x)) / np.sqrt(n)          # sd(M1)/m1
    mu = np.empty((nc, 4)); sd = np.empty((nc, 4))
    if a.kernel == "additive":
        mu[:, 0] = I * x / (1 + (x / 0.03) ** 2)
        mu[:, 1] = I * x / u
        mu[:, 2] = 9.1e7 * (x / 0.099) ** 3
        mu[:, 3] = 2.8e12 * (x / 0.099) ** 6
        sd[:, 0] = 0.1 * s * mu[:, 0]
        sd[:, 1] = a.m1_sd_factor * eq47 * mu[:, 1]
        sd[:, 2] = 2.09e7 / 9.1e7 * (1.0 if a.m2_sd_no_scaling else s) * mu[:, 2]
        sd[:, 3] = 0.3 * s * mu[:, 3]
        m1_last = a.m1_last if a.m1_last is not None else (9.877e3 if a.method == "SWA" else None)
        if m1_last is not None:
            mu[-1, 1] = m1_last
        if a.m1_last_sd is not None:
            sd[-1, 1] = a.m1_last_sd
        mu[-1, 2] = a.m2_last
        if a.m2_last_sd is not None:
            sd[-1, 2] = a.m2_last_sd
    else:
        A = np.sqrt(I * K0 / 2.0)
        mu[:, 0] = np.sqrt(2 * I / K0) * np.tanh(A * x)
        mu[:, 1] = I * x
        mu[:, 2] = I * x + K0 * I ** 2 * x ** 3 / 3
        mu[:, 3] = I * x + K0 * I ** 2 * x ** 3 + K0 ** 2 * I ** 3 * x ** 5 / 5
        sd[:] = 0.16 * mu
        sd[:, 1] = eq47 * mu[:, 1]

    def times(te):
        return np.arange(0, int(round(te / dts)) + 1) * dts
    t_ends = [t_end] * R
    if a.last_t_end is not None:
        t_ends[-1] = a.last_t_end
    i_relax = int(round(trelax / dts))
    Ns = np.array([times(te).size - i_relax for te in t_ends], dtype=float)   # in-window samples
    N = Ns.sum()

    def standardise(z, axis):
        z = z - z.mean(axis=axis, keepdims=True)
        return z / z.std(axis=axis, ddof=1, keepdims=True)

    # realisation offsets delta_k: count-weighted mean 0, so that the pooled mean is mu
    c = standardise(rng.standard_normal((R, nc, 4)), 0)
    delta = a.between * sd * c / np.sqrt(Ns)[:, None, None]
    delta -= np.tensordot(Ns / N, delta, axes=1)
    # within-realisation sd s_w such that the pooled sample variance is sd^2:
    # (N - 1) sd^2 = (N - R) s_w^2 + sum_k Ns_k delta_k^2
    sw = np.sqrt((sd ** 2 * (N - 1) - np.tensordot(Ns, delta ** 2, axes=1)) / (N - R))
    for k in range(R):
        t = times(t_ends[k])
        win = np.arange(t.size) >= i_relax
        z = standardise(rng.standard_normal((int(win.sum()), nc, 4)), 0)
        m = np.empty((t.size, nc, 4))
        m[win] = mu + delta[k] + sw * z
        m[~win] = 0.5 * mu * (1 + 0.01 * rng.standard_normal(((~win).sum(), nc, 4)))
        cells = rng.permutation(nc) if k % 2 else np.arange(nc)   # unsorted cells in some files
        d = os.path.join(row, "realisation_%d" % k, "postProcessing", "coagulationSamples")
        os.makedirs(d, exist_ok=True)
        with h5py.File(os.path.join(d, "samples.h5"), "w") as f:
            f["cellCentres"] = np.stack([x, np.zeros(nc), np.zeros(nc)], axis=1)[cells]
            f["time"] = t
            f["moments"] = m[:, cells, :]
            seed = a.seed * 100 + (0 if a.dup_seed and k == 1 else k)
            for key, v in dict(n=n, V1=V1, K0=K0, inceptionRate=I, seed=seed, splitDeltaT=dtsplit,
                               sampleInterval=dts, tRelax=trelax).items():
                f.attrs[key] = v
            f.attrs["algorithm"] = a.method
            f.attrs["kernel"] = a.kernel
    if a.timing:
        with open(os.path.join(row, "ensemble.json"), "w") as f:
            json.dump({"realisations": R, "jobs": 4, "ranksPerRealisation": 1,
                       "wallSeconds": 12.5, "cpuSeconds": 48.25}, f)

base = sys.argv[1]
for line in sys.stdin:
    line = line.split("#")[0].strip()
    if line:
        make(ap.parse_args(shlex.split(line)))
EOF

# expect_grep DESCRIPTION LOG PATTERN: a line of LOG matches the extended regex PATTERN
expect_grep() {
    if grep -Eq -- "$3" "$2"; then ok "$1"; else
        ko "$1: no line matching '$3' in $(basename "$2"); its check lines:"
        grep -E "check|error" "$2" | sed 's/^/    /'; fi
}

tables() { "$PY" "$TABLES" "$@"; }

# ---------------------------------------------------------------- rows
D="$TMP/rows"
"$PY" "$TMP/make_rows.py" "$D" <<'ROWS' || ko "generator make_rows.py"
# good rows (case 1): SWA M1 last cell 9.877e3, M2 9.1e7, sds of eq. (47) and 2.09e7 sqrt(2048/n)
swa2048  --method SWA  --n 2048 --realisations 3 --seed 1 --timing
swa8192  --method SWA  --n 8192 --realisations 3 --seed 2
# DSA1: 10.5e3 +- 3e3 over 4 x 201 samples: SE = 3e3/sqrt(804) = 106, 5.7 SE above 9.9e3
dsa1_2048 --method DSA1 --n 2048 --realisations 4 --seed 3 --m1-last 10.5e3 --m1-last-sd 3e3
# DSA2: M2 3e7 +- 3.45e7 and 5.5e7 +- 5.97e7 (paper sds), 4 x 201 samples each:
# SEs 1.22e6 and 2.11e6, rise 2.5e7 = 10.3 combined SE
dsa2_2048 --method DSA2 --n 2048 --realisations 4 --seed 4 --m2-last 3e7 --m2-last-sd 3.45e7
dsa2_8192 --method DSA2 --n 8192 --realisations 4 --seed 5 --m2-last 5.5e7 --m2-last-sd 5.97e7

# spoiled rows: +0.5 % in the last cell's M1 (cases 2, 3)
swa2048_shift --method SWA --n 2048 --realisations 3 --seed 11 --m1-last 9.926385e3
swa8192_shift --method SWA --n 8192 --realisations 3 --seed 12 --m1-last 9.926385e3
# sd of M2 the same at n = 8192 as at 2048 (case 4); M1 sd twice eq. (47) (case 5)
swa8192_m2sd  --method SWA --n 8192 --realisations 3 --seed 13 --m2-sd-no-scaling
swa2048_sd2   --method SWA --n 2048 --realisations 3 --seed 14 --m1-sd-factor 2
swa8192_sd2   --method SWA --n 8192 --realisations 3 --seed 15 --m1-sd-factor 2
# DSA1 on the exact value (case 6); DSA2 falling with n (case 7)
dsa1_exact    --method DSA1 --n 2048 --realisations 4 --seed 16 --m1-last 9.9e3 --m1-last-sd 3e3
dsa2_2048_hi  --method DSA2 --n 2048 --realisations 4 --seed 17 --m2-last 5.5e7 --m2-last-sd 3.45e7
dsa2_8192_lo  --method DSA2 --n 8192 --realisations 4 --seed 18 --m2-last 3e7 --m2-last-sd 5.97e7
# a second SWA n=2048 row; realisations 0 and 1 with one seed (case 8)
swa2048_again --method SWA --n 2048 --realisations 3 --seed 19
swa2048_dupseed --method SWA --n 2048 --realisations 3 --seed 20 --dup-seed
# realisation means 3x more scattered than the samples suggest (cases 6b, 6c)
dsa1_corr4    --method DSA1 --n 2048 --realisations 4 --seed 22 --m1-last 10.5e3 --m1-last-sd 3e3 --between 3
dsa1_corr2    --method DSA1 --n 2048 --realisations 2 --seed 23 --m1-last 10.5e3 --m1-last-sd 3e3 --between 3
# last realisation ends at 0.3 (case 10); constant-kernel duct of section 3.1 (case 9)
swa2048_short --method SWA --n 2048 --realisations 3 --seed 24 --last-t-end 0.3
const256 --kernel constant --method SWA --n 256 --realisations 2 --seed 21
# twelve realisations (case 12); the last cell's M1 sd twice eq. (47), 2 x 248.2 (case 13)
swa2048_R12   --method SWA --n 2048 --realisations 12 --seed 25
swa2048_lastsd --method SWA --n 2048 --realisations 3 --seed 26 --m1-last-sd 496.4
ROWS
GOOD=("$D/swa2048" "$D/swa8192" "$D/dsa1_2048" "$D/dsa2_2048" "$D/dsa2_8192")
mkdir -p "$D/empty"

# ---------------------------------------------------------------- 1. good study
O="$TMP/good"
run_expect "1. good study --check" 0 "$TMP/good.log" -- \
    tables --rows "${GOOD[@]}" --out "$O" --check
expect_grep "1. all 11 checks run, none failed" "$TMP/good.log" "^checks: 11 run, 0 failed$"
expect_grep "1. DSA1 SE from the 4 realisation means (5.67 SE)" "$TMP/good.log" \
    "^check passed: DSA1 n=2048 M1 mean 10500 above 9900 by 5\.67 SE \(SE 106 from realisations, R=4"
grep -q "CHECK FAILED" "$TMP/good.log" && ko "1. a CHECK FAILED line in the good study" \
    || ok "1. no CHECK FAILED line"
for f in table1.csv table1.md table2.csv table2.md tableM0M3.csv rows.csv checks.txt \
         figure7.png figure8.png figure9.png figure10.png; do
    [ -s "$O/$f" ] && ok "1. output $f written" || ko "1. output $f missing"
done
ls "$O"/figure[3-6].png > /dev/null 2>&1 && ko "1. constant-kernel figures without such rows" \
    || ok "1. no figure3..6 without constant-kernel rows"

if "$PY" - "$O" <<'EOF'
import csv, math, sys
from scipy.stats import t as student
d = sys.argv[1]
bad = []
def rows(name):
    with open("%s/%s" % (d, name)) as f:
        return list(csv.DictReader(f))
eq47 = lambda V1, n: 9.9e3 * math.sqrt(1 / (1e5 * V1 * 0.099)) / math.sqrt(n)
# method, n, R, samples per realisation, tEnd, (M1 mean, sd), (M2 mean, sd)
want = [("DSA1", 2048, 4, 201, 1.0, (10.5e3, 3e3), (9.1e7, 2.09e7)),
        ("DSA2", 2048, 4, 201, 1.0, (9.9e3, eq47(1e-3 / 3, 2048)), (3e7, 3.45e7)),
        ("DSA2", 8192, 4, 201, 1.0, (9.9e3, eq47(1e-3 / 3, 8192)), (5.5e7, 5.97e7)),
        ("SWA", 2048, 3, 51, 0.4, (9.877e3, eq47(7.8125e-5, 2048)), (9.1e7, 2.09e7)),
        ("SWA", 8192, 3, 51, 0.4, (9.877e3, eq47(7.8125e-5, 8192)), (9.1e7, 1.045e7))]
paper = {(1, "SWA", 2048): 9.878e3, (1, "DSA1", 2048): 10.570e3, (2, "DSA2", 8192): 5.549e7}
for k in (1, 2):
    got = rows("table%d.csv" % k)
    if [(r["method"], int(r["n"])) for r in got] != [(w[0], w[1]) for w in want]:
        bad.append("table%d rows %s" % (k, [(r["method"], r["n"]) for r in got]))
        continue
    for r, (meth, n, R, ns, tend, m1, m2) in zip(got, want):
        mean, sd = m1 if k == 1 else m2
        N = R * ns
        exp = {"realisations": R, "samples": N, "tStart": 0.2, "tEnd": tend, "mean": mean,
               "sd": sd, "ci95": 1.96 * sd / math.sqrt(N),
               "ci95_realisations": student.ppf(0.975, R - 1) * sd / math.sqrt(N)}
        for key, v in exp.items():
            if not math.isclose(float(r[key]), v, rel_tol=1e-5):
                bad.append("table%d %s n=%d %s = %s, expected %.6g" % (k, meth, n, key, r[key], v))
        p = paper.get((k, meth, n))
        if p is not None and not math.isclose(float(r["paper_mean"]), p, rel_tol=1e-9):
            bad.append("table%d %s n=%d paper_mean %s, expected %g" % (k, meth, n, r["paper_mean"], p))
m03 = rows("tableM0M3.csv")
if len(m03) != 5: bad.append("tableM0M3.csv has %d rows" % len(m03))
else:
    m0 = 1e5 * 0.099 / (1 + (0.099 / 0.03) ** 2)
    for r in m03:
        if not math.isclose(float(r["M0_mean"]), m0, rel_tol=1e-5):
            bad.append("tableM0M3 %s n=%s M0_mean %s, expected %.6g" % (r["method"], r["n"], r["M0_mean"], m0))
rr = rows("rows.csv")
if [(r["method"], int(r["n"]), int(r["realisations"])) for r in rr] != [(w[0], w[1], w[2]) for w in want]:
    bad.append("rows.csv rows %s" % [(r["method"], r["n"], r["realisations"]) for r in rr])
else:
    s = rr[3]
    if (float(s["wallSeconds"]), float(s["cpuSeconds"]), s["jobs"], s["ranksPerRealisation"]) \
            != (12.5, 48.25, "4", "1") or not s["folder"].endswith("swa2048"):
        bad.append("rows.csv timing of swa2048: %s" % s)
    if rr[0]["wallSeconds"] != "" or rr[0]["kernel"] != "additive":
        bad.append("rows.csv DSA1 row: %s" % rr[0])
md = open(d + "/table1.md").read()
if "[0.098, 0.1]" not in md or "| SWA | 2048 | 3 | 153 |" not in md or "9.8770" not in md:
    bad.append("table1.md:\n" + md)
if bad: print("\n".join(bad))
sys.exit(1 if bad else 0)
EOF
then ok "1. table1/table2/tableM0M3/rows.csv: rows, counts, windows, means, sds, ci95s, timing"
else ko "1. table contents"; fi

# ---------------------------------------------------------------- 2-7. one spoiled check each
S="$TMP/spoiled"
SHIFT=("$D/swa2048_shift" "$D/swa8192_shift" "$D/dsa1_2048" "$D/dsa2_2048" "$D/dsa2_8192")
run_expect "2. SWA M1 mean +0.5 %" 1 "$TMP/shift.log" -- \
    tables --rows "${SHIFT[@]}" --out "$S/shift" --no-plots --check
expect_grep "2. Table 1 check failed for SWA n=2048" "$TMP/shift.log" \
    "^CHECK FAILED: Table 1 SWA n=2048 M1 mean .*\+0\.500%"
expect_grep "2. Table 1 check failed for SWA n=8192" "$TMP/shift.log" \
    "^CHECK FAILED: Table 1 SWA n=8192 M1"
expect_grep "2. only those two checks failed" "$TMP/shift.log" "^checks: 11 run, 2 failed$"

run_expect "3. the same shifted data with --z-ci 50" 0 "$TMP/zci.log" -- \
    tables --rows "${SHIFT[@]}" --out "$S/zci" --no-plots --check --z-ci 50
expect_grep "3. Table 1 check passes within 50 SE" "$TMP/zci.log" \
    "^check passed: Table 1 SWA n=8192 M1 mean .*50 SE"

run_expect "4. SWA sd of M2 not falling with n" 1 "$TMP/sdexp.log" -- \
    tables --rows "$D/swa2048" "$D/swa8192_m2sd" --out "$S/sdexp" --no-plots --check
expect_grep "4. sd exponent check of M2 failed (n^0)" "$TMP/sdexp.log" \
    "^CHECK FAILED: SWA sd of M2 ~ n\^-?0\.000 "
expect_grep "4. sd exponent of M1 still -0.5" "$TMP/sdexp.log" \
    "^check passed: SWA sd of M1 ~ n\^-0\.500 "
expect_grep "4. only that check failed" "$TMP/sdexp.log" "^checks: 8 run, 1 failed$"

run_expect "5. SWA M1 sd twice eq. (47)" 1 "$TMP/nsd.log" -- \
    tables --rows "$D/swa2048_sd2" "$D/swa8192_sd2" --out "$S/nsd" --no-plots --check
expect_grep "5. normalised-sd check failed (+100 %)" "$TMP/nsd.log" \
    "^CHECK FAILED: SWA n=2048 normalised sd of M1 vs eq. \(47\).*worst \+100\.0%"
expect_grep "5. only the two normalised-sd checks failed" "$TMP/nsd.log" "^checks: 8 run, 2 failed$"

run_expect "6. DSA1 M1 mean at 9.9e3" 1 "$TMP/dsa1.log" -- \
    tables --rows "$D/dsa1_exact" --out "$S/dsa1" --no-plots --check
expect_grep "6. DSA1 check failed (0 SE above)" "$TMP/dsa1.log" \
    "^CHECK FAILED: DSA1 n=2048 M1 mean 9900 above 9900 by -?0\.00 SE"

# realisation means scattered 3x more than independent samples would (correlated samples):
# R = 4 takes the SE from the realisation means, 3 x 106 -> 1.89 SE; R = 2 from the samples
run_expect "6b. DSA1 with correlated samples, R = 4" 1 "$TMP/corr4.log" -- \
    tables --rows "$D/dsa1_corr4" --out "$S/corr4" --no-plots --check
expect_grep "6b. DSA1 check failed on the realisation-mean SE" "$TMP/corr4.log" \
    "^CHECK FAILED: DSA1 n=2048 M1 mean 10500 above 9900 by 1\.89 SE \(SE 317 from realisations, R=4"
run_expect "6c. DSA1 with correlated samples, R = 2" 0 "$TMP/corr2.log" -- \
    tables --rows "$D/dsa1_corr2" --out "$S/corr2" --no-plots --check
expect_grep "6c. DSA1 check passes on the sample SE" "$TMP/corr2.log" \
    "^check passed: DSA1 n=2048 M1 mean 10500 above 9900 by 4\.01 SE \(SE 150 from samples, R=2"

run_expect "7. DSA2 M2 mean falling with n" 1 "$TMP/dsa2.log" -- \
    tables --rows "$D/dsa2_2048_hi" "$D/dsa2_8192_lo" --out "$S/dsa2" --no-plots --check
expect_grep "7. DSA2 rise check failed" "$TMP/dsa2.log" "^CHECK FAILED: DSA2 M2 mean rises from 5.5e\+07"
expect_grep "7. DSA2 closer-to-SWA check failed" "$TMP/dsa2.log" "^CHECK FAILED: DSA2 M2 at n=8192 is closer"

# ---------------------------------------------------------------- 8. bad input
run_expect "8. row without realisation_* or samples" 2 "$TMP/empty.log" -- \
    tables --rows "$D/swa2048" "$D/empty" --out "$S/empty" --no-plots
expect_grep "8. no-realisation message" "$TMP/empty.log" "empty holds no realisation_\* folder"
run_expect "8. two rows both SWA n=2048" 2 "$TMP/twice.log" -- \
    tables --rows "$D/swa2048" "$D/swa2048_again" --out "$S/twice" --no-plots --check
expect_grep "8. duplicate-row message" "$TMP/twice.log" "are both SWA n=2048"
run_expect "8. realisations sharing a seed" 2 "$TMP/dupseed.log" -- \
    tables --rows "$D/swa2048_dupseed" --out "$S/dupseed" --no-plots --check
expect_grep "8. shared-seed message" "$TMP/dupseed.log" "share seeds"

run_expect "8. one folder pooled with itself (DIR+DIR)" 2 "$TMP/selfpool.log" -- \
    tables --rows "$D/swa2048+$D/swa2048" --out "$S/selfpool" --no-plots
expect_grep "8. self-pooling shares seeds" "$TMP/selfpool.log" "share seeds"
run_expect "8. SWA pooled with a DSA1 folder" 2 "$TMP/mixpool.log" -- \
    tables --rows "$D/swa2048+$D/dsa1_2048" --out "$S/mixpool" --no-plots
expect_grep "8. mixed pooling names the attribute" "$TMP/mixpool.log" "attribute algorithm"

# ---------------------------------------------------------------- 8b. a row pooled from two folders
# swa2048 (3 realisations, timing 12.5 s wall / 48.25 core-s) + swa2048_again (3, no timing):
# one row of 6 realisations, 306 samples, mean exactly 9877 (both folders have that mean)
run_expect "8b. DIR1+DIR2 pooled into one row" 0 "$TMP/pool.log" -- \
    tables --rows "$D/swa2048+$D/swa2048_again" "$D/swa8192" --out "$S/pool" --no-plots
if "$PY" - "$S/pool" <<'EOF'
import csv, math, sys
r = [x for x in csv.DictReader(open(sys.argv[1] + "/table1.csv")) if x["n"] == "2048"]
good = (len(r) == 1 and r[0]["realisations"] == "6" and r[0]["samples"] == "306"
        and math.isclose(float(r[0]["mean"]), 9877, rel_tol=1e-9))
w = [x for x in csv.DictReader(open(sys.argv[1] + "/rows.csv")) if x["n"] == "2048"]
good = good and len(w) == 1 and w[0]["wallSeconds"] == "" and "+" in w[0]["folder"]
sys.exit(0 if good else 1)
EOF
then ok "8b. pooled row: R = 6, 306 samples, mean 9877, no partial timing"
else ko "8b. pooled row table1.csv/rows.csv"; fi

# ---------------------------------------------------------------- 9. constant kernel
run_expect "9. constant-kernel row, no --check" 0 "$TMP/const.log" -- \
    tables --rows "$D/const256" --out "$TMP/const"
for f in figure3.png figure4.png figure5.png figure6.png table1.csv rows.csv; do
    [ -s "$TMP/const/$f" ] && ok "9. output $f written" || ko "9. output $f missing"
done
ls "$TMP/const"/figure[7-9].png "$TMP/const"/figure10.png > /dev/null 2>&1 \
    && ko "9. additive-kernel figures without such rows" || ok "9. no figure7..10 without additive rows"
"$PY" -c "
import csv, sys
r = list(csv.DictReader(open('$TMP/const/table1.csv')))
sys.exit(0 if len(r) == 1 and r[0]['method'] == 'SWA' and r[0]['n'] == '256'
         and r[0]['samples'] == '242' and r[0]['tStart'] == '0.4' else 1)" \
    && ok "9. constant row tabulated (242 samples from t = 0.4)" || ko "9. constant row table1.csv"

# ---------------------------------------------------------------- 10. unequal realisations, --t-end
# realisations of 51, 51 and 26 samples: the pooled mean is exact only if weighted by counts
run_expect "10. realisations of unequal length --check" 0 "$TMP/short.log" -- \
    tables --rows "$D/swa2048_short" --out "$S/short" --no-plots --check
expect_grep "10. three checks run (one SWA row), none failed" "$TMP/short.log" "^checks: 3 run, 0 failed$"
run_expect "10. the same row with --t-end 0.3" 0 "$TMP/tend.log" -- \
    tables --rows "$D/swa2048_short" --out "$S/tend" --no-plots --t-end 0.3
if "$PY" - "$S" <<'EOF'
import csv, math, sys
d = sys.argv[1]
r = list(csv.DictReader(open(d + "/short/table1.csv")))
good = (len(r) == 1 and int(r[0]["samples"]) == 128 and float(r[0]["tEnd"]) == 0.4
        and math.isclose(float(r[0]["mean"]), 9877, rel_tol=1e-7)
        and math.isclose(float(r[0]["sd"]), 248.747, rel_tol=1e-5))
r = list(csv.DictReader(open(d + "/tend/table1.csv")))
good = good and len(r) == 1 and int(r[0]["samples"]) == 78 and float(r[0]["tEnd"]) == 0.3
sys.exit(0 if good else 1)
EOF
then ok "10. count-weighted pooled mean and sd exact (128 samples); --t-end 0.3: 78 samples"
else ko "10. table1.csv of unequal realisations / --t-end"; fi

# ---------------------------------------------------------------- 11. a single run as a row
run_expect "11. one run given directly as a row (no realisation_*)" 0 "$TMP/single.log" -- \
    tables --rows "$D/swa2048/realisation_0" --out "$S/single" --no-plots
"$PY" -c "
import csv, sys
r = list(csv.DictReader(open('$S/single/table1.csv')))
sys.exit(0 if len(r) == 1 and r[0]['realisations'] == '1' and r[0]['samples'] == '51'
         and r[0]['ci95_realisations'] == '' and r[0]['ci95'] != '' else 1)" \
    && ok "11. R = 1, 51 samples, no realisation-mean ci95" || ko "11. table1.csv of a single run"

# ---------------------------------------------------------------- 12. a row of 12 realisations
run_expect "12. a row of 12 realisations (realisation_0..realisation_11)" 0 "$TMP/r12.log" -- \
    tables --rows "$D/swa2048_R12" --out "$S/r12" --no-plots
"$PY" -c "
import csv, sys
r = list(csv.DictReader(open('$S/r12/table1.csv')))
sys.exit(0 if len(r) == 1 and r[0]['realisations'] == '12' and r[0]['samples'] == '612' else 1)" \
    && ok "12. every realisation pooled: R = 12, 612 samples" || ko "12. table1.csv of a row of 12 realisations"

# ---------------------------------------------------------------- 13. eq. (47) in every cell
run_expect "13. M1 sd twice eq. (47) in the last cell only" 1 "$TMP/lastsd.log" -- \
    tables --rows "$D/swa2048_lastsd" --out "$S/lastsd" --no-plots --check
expect_grep "13. normalised-sd check failed on that cell" "$TMP/lastsd.log" \
    "^CHECK FAILED: SWA n=2048 normalised sd of M1 vs eq. \(47\).*worst \+99\.[0-9]% at x=0\.099"
expect_grep "13. only that check failed" "$TMP/lastsd.log" "^checks: 3 run, 1 failed$"

finish
