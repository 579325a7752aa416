#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Coverage of the report's 95 % intervals on the constant duct (issue 18): 4 runs of the
# tutorial (seeds 11..14, SWA n = 256, endTime 2.0, tRelax 0.4: 321 samples a cell).
#  - single run: the fraction of (cells 3..49) x (M0..M3) x (4 runs) whose interval
#    (correlated samples: tau_int, n_eff, Student t) holds the analytic cell average
#    must be in [0.90, 0.99]; the independent-sample interval's fraction is printed;
#  - the 4 runs pooled (--realisations, t with 3 dof): the same fraction in [0.90, 0.99].
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

"$COAGULATIONFOAM_PYTHON" - "$pooled" "${runs[@]}" <<'PY' || fail "interval coverage outside [0.90, 0.99]"
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
bad = [name for name, c in (("single-run", cov), ("pooled", covR)) if not 0.90 <= c <= 0.99]
for b in bad:
    print("FAIL: %s coverage outside [0.90, 0.99]" % b)
sys.exit(1 if bad else 0)
PY
echo "PASS coverage: single-run and pooled 95 % intervals hold the analytic moments at their rate"
