#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Field-driven sources: an inception rate and a Saffman-Turner kernel that
# differ from cell to cell, read from volScalarFields of the start time. On the duct with
# U = 0 every cell is a closed box, a process of its own (its own random stream), so
#   inception  the 'field' inception model, no coagulation (K0 = 1e-30), a rate field that is
#              0 in cells 0..9 and a ramp I_c = 3e8 (c - 9)/40 in cells 10..49, n = 8192: the
#              count of cell c after T = 0.05 is Poisson with mean I_c V T/W (38 to 1536). Every cell within its two-sided
#              Poisson interval at level 1e-3/50 (scipy), the total within its own, the
#              zero-rate cells empty, and the sum of (N - mean)^2/mean over the 40 cells
#              within chi2(40)'s 1e-3 quantiles.
#   kernel     the 'localSaffmanTurner' kernel, epsilon 1e-3 in the upstream half and 1.6e-2
#              downstream, nu 1e-5 from constant/transportProperties, coefficient 1e-8: the
#              cell prefactors are K0 = 1e-7 and 4e-7 (K_11 n T = 0.6 and 2.4 at T = 0.05).
#              With uniform inception 3e8 from empty cells, n = 4096, each half must be distributed as the cells of a run of the core's
#              saffmanTurner kernel with that K0 in every cell (another seed): the half's
#              mean M0 and M2 against the reference run's, z = difference / its standard
#              error from the cells' spread, |z| < 4 (and the two references apart by more
#              than 10 standard errors, so that a kernel of the wrong cell is seen). The
#              same run with epsilon under another name and nu as a field ('epsilon
#              dissipation; nu nu;') is the same bit for bit.
#   fieldSources.sh [name...]   run only the named cases (default: both)
. "$(dirname "$0")/caseLib.sh"

only=("$@")
want() { [ "${#only[@]}" -eq 0 ] || [[ " ${only[*]} " == *" $1 "* ]]; }
passed=0

runSolver()
{
    local rc=0
    timeout 300 coagulationFoam > log.coagulationFoam 2>&1 || rc=$?
    [ "$rc" -eq 0 ] || { tail -20 log.coagulationFoam; fail "$1: coagulationFoam exit $rc"; }
}

samples() { echo "$1/postProcessing/coagulationSamples/samples_0.h5"; }

# writeField case name dimensions python-expression-of-c (c = cell index 0..49)
writeField()
{
    "$COAGULATIONFOAM_PYTHON" - "$@" <<'PY'
import sys
case, name, dims, expr = sys.argv[1:5]
values = [eval(expr, {"c": c}) for c in range(50)]
with open("%s/0/%s" % (case, name), "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class volScalarField; object %s; }\n" % name)
    f.write("dimensions %s;\n" % dims)
    f.write("internalField nonuniform List<scalar> 50 (%s);\n" % " ".join("%.17g" % v for v in values))
    f.write('boundaryField { ".*" { type zeroGradient; } sides { type empty; } }\n')
PY
}

# A closed box of 50 cells (U = 0), T = 0.05, n = 8192 (W = 6.25e-4), samples from t = 0
setUp()
{
    setEntry . 0/U internalField "uniform (0 0 0)"
    setEntry . 0/U boundaryField/inlet/value "uniform (0 0 0)"
    setEntry . constant/coagulationProperties statisticalWeight/n 8192
    setEntry . constant/coagulationProperties sampling/tRelax 0
    setEntry . system/controlDict endTime 0.05
    setEntry . system/controlDict writeInterval 0.05
}

# ---- inception: the rate of every cell from a field
if want inception; then
    c=$(newCase constantKernelDuct fieldSources_inception)
    cd "$c"
    setUp
    setEntry . constant/coagulationProperties kernel/K0 1e-30
    setEntry . constant/coagulationProperties inception "{ type field; field inceptionRate; mass 1; }"
    writeField . inceptionRate "[0 -3 -1 0 0 0 0]" "0 if c < 10 else 3e8*(c - 9)/40"
    runSolver inception
    checkBalance log.coagulationFoam
    grep -q "Inception rate from field inceptionRate: 0 to 300000000 per unit volume and time, 40 cells" log.coagulationFoam \
        || fail "inception: the log does not give the field's range and 40 cells"
    [ -f 0.05/inceptionRate ] || fail "inception: the rate field is not written with the time (a restart would miss it)"
    "$COAGULATIONFOAM_PYTHON" - "$(samples "$c")" <<'PY' || fail "inception: counts are not the field's rate V T/W"
import sys
import h5py
import numpy as np
from scipy import stats
f = h5py.File(sys.argv[1], "r")
T, V = 0.05, 0.2 / 50 * 0.004**2
t = f["time"][-1]
assert abs(t - T) < 1e-9, t
W = float(f.attrs["particleWeight"])
N = np.rint(f["moments"][-1, :, 0] * V / W).astype(int)
c = np.arange(50)
rate = np.where(c < 10, 0.0, 3e8 * (c - 9) / 40)
lam = rate * V * T / W
alpha = 1e-3 / 50
bad = []
if N[:10].any():
    bad.append("zero-rate cells incepted: %s" % N[:10])
lo, hi = stats.poisson.ppf(alpha / 2, lam[10:]), stats.poisson.ppf(1 - alpha / 2, lam[10:])
out = np.flatnonzero((N[10:] < lo) | (N[10:] > hi)) + 10
print("inception: W %g, counts %d (cell 10, mean %.1f) .. %d (cell 49, mean %.1f)"
      % (W, N[10], lam[10], N[49], lam[49]))
if out.size:
    bad.append("cells outside their Poisson interval: %s (counts %s, means %s)" % (out, N[out], lam[out]))
total, mean = N.sum(), lam.sum()
tlo, thi = stats.poisson.ppf(1e-4, mean), stats.poisson.ppf(1 - 1e-4, mean)
print("inception: total %d, Poisson mean %.1f, interval [%d, %d]" % (total, mean, tlo, thi))
if not tlo <= total <= thi:
    bad.append("total outside its interval")
chi2 = (((N[10:] - lam[10:]) ** 2) / lam[10:]).sum()
clo, chi = stats.chi2.ppf(5e-4, 40), stats.chi2.ppf(1 - 5e-4, 40)
print("inception: sum (N - mean)^2/mean = %.1f over 40 cells, chi2(40) interval [%.1f, %.1f]" % (chi2, clo, chi))
if not clo <= chi2 <= chi:
    bad.append("chi2 outside its interval")
for b in bad:
    print("inception: " + b)
sys.exit(1 if bad else 0)
PY
    passed=$((passed + 1)); echo "ok inception"
fi

# ---- kernel: Saffman-Turner on each cell's epsilon
if want kernel; then
    base=$(newCase constantKernelDuct fieldSources_kernelBase)
    cd "$base"
    setUp
    setEntry . constant/coagulationProperties statisticalWeight/n 4096
    cd ..
    # the reference runs: the core's kernel with each half's K0 in every cell
    for ref in A:1e-7:2 B:4e-7:3; do
        IFS=: read -r name K0 seed <<< "$ref"
        rm -rf "fieldSources_kernel$name"; cp -r "$base" "fieldSources_kernel$name"
        cd "fieldSources_kernel$name"
        setEntry . constant/coagulationProperties kernel "{ type saffmanTurner; K0 $K0; }"
        setEntry . constant/coagulationProperties seed "$seed"
        runSolver "kernel reference $name"
        checkBalance log.coagulationFoam
        cd ..
    done
    rm -rf fieldSources_kernelLocal; cp -r "$base" fieldSources_kernelLocal
    cd fieldSources_kernelLocal
    setEntry . constant/coagulationProperties kernel "{ type localSaffmanTurner; coefficient 1e-8; }"
    writeField . epsilon "[0 2 -3 0 0 0 0]" "1e-3 if c < 25 else 1.6e-2"
    cat > constant/transportProperties <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
transportModel  Newtonian;
nu              [0 2 -1 0 0 0 0] 1e-05;
DICT
    runSolver "kernel local"
    checkBalance log.coagulationFoam
    cd ..
    # the same with epsilon under another name and nu as a field: the same run, bit for bit
    rm -rf fieldSources_kernelFields; cp -r fieldSources_kernelLocal fieldSources_kernelFields
    cd fieldSources_kernelFields
    rm -rf 0.05 postProcessing constant/transportProperties
    mv 0/epsilon 0/dissipation
    sed -i 's/object epsilon;/object dissipation;/' 0/dissipation
    writeField . nu "[0 2 -1 0 0 0 0]" "1e-05"
    setEntry . constant/coagulationProperties kernel "{ type localSaffmanTurner; coefficient 1e-8; epsilon dissipation; nu nu; }"
    runSolver "kernel fields"
    cd ..
    "$COAGULATIONFOAM_PYTHON" - "$(samples fieldSources_kernelLocal)" "$(samples fieldSources_kernelFields)" <<'PY' \
        || fail "kernel: epsilon and nu as named fields do not give the run of epsilon and transportProperties"
import sys
import h5py
import numpy as np
a, b = (h5py.File(p, "r")["moments"][:] for p in sys.argv[1:3])
print("kernel: 'epsilon dissipation; nu nu;' (fields) against epsilon and transportProperties: %s"
      % ("identical" if np.array_equal(a, b) else "different"))
sys.exit(0 if np.array_equal(a, b) else 1)
PY
    "$COAGULATIONFOAM_PYTHON" - "$(samples fieldSources_kernelLocal)" "$(samples fieldSources_kernelA)" "$(samples fieldSources_kernelB)" <<'PY' \
        || fail "kernel: a half is not distributed as the uniform kernel of its epsilon"
import sys
import h5py
import numpy as np
local, A, B = (h5py.File(p, "r")["moments"][-1] for p in sys.argv[1:4])
bad = []
def z(a, b):
    return (a.mean() - b.mean()) / np.sqrt(a.var(ddof=1) / len(a) + b.var(ddof=1) / len(b))
for k in (0, 2):
    for half, ref, cells in (("upstream (epsilon 1e-3)", A, slice(0, 25)),
                             ("downstream (epsilon 1.6e-2)", B, slice(25, 50))):
        zk = z(local[cells, k], ref[:, k])
        print("kernel: M%d %s: local %.5g, uniform-kernel run %.5g, z = %.2f"
              % (k, half, local[cells, k].mean(), ref[:, k].mean(), zk))
        if abs(zk) > 4:
            bad.append("M%d %s" % (k, half))
    zAB = z(A[:, k], B[:, k])
    print("kernel: M%d, the two references apart by z = %.1f" % (k, zAB))
    if k == 0 and abs(zAB) < 10:
        bad.append("the references are too close to tell the halves apart")
for b in bad:
    print("kernel: off: " + b)
sys.exit(1 if bad else 0)
PY
    # the log's prefactor range; epsilon written with the time
    cd fieldSources_kernelLocal
    awk '/K0 = coefficient sqrt\(epsilon\/nu\) from/ { lo = $(NF - 2); hi = $NF }
         END { exit !(lo / 1e-7 - 1 < 1e-12 && 1 - lo / 1e-7 < 1e-12 && hi / 4e-7 - 1 < 1e-12 && 1 - hi / 4e-7 < 1e-12) }' \
        log.coagulationFoam || fail "kernel: the log does not give the cell prefactors 1e-7 and 4e-7"
    [ -f 0.05/epsilon ] || fail "kernel: epsilon is not written with the time (a restart would miss it)"
    passed=$((passed + 1)); echo "ok kernel"
fi

echo "PASS fieldSources: $passed cases (field inception against Poisson, local Saffman-Turner against uniform runs)"
