#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Walls that particles stick to (patchInteraction): a 2-D box, length L = 0.2,
# height H = 0.04, inception everywhere (no coagulation), a uniform flow (u, -v) with
# v/u = 0.1 towards the bottom wall. A particle born at (x, y) reaches the bottom before the
# outlet when y < v (L - x)/u, so at steady state the deposited share of what leaves is the
# triangle's share of the box, v L/(2 u H) = 1/4, whatever the splitting (the flow is steady
# and uniform and tracking is exact). Checked over [0.3, 0.6] (after the 0.2 s flush) within
# its binomial 99.9 % interval; the balances close with deposition booked; the patch lines
# add up to the totals at every write; a restart books per patch what the uninterrupted run
# books (with coagulation, so that a deposited particle's mass is not its number); with the
# bottom set to rebound nothing deposits; bad patchInteraction entries stop the run naming them.
. "$(dirname "$0")/caseLib.sh"
# patchBalance log [options]: the per-patch lines against the totals at every write
patchBalance() { "$COAGULATIONFOAM_PYTHON" "$testsDir/../python/patchBalance.py" "$@"; }

box=$(newCase constantKernelDuct walls_stick)
cd "$box"
"$COAGULATIONFOAM_PYTHON" - system/blockMeshDict <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
s = s[:s.index("vertices")] + """vertices
(
    (0 0 0) (0.2 0 0) (0.2 0.04 0) (0 0.04 0)
    (0 0 0.004) (0.2 0 0.004) (0.2 0.04 0.004) (0 0.04 0.004)
);
blocks ( hex (0 1 2 3 4 5 6 7) (50 10 1) simpleGrading (1 1 1) );
boundary
(
    inlet  { type patch; faces ((0 4 7 3)); }
    outlet { type patch; faces ((1 2 6 5)); }
    bottom { type wall;  faces ((0 1 5 4)); }
    top    { type wall;  faces ((3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
"""
open(p, "w").write(s)
PY
"$COAGULATIONFOAM_PYTHON" - 0/U <<'PY'
import sys
p = sys.argv[1]
s = open(p).read()
s = s[:s.index("boundaryField")] + """boundaryField
{
    inlet        { type fixedValue; value uniform (1 -0.1 0); }
    outlet       { type zeroGradient; }
    "(bottom|top)" { type slip; }
    frontAndBack { type empty; }
}
"""
s = s.replace("uniform (1 0 0);", "uniform (1 -0.1 0);", 1)
open(p, "w").write(s)
PY
grep -q "internalField   uniform (1 -0.1 0)" 0/U || setEntry . 0/U internalField "uniform (1 -0.1 0)"
rm -rf constant/polyMesh log.blockMesh
runApplication blockMesh
setEntry . constant/coagulationProperties kernel/K0 1e-30
setEntry . constant/coagulationProperties statisticalWeight/n 64
foamDictionary -entry patchInteraction -add "{ patches { bottom stick; top rebound; } }" \
    constant/coagulationProperties > /dev/null
setEntry . system/controlDict deltaT 1e-3
setEntry . system/controlDict endTime 0.6
setEntry . system/controlDict writeInterval 0.3
foamDictionary -entry functions -remove system/controlDict > /dev/null
rm -rf "$workDir/walls_rebound"; cp -r . "$workDir/walls_rebound"
runApplication coagulationFoam
checkBalance log.coagulationFoam
# Outlet and bottom add up to the totals at 0.3 and 0.6, patches.csv holds the log's lines,
# and (nothing coagulates) every particle left with the weight W it was born with
patchBalance log.coagulationFoam --csv postProcessing/coagulationBalance/patches.csv --equal-weights \
    || fail "the per-patch balance does not add up to the totals"

"$COAGULATIONFOAM_PYTHON" - postProcessing/coagulationBalance/patches.csv <<'PY' || fail "deposited share off v L/(2 u H)"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
at = lambda t, patch: next((float(r["particles"]) for r in rows if r["time"] == t and r["patch"] == patch), 0.0)
kinds = {r["patch"]: r["kind"] for r in rows}
assert kinds.get("bottom") == "deposited" and kinds.get("outlet") == "outflow", kinds
assert "top" not in kinds, "particles left through the rebound wall"
dep = at("0.6", "bottom") - at("0.3", "bottom")
out = at("0.6", "outlet") - at("0.3", "outlet")
n = dep + out
share, p = dep / n, 0.1 * 0.2 / (2 * 0.04)
half = 3.29 * math.sqrt(p * (1 - p) / n)
print("deposited share over [0.3, 0.6]: %.4f of %d particles (exact %.4f, 99.9 %% half-width %.4f)"
      % (share, n, p, half))
sys.exit(0 if abs(share - p) <= half and n > 2000 else 1)
PY

# Stopped at 0.3 and restarted: patches.csv counts from the first start (the totals carried
# in 0.3/uniform/coagulationPatchBalance), so its rows at 0.6 are the uninterrupted run's
# (a restart continues the same random streams): the same particle counts, number and mass
# to round-off (the sums are split at the restart). With coagulation (K0 1e-6): the particles
# that leave have coagulated, so each patch's mass differs from its number and a total read
# back into the wrong entry shows. The restarted run's patch lines less the start's add up to
# its own totals.
coag="$workDir/walls_coag"; rm -rf "$coag"; cp -r "$workDir/walls_rebound" "$coag"
foamDictionary -entry patchInteraction/patches/bottom -set stick "$coag/constant/coagulationProperties" > /dev/null
setEntry "$coag" constant/coagulationProperties kernel/K0 1e-6
r="$workDir/walls_restart"; rm -rf "$r"; cp -r "$coag" "$r"
(cd "$coag" && runApplication coagulationFoam)
patchBalance "$coag/log.coagulationFoam" --csv "$coag/postProcessing/coagulationBalance/patches.csv" \
    || fail "coagulating walls: the per-patch balance does not add up to the totals"
setEntry "$r" system/controlDict endTime 0.3
(cd "$r" && runApplication -s first coagulationFoam)
setEntry "$r" system/controlDict endTime 0.6
(cd "$r" && runApplication -s restart coagulationFoam)
grep -q "Starting time loop" "$r/log.coagulationFoam.restart" || fail "restart did not run"
patchBalance "$r/log.coagulationFoam.restart" --start "$r/0.3/uniform/coagulationPatchBalance" \
    --csv "$r/postProcessing/coagulationBalance/patches.csv" \
    || fail "restarted: the per-patch balance less the start's does not add up to the run's totals"
"$COAGULATIONFOAM_PYTHON" - "$coag/postProcessing/coagulationBalance/patches.csv" \
    "$r/postProcessing/coagulationBalance/patches.csv" <<'PY' || fail "patches.csv after a restart differs from the uninterrupted run"
import csv, sys
for t in ("0.3", "0.6"):
    rows = [{(r["patch"], r["kind"]): r for r in csv.DictReader(open(f)) if r["time"] == t}
            for f in sys.argv[1:3]]
    assert rows[0] and rows[0].keys() == rows[1].keys(), (t, rows[0].keys(), rows[1].keys())
    for key, a in rows[0].items():
        b = rows[1][key]
        assert a["particles"] == b["particles"], (t, key, a, b)
        for q in ("number", "mass"):
            assert abs(float(a[q]) - float(b[q])) <= 1e-12 * abs(float(a[q])), (t, key, q, a, b)
bottom = rows[0][("bottom", "deposited")]
ratio = float(bottom["mass"]) / float(bottom["number"])
print("deposited at 0.6: %s particles, mean mass %.3f" % (bottom["particles"], ratio))
assert ratio > 1.2, "the deposited particles have hardly coagulated: mass / number %.3f" % ratio
PY
echo "ok restart: patches.csv at 0.3 and 0.6 as in the uninterrupted run, with coagulation"

# The same box with the bottom rebounding: nothing deposits, the balances close
cd "$workDir/walls_rebound"
foamDictionary -entry patchInteraction/patches/bottom -set rebound constant/coagulationProperties > /dev/null
runApplication coagulationFoam
checkBalance log.coagulationFoam
! grep -q "deposited" log.coagulationFoam || fail "rebound: something deposited"
grep -q "outflow outlet" log.coagulationFoam || fail "rebound: no outflow booked"

# Bad entries: each a FatalIOError naming it
for bad in "bottom glue" "floor stick" "top stick"; do
    c="$workDir/walls_bad"; rm -rf "$c"; cp -r "$workDir/walls_rebound" "$c"
    rm -rf "$c"/0.[0-9]* "$c/postProcessing"
    foamDictionary -entry patchInteraction -set "{ patches { $bad; } }" "$c/constant/coagulationProperties" > /dev/null
    if coagulationFoam -case "$c" > "$c/log" 2>&1; then fail "patchInteraction { $bad } accepted"; fi
    grep -q "FOAM FATAL IO ERROR" "$c/log" || { tail -5 "$c/log"; fail "$bad: no FatalIOError"; }
    case "$bad" in
        "bottom glue") grep -q "valid interactions are" "$c/log" || fail "$bad: no list of the valid ones" ;;
        "floor stick") grep -q "matches no wall patch" "$c/log" || fail "$bad: not named" ;;
        "top stick")   grep -q "Wall patch 'bottom' has no interaction" "$c/log" || fail "$bad: the wall without one not named" ;;
    esac
    echo "ok bad patchInteraction { $bad }"
done
echo "PASS walls: deposited share at v L/(2 u H), balances closed with deposition, rebound deposits nothing, bad entries named"
