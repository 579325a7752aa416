#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Particles that grow and shrink, in a closed box at rest (4 x 4 cells, nothing moves), against
# exact answers:
#   growth.sh exact       no coagulation, monodisperse 10 nm particles of 1800 kg/m3 (masses in
#                         kg): every cell stays monodisperse (M0 M2 = M1^2) at the exact size
#                         after 0.04 s of surface growth from a field k_s of its own
#                         (d = d0 + 2 k_s t / rho), of free-molecular condensation
#                         (d(d)/dt = alpha cbar dc / (2 rho)), of continuum condensation
#                         (d(d^2)/dt = 8 D dc / rho) and of transition condensation (the
#                         Fuchs-Sutugin rate's time to grow from d0 to d, in closed form); the
#                         growthRate field of the surface growth, the last step's mass gain
#                         per volume and time
#   oxidation             surface oxidation from a field, factor -1, minimumDiameter 2 nm: before
#                         the exact time the particles reach 2 nm none is gone and the size is
#                         exact; after it every particle is gone, booked as gone by shrinking
#                         (its number), the growth term -N w (m0 - m_min) and the loss term
#                         N w m_min exactly, the balances closed (serially and decomposed on 2
#                         processors)
#   moments ALGORITHM     the constant kernel (K0 = 5e-15 m3/s, N0 = 1e16 /m3: K0 N0 t = 2 at the
#                         end) with dm/dt = sigma m (sigma = 50 /s, two e-folding times) in
#                         16 x 16 closed cells, 1000 particles each, steps of 0.01 s (growth
#                         proportional to m commutes with the constant kernel's jumps: the split
#                         step is exact): M0, M1, M2 at 0.02 and 0.04 s against the closed
#                         moment equations, over the cells' independent realisations (99.9 %
#                         t-intervals)
#   duct                  the constant-kernel duct (inception, K0 = 1e-5, u = 1 m/s) with
#                         dm/dt = sigma m (sigma = 10 /s: e^2 at the outlet), Strang, SWA: the
#                         time-averaged M0, M1, M2 of every cell against the homogeneous
#                         solution at t = x/u (dM0/dt = I - K0 M0^2/2, dM1/dt = I + sigma M1,
#                         dM2/dt = I + 2 sigma M2 + K0 M1^2, averaged over the cell), each
#                         within 8 % or 4 standard errors (the first 3 cells skipped, as the
#                         duct tests do)
. "$(dirname "$0")/caseLib.sh"
mode="${1:?exact | oxidation | moments ALGORITHM}"
export PYTHONPATH="$COAGULATIONFOAM_DIR/tests/cases:$COAGULATIONFOAM_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}"

# boxCase name nx properties-body: a closed box at rest, nx x nx cells of 1 mm, with the
# coagulationProperties body given and a field kS (k_s per cell: 1e-4 (1 + cell index / 16)
# kg/(m2 s))
boxCase()
{
    local c
    c=$(newCase constantKernelDuct "growth_$1")
    cd "$c"
    rm -rf constant/polyMesh log.blockMesh
    NX="$2" BODY="$3" "$COAGULATIONFOAM_PYTHON" - <<'PY'
import os
from dispersionCases import HEADER, block_mesh, zero_velocity
nx = int(os.environ["NX"])
patches = {"walls": ("wall", ["left", "right", "bottom", "top"]),
           "frontAndBack": ("empty", ["frontAndBack"])}
open("system/blockMeshDict", "w").write(block_mesh(nx, nx, 1e-3 * nx, 1e-3 * nx, patches))
open("0/U", "w").write(zero_velocity(patches))
kS = [1e-4 * (1 + i / 16.0) for i in range(nx * nx)]
open("0/kS", "w").write(HEADER.format(cls="volScalarField", obj="kS")
    + "dimensions [1 -2 -1 0 0 0 0];\ninternalField nonuniform List<scalar> %d (%s);\n"
      "boundaryField\n{\n    walls { type zeroGradient; }\n    frontAndBack { type empty; }\n}\n"
    % (len(kS), " ".join(repr(k) for k in kS)))
open("constant/coagulationProperties", "w").write(
    HEADER.format(cls="dictionary", obj="coagulationProperties") + os.environ["BODY"])
PY
    runApplication blockMesh >&2
    foamDictionary -entry functions -remove system/controlDict > /dev/null 2>&1 || true
    setEntry . system/controlDict writeFormat ascii
    setEntry . system/controlDict writePrecision 17
    echo "$c"
}

# the body of a box without coagulation: SWA, 20 particles a cell of 10 nm at 1e12 per m3
common="
algorithm SWA;
splitting Strang;
kernel { type none; }
inception { rate 0; mass 1; }
particles { density 1800; }
statisticalWeight { n 20; V1 1e-12; }
seed 5;
sampling { tRelax 1; sampleInterval 0.01; }
initialPopulation { numberDensity 1e12; diameter 1e-8; }
"

case "$mode" in
exact)
    for model in surface freeMolecular continuum transition; do
        case $model in
        surface) g="coat { type surface; rate kS; }" ;;
        *) g="vapour { type condensation; concentration 1e-5; saturationConcentration 2e-6;
                       molarMass 0.098; diffusivity 1e-5; accommodation 0.8; T 400;
                       regime $model; }" ;;
        esac
        c=$(boxCase "exact_$model" 4 "$common
growth { $g }
")
        cd "$c"
        setEntry . system/controlDict deltaT 0.01
        setEntry . system/controlDict endTime 0.04
        setEntry . system/controlDict writeInterval 0.04
        runApplication coagulationFoam
        checkBalance log.coagulationFoam
        MODEL=$model "$COAGULATIONFOAM_PYTHON" - <<'PY' || fail "$model: the sizes are not the exact ones"
import os, sys
import numpy as np
from dispersionCases import read_field
model = os.environ["MODEL"]
rho, d0, t = 1800.0, 1e-8, 0.04
m0 = np.broadcast_to(read_field(".", "0.04", "M0"), 16)
m1 = np.broadcast_to(read_field(".", "0.04", "M1"), 16)
m2 = np.broadcast_to(read_field(".", "0.04", "M2"), 16)
mass = m1 / m0                                   # every particle's, in kg
d = (6 * mass / (np.pi * rho)) ** (1 / 3)
c, cs, M, D, alpha, T = 1e-5, 2e-6, 0.098, 1e-5, 0.8, 400.0
dc = c - cs
cbar = np.sqrt(8 * 8.314462618 * T / (np.pi * M))
if model == "surface":
    exact = d0 + 2 * 1e-4 * (1 + np.arange(16) / 16.0) * t / rho
    # growthRate: the last step's (0.03 to 0.04 s) mass per volume and time
    dOf = lambda tt: d0 + 2 * 1e-4 * (1 + np.arange(16) / 16.0) * tt / rho
    mOf = lambda tt: rho * np.pi * dOf(tt) ** 3 / 6
    rate = np.broadcast_to(read_field(".", "0.04", "growthRate"), 16)
    rateExact = m0 * (mOf(0.04) - mOf(0.03)) / 0.01
    rateErr = np.abs(rate / rateExact - 1).max()
    print("surface: growthRate %.4e .. %.4e kg/(m3 s), exact to %.1e" % (rate.min(), rate.max(), rateErr))
    if rateErr > 1e-9:
        sys.exit(1)
elif model == "freeMolecular":
    exact = np.full(16, d0 + alpha * cbar * dc * t / (2 * rho))
elif model == "continuum":
    exact = np.full(16, np.sqrt(d0 ** 2 + 8 * D * dc * t / rho))
else:
    # dt/dd = rho d / (4 D dc F): t(d) = rho/(4 D dc) [d^2/2 + (A-L) d + (B-(A-L)L) ln(d+L)]
    L = 2 * 3 * D / cbar
    r = 4 / (3 * alpha)
    A, B = (r + 0.377) * L, r * L * L
    tOf = lambda x: rho / (4 * D * dc) * (x * x / 2 + (A - L) * x + (B - (A - L) * L) * np.log(x + L))
    exact = None
    err = np.abs(tOf(d) - tOf(d0) - t) / t
    print("transition: d %.6e m, time to grow there %.12g of t" % (d[0], 1 - err.max()))
    ok = err.max() < 1e-7
mono = np.abs(m0 * m2 / m1 ** 2 - 1).max()
print("%s: monodisperse to %.1e" % (model, mono))
if exact is not None:
    rel = np.abs(d / exact - 1).max()
    print("%s: d %.6e .. %.6e m (from %.1e), exact to %.1e" % (model, d.min(), d.max(), d0, rel))
    ok = rel < 1e-10
sys.exit(0 if ok and mono < 1e-12 and d.min() > 1.05 * d0 else 1)
PY
        grep -q "Growth vapour: condensation ($model)\|Growth coat: surface" log.coagulationFoam \
            || fail "$model: the model is not in the log"
    done
    echo "PASS growth exact: surface growth from a field and condensation in its three regimes"
    ;;
oxidation)
    # d(d)/dt = -2 k_s / rho, k_s = 1e-4 (1 + i/16): cell 15 (the fastest) reaches 2 nm at
    # 8e-9 rho / (2 k_s) = 37 ms, cell 0 at 72 ms
    # (0.08 also decomposed on 2 processors: the bookings reduced over the ranks)
    for end in 0.03 0.08 0.08parallel; do
        c=$(boxCase "oxidation_$end" 4 "$common
growth { minimumDiameter 2e-9; oxidation { type surface; rate kS; factor -1; } }
")
        cd "$c"
        parallel=""
        [ "$end" = 0.08parallel ] && parallel=yes
        end=${end%parallel}
        setEntry . system/controlDict deltaT 0.01
        setEntry . system/controlDict endTime "$end"
        setEntry . system/controlDict writeInterval "$end"
        if [ -n "$parallel" ]; then
            runApplication decomposePar
            runParallel -np 2 coagulationFoam
        else
            runApplication coagulationFoam
        fi
        checkBalance log.coagulationFoam
        END=$end "$COAGULATIONFOAM_PYTHON" - <<'PY' || fail "oxidation to $end: off the exact answer"
import os, re, sys
import numpy as np
from dispersionCases import read_field
end = os.environ["END"]
log = open("log.coagulationFoam").read()
gone = re.findall(r"particles gone by shrinking = (\S+) \(number (\S+)\)", log)[-1]
masses = re.findall(r"mass initial \+ inflow \+ inception \+ growth - outflow - loss \+ control = "
                    r"(\S+) \+ (\S+) \+ (\S+) \+ (\S+) - (\S+) - (\S+) \+ (\S+)", log)[-1]
initial, grown, lost = float(masses[0]), float(masses[3]), float(masses[5])
rho, d0, dmin = 1800.0, 1e-8, 2e-9
m0, mmin = rho * np.pi * d0 ** 3 / 6, rho * np.pi * dmin ** 3 / 6
number0 = 1e12 * 16e-9            # 1e12 per m3 in 16 cells of 1 mm^3
if end == "0.03":
    M0 = np.broadcast_to(read_field(".", end, "M0"), 16)
    M1 = np.broadcast_to(read_field(".", end, "M1"), 16)
    d = (6 * (M1 / M0) / (np.pi * rho)) ** (1 / 3)
    exact = d0 - 2 * 1e-4 * (1 + np.arange(16) / 16.0) * 0.03 / rho
    rel = np.abs(d / exact - 1).max()
    print("0.03 s: none gone (%s), d %.4e .. %.4e m, exact to %.1e" % (gone[0], d.min(), d.max(), rel))
    sys.exit(0 if gone[0] == "0" and lost == 0 and rel < 1e-10 else 1)
print("0.08 s: gone %s particles, number %s (initial %.6g); growth %.10g (exact %.10g), "
      "loss %.10g (exact %.10g), initial mass %.10g"
      % (gone[0], gone[1], number0, grown, -number0 * (m0 - mmin), lost, number0 * mmin, initial))
# sources.csv: the growth and loss rows as the log's
import csv
rows = {r["source"]: r for r in csv.DictReader(open("postProcessing/coagulationBalance/sources.csv"))
        if r["time"] == end}
print("sources.csv at %s: growth %s, loss %s particles, mass %s"
      % (end, rows["growth"]["mass"], rows["loss"]["particles"], rows["loss"]["mass"]))
ok = abs(float(rows["growth"]["mass"]) / grown - 1) < 1e-12
ok &= abs(float(rows["loss"]["mass"]) / lost - 1) < 1e-12 and rows["loss"]["particles"] == gone[0]
ok &= int(gone[0]) == 16 * 20
ok &= abs(float(gone[1]) / number0 - 1) < 1e-12
ok &= abs(grown / (-number0 * (m0 - mmin)) - 1) < 1e-12
ok &= abs(lost / (number0 * mmin) - 1) < 1e-12
ok &= abs(initial / (number0 * m0) - 1) < 1e-12
sys.exit(0 if ok else 1)
PY
        grep -q "particles in domain        = 0" log.coagulationFoam || [ "$end" = 0.03 ] \
            || fail "particles are left after the oxidation"
    done
    echo "PASS growth oxidation: sizes exact before the minimum, every particle gone after it, booked exactly (serial and on 2 processors)"
    ;;
moments)
    alg="${2:?moments ALGORITHM}"
    c=$(boxCase "moments_$alg" 16 "
algorithm $alg;
splitting Lie;
kernel { type constant; K0 5e-15; }
inception { rate 0; mass 1; }
statisticalWeight { n 1000; V1 1e-16; }
seed 9;
sampling { tRelax 1; sampleInterval 0.01; }
initialPopulation { numberDensity 1e16; mass 1; }
growth { volume { type linear; rate 50; } }
")
    cd "$c"
    setEntry . system/controlDict deltaT 0.01
    setEntry . system/controlDict endTime 0.04
    setEntry . system/controlDict writeInterval 0.02
    runApplication coagulationFoam
    checkBalance log.coagulationFoam
    "$COAGULATIONFOAM_PYTHON" - <<'PY' || fail "$alg: moments off the closed moment equations"
import sys
import numpy as np
from scipy import stats
from dispersionCases import read_field
K0, N0, sigma = 5e-15, 1e16, 50.0
ok = True
for t in ("0.02", "0.04"):
    T = K0 * N0 * float(t)
    e = np.exp(sigma * float(t))
    exact = [N0 / (1 + T / 2), N0 * e, N0 * e * e * (1 + T)]
    for k in range(3):
        col = np.asarray(read_field(".", t, "M%d" % k))
        if k == 1:
            # the mass: conserved by the jumps and grown exactly, in every cell
            rel = np.abs(col / exact[1] - 1).max()
            ok &= rel < 1e-12
            print("t %s: M1 exact in every cell to %.1e" % (t, rel))
            continue
        se = col.std(ddof=1) / np.sqrt(col.size)
        half = stats.t.ppf(0.9995, col.size - 1) * se
        good = abs(col.mean() - exact[k]) <= half
        ok &= good
        print("t %s: M%d %.6e +- %.1e, exact %.6e (%+.2f SE) %s"
              % (t, k, col.mean(), half, exact[k], (col.mean() - exact[k]) / se,
                 "ok" if good else "OFF"))
sys.exit(0 if ok else 1)
PY
    grep -q "Growth volume: linear, rate 50" log.coagulationFoam || fail "the growth model is not in the log"
    # The report of this two-dimensional case: maps, not profiles along x; the maps' values are
    # the report's cell averages and each panel's colour range their range
    $report --case . --out results --analytic none --t-relax 0 > log.report 2>&1 || fail "report failed"
    [ -s results/maps.png ] && [ ! -e results/moments.png ] || fail "the report of a 2-D case drew no maps"
    "$COAGULATIONFOAM_PYTHON" - <<'PY' || fail "the maps' values are not the report's"
import sys
import numpy as np
maps = np.genfromtxt("results/maps.csv", delimiter=",", names=True, skip_header=2)
drawn = open("results/maps.csv").readlines()[1]
print(drawn.strip())
full = np.genfromtxt("results/moments_full.csv", delimiter=",", names=True)
head = open("results/maps.csv").readline().split(":", 1)[1]
ranges = {q: (float(a), float(b)) for q, a, b in (p.split() for p in head.split(","))}
ok = "the mesh's polygons" in drawn
for q, col in (("M0", "M0_mean"), ("M1", "M1_mean")):
    # the same cells (by centre) with the same values
    order = np.lexsort((maps["y"], maps["x"]))
    ref = np.lexsort((full["y"], full["x"]))
    same = np.allclose(maps[q][order], full[col][ref], rtol=1e-10)
    rng = np.isclose(ranges[q][0], maps[q].min()) and np.isclose(ranges[q][1], maps[q].max())
    print("maps %s: %d cells, values as moments_full.csv: %s, colour range %.6g..%.6g: %s"
          % (q, len(maps), same, ranges[q][0], ranges[q][1], rng))
    ok &= same and rng
sys.exit(0 if ok else 1)
PY
    echo "PASS growth moments $alg: M0, M1, M2 of the constant kernel with dm/dt = sigma m on the closed moment equations"
    ;;
duct)
    c=$(newCase constantKernelDuct growth_duct)
    cd "$c"
    setEntry . constant/coagulationProperties splitting Strang
    setEntry . constant/coagulationProperties statisticalWeight/n 256
    setEntry . constant/coagulationProperties growth "{ volume { type linear; rate 10; } }"
    setEntry . system/controlDict endTime 2.0
    setEntry . system/controlDict writeInterval 2.0
    runApplication coagulationFoam
    checkBalance log.coagulationFoam
    $report --case . --out results --no-plots --analytic none > log.report 2>&1 || fail "report failed"
    "$COAGULATIONFOAM_PYTHON" - <<'PY' || fail "duct with growth: moments off the homogeneous solution"
import sys
import numpy as np
from scipy.integrate import solve_ivp
I, K, sigma, u, dx = 3e8, 1e-5, 10.0, 1.0, 4e-3
rhs = lambda t, M: [I - 0.5 * K * M[0] ** 2, I + sigma * M[1],
                    I + 2 * sigma * M[2] + K * M[1] ** 2]
m = np.genfromtxt("results/moments.csv", delimiter=",", names=True)
# each cell's average over its length: 8 Gauss-Legendre points
g, wg = np.polynomial.legendre.leggauss(8)
ts = np.sort(np.concatenate([(x + 0.5 * dx * g) / u for x in m["x"]]))
sol = solve_ivp(rhs, (0, ts[-1]), [0, 0, 0], t_eval=ts, rtol=1e-10, atol=1e-3, method="LSODA")
ok = True
for k in range(3):
    ref = np.array([np.dot(wg / 2, np.interp((x + 0.5 * dx * g) / u, sol.t, sol.y[k]))
                    for x in m["x"]])
    mean, se = m["M%d_mean" % k], m["M%d_ci95" % k] / 1.96
    rel = np.abs(mean / ref - 1)[3:]
    z = np.abs(mean - ref)[3:] / se[3:]
    bad = (rel > 0.08) & (z > 4)
    ok &= not bad.any()
    print("M%d: outlet %.4e (solution %.4e); largest error %.1f %%, largest |z| %.2f, %d cells off"
          % (k, mean[-1], ref[-1], 100 * rel.max(), z.max(), bad.sum()))
sys.exit(0 if ok else 1)
PY
    echo "PASS growth duct: M0, M1, M2 along the duct on the homogeneous solution with growth"
    ;;
*) fail "unknown mode $mode" ;;
esac
