#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# The three splitting schemes against their own exact expectations.
#
# Without coagulation (K0 = 1e-30) every particle keeps its mass, and a split step's
# inception makes a cohort placed uniformly in its cells that the scheme then displaces by
# a fixed distance: h = u dt per later step, plus h (Lie: S(dt) then A(dt)) or h/2 (Strang:
# A(dt/2) S(dt) A(dt/2)) in its own step; with StrangSAS, S(dt/2) A(dt) S(dt/2), half of a
# step's cohort moves h in its own step and half does not. The incepted part of M_k is
# therefore a staircase,
#     Lie   I dt floor(x/h),   Strang   I dt floor(x/h + 1/2),   StrangSAS   I dt (floor(x/h) + 1/2),
# whose cell averages differ from the exact I x/u by -h/2 (first order) and by a bounded
# O(h^2/dx) oscillation (second order) respectively; the inflow c_in 3^k is exact for all
# (entering particles are spread over the distance of each transport). With dt = 2.4e-3
# (Courant 0.6, dx/h = 5/3) the two predictions differ in cell 0 by 48 % of the incepted
# mass (cells 0..2 together: over 10 standard errors), so a scheme run in the wrong order
# fails; StrangSAS and Lie differ in cell 0 by 60 %. Every cell's time average must agree
# with its scheme's prediction within |z| <= 6 (the report's 95 % interval; samples in time
# are correlated, hence the widening), the balances must close, no two particles may share
# their (y, z) (a cell step that draws from another's streams places its particles where
# those were), and Strang and StrangSAS must give the same bits on 1 and 2 threads and after
# a restart.
. "$(dirname "$0")/caseLib.sh"
dt=2.4e-3; rate=3e8; cIn=2e5

runScheme()
{
    local scheme=$1 name=$2 end=$3 write=$4 n=$5
    local d; d=$(newCase constantKernelDuct "$name")
    cd "$d"
    setEntry . constant/coagulationProperties splitting "$scheme"   # the tutorial names Lie
    setEntry . constant/coagulationProperties kernel/K0 1e-30
    setEntry . constant/coagulationProperties inception/rate $rate
    setEntry . constant/coagulationProperties inflow/density $cIn
    setEntry . constant/coagulationProperties inflow/mass 3
    setEntry . constant/coagulationProperties statisticalWeight/n "$n"
    setEntry . constant/coagulationProperties sampling/tRelax 0.24
    setEntry . constant/coagulationProperties sampling/sampleInterval 4.8e-3
    setEntry . system/controlDict deltaT $dt
    setEntry . system/controlDict endTime "$end"
    setEntry . system/controlDict writeInterval "$write"
    [ -n "${WRITEFORMAT:-}" ] && setEntry . system/controlDict writeFormat "$WRITEFORMAT"
    foamDictionary -entry functions -remove system/controlDict > /dev/null
    runApplication coagulationFoam
    grep -q "^Splitting $scheme" log.coagulationFoam || fail "$name: the log does not say 'Splitting $scheme'"
    checkBalance log.coagulationFoam
}

for scheme in Lie Strang StrangSAS; do
    WRITEFORMAT=ascii runScheme $scheme "split_$scheme" 1.44 1.44 2048
    # no coagulation: particles never interact, samples a cell transit apart are independent
    $report --case . --out results --no-plots --analytic none --correlation-time 0 > log.report \
        || fail "report failed"
done

"$COAGULATIONFOAM_PYTHON" - "$workDir" $dt $rate $cIn <<'PY' || fail "a scheme's moments are off its exact expectation"
import sys
import numpy as np
work, dt, rate, c_in = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
u, dx, h = 1.0, 4e-3, 1.0 * float(sys.argv[2])
# (shift inside the floor, offset outside)
shift = {"Lie": (0.0, 0.0), "Strang": (0.5, 0.0), "StrangSAS": (0.0, 0.5)}

def staircase(scheme, a, b):
    """cell average over [a, b] of I dt (floor(x/h + shift) + offset): the incepted M_k of
    mass-1 particles"""
    x = np.linspace(a, b, 200001)
    s, o = shift[scheme]
    return rate * dt * np.trapz(np.floor(x / h + s) + o, x) / (b - a)

bad, res = [], {}
for scheme in ("Lie", "Strang", "StrangSAS"):
    f = np.genfromtxt("%s/split_%s/results/moments_full.csv" % (work, scheme), delimiter=",", names=True)
    x = f["x"]
    res[scheme] = f
    worst = 0.0
    for k in range(4):
        pred = np.array([c_in * 3.0**k + staircase(scheme, xc - dx / 2, xc + dx / 2) for xc in x])
        se = f["M%d_ci95" % k] / 1.96
        z = (f["M%d_mean" % k] - pred) / se
        worst = max(worst, np.abs(z).max())
        if np.any(np.abs(z) > 6):
            i = int(np.argmax(np.abs(z)))
            bad.append("%s M%d: cell x=%.4g mean %.6g, scheme's expectation %.6g (z = %.1f)"
                       % (scheme, k, x[i], f["M%d_mean" % k][i], pred[i], z[i]))
    exact = c_in * 3 + rate * x / u
    err = f["M1_mean"] / exact - 1
    print("%-9s worst |z| against its expectation %.2f; M1 - exact (c_in 3 + I x/u) in cells 0..3: %s"
          % (scheme, worst, " ".join("%+.2f%%" % (100 * e) for e in err[:4])))
# each second-order expectation is far from Lie's in cell 0: each run is told from Lie's
lie = res["Lie"]
for other in ("Strang", "StrangSAS"):
    st = res[other]
    z = (lie["M1_mean"][:3] - st["M1_mean"][:3]) / np.hypot(lie["M1_ci95"][:3], st["M1_ci95"][:3]) * 1.96
    sep = np.sqrt(np.sum(z**2))
    print("cells 0..2: Lie and %s M1 differ by %.1f standard errors (root sum of squares)" % (other, sep))
    if sep < 10:
        bad.append("Lie and %s are not told apart in cells 0..2 (%.1f standard errors)" % (other, sep))
# every cell step draws from its own streams: particles incepted from the same stream sit at
# the same (y, z) (the flow moves them along x only), so no two may share them
import re
for scheme in ("Lie", "Strang", "StrangSAS"):
    text = open("%s/split_%s/1.44/lagrangian/coagulationCloud/positions" % (work, scheme)).read()
    yz = re.findall(r"\(\s*[-+0-9.eE]+\s+([-+0-9.eE]+)\s+([-+0-9.eE]+)\s*\)", text)
    shared = len(yz) - len(set(yz))
    print("%-9s %d particles, %d sharing another's (y, z)" % (scheme, len(yz), shared))
    if len(yz) < 1000 or shared > 0:
        bad.append("%s: %d of %d particles share (y, z) with another (streams drawn twice)"
                   % (scheme, shared, len(yz)))
for b in bad:
    print("FAIL:", b)
sys.exit(1 if bad else 0)
PY

# Strang and StrangSAS: the same bits on 2 threads and after a restart (a short run, written
# halfway)
for scheme in Strang StrangSAS; do
    runScheme $scheme ${scheme}_full 0.24 0.12 256
    OMP_NUM_THREADS=2 runScheme $scheme ${scheme}_threads 0.24 0.12 256
    runScheme $scheme ${scheme}_restart 0.12 0.12 256
    setEntry . system/controlDict endTime 0.24
    runApplication -s restart coagulationFoam
    grep -q "Create mesh for time = 0.12" log.coagulationFoam.restart || fail "$scheme: did not restart from 0.12"
    for other in ${scheme}_threads ${scheme}_restart; do
        for f in M0 M1 M2 M3 lagrangian/coagulationCloud/mass lagrangian/coagulationCloud/weight \
                 lagrangian/coagulationCloud/coordinates
        do
            cmp -s "$workDir/${scheme}_full/0.24/$f" "$workDir/$other/0.24/$f" \
                || fail "$scheme: 0.24/$f differs between the full run and $other"
        done
    done
done
echo "PASS splitting: Lie, Strang and StrangSAS each at their exact expectation, the second-order ones told from Lie; Strang and StrangSAS identical on 2 threads and after a restart"
