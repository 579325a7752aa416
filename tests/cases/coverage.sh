#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Coverage of the report's 95 % intervals on the constant duct: 4 runs of the
# tutorial (seeds 11..14, SWA n = 256, endTime 2.0, tRelax 0.4, a sample every 5e-4 s, 5
# steps: 3201 samples a cell, tau_int 2.3 to 12 samples, median 4.5).
#  - single run: the fraction of (cells 3..49) x (M0..M3) x (4 runs) whose interval
#    (correlated samples: tau_int, n_eff, Student t) holds the analytic cell average
#    must be in [0.90, 0.995]; the independent-sample interval's fraction is printed
#    (0.50 in two seed sets);
#  - the 4 runs pooled (--realisations, t with 3 dof): the same fraction at least 0.80.
#    Its half-width is half a run's, and there the method's own bias (SWA at n = 256 and the
#    splitting, a few tenths of a per cent) shows: measured 0.85 to 0.99, mean 0.91, over
#    8 seed sets and both random engines; with the tutorial's sample every 5e-3 s (tau_int
#    0.6) the iid interval held 0.88 to 0.99 of them, inside the band in 3 of 6 seed sets.
# COAGULATIONPOST_IID_INTERVAL=1 removes the correction (the test must then fail).
#   coverage.sh [endTime]
. "$(dirname "$0")/caseLib.sh"
endTime="${1:-2.0}"

runs=()
for seed in 11 12 13 14; do
    case=$(newCase constantKernelDuct "coverage_$seed")
    (
        cd "$case"
        setEntry . constant/coagulationProperties seed "$seed"
        setEntry . constant/coagulationProperties algorithm SWA
        setEntry . constant/coagulationProperties statisticalWeight/n 256
        setEntry . constant/coagulationProperties sampling/tRelax 0.4
        setEntry . constant/coagulationProperties sampling/sampleInterval 5e-4
        setEntry . system/controlDict endTime "$endTime"
        setEntry . system/controlDict writeInterval "$endTime"
        runApplication coagulationFoam
        $report --case . --out results --no-plots > log.report || fail "report failed (seed $seed)"
    ) || exit 1
    runs+=("$case")
done
pooled="$workDir/coverage_pooled"
rm -rf "$pooled"
$report --case "$workDir" --out "$pooled" --no-plots --realisations "${runs[@]}" \
    > "$workDir/log.coverage_pooled" || fail "pooled report failed"

"$COAGULATIONFOAM_PYTHON" - "$pooled" "${runs[@]}" <<'PY' || fail "interval coverage outside its band"
import sys
import numpy as np
pooled, runs = sys.argv[1], sys.argv[2:]

def load(d):
    return np.genfromtxt(d + "/moments_full.csv", delimiter=",", names=True)

def covered(f, col):
    c = [np.abs(f["M%d_mean" % k][3:50] - f["M%d_analytic" % k][3:50]) <= f["M%d_%s" % (k, col)][3:50]
         for k in range(4)]
    return np.concatenate(c)

single = [load(r + "/results") for r in runs]
assert all(len(f) == 50 for f in single), "expected 50 cells"
cov = np.concatenate([covered(f, "ci95") for f in single]).mean()
iid = np.concatenate([covered(f, "ci95_iid") for f in single]).mean()
neff = np.concatenate([[f["M%d_neff" % k][3:50] for k in range(4)] for f in single])
tau = np.concatenate([[f["M%d_tauInt" % k][3:50] for k in range(4)] for f in single])
p = load(pooled)
covR = covered(p, "ci95").mean()
covRiid = covered(p, "ci95_iid").mean()
n = 47 * 4 * len(runs)
print("single runs: %d cell-moments; tau_int %.1f..%.1f (median %.1f) samples, n_eff %.0f..%.0f"
      % (n, tau.min(), tau.max(), np.median(tau), neff.min(), neff.max()))
print("coverage of the nominal 95 %% intervals: single-run %.3f, single-run iid %.3f, "
      "%d realisations pooled %.3f (iid %.3f)" % (cov, iid, len(runs), covR, covRiid))
bad = [name for name, c, lo, hi in (("single-run", cov, 0.90, 0.995), ("pooled", covR, 0.80, 1.0))
       if not lo <= c <= hi]
for b in bad:
    print("FAIL: %s coverage outside its band (single run [0.90, 0.995], pooled >= 0.80)" % b)
sys.exit(1 if bad else 0)
PY
echo "PASS coverage: single-run and pooled 95 % intervals hold the analytic moments at their rate"
