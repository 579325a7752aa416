#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# The short version of tests/benchmarks/coagulationDiffusionColumn.sh: the
# coagulation-diffusion problem of Sabelfeld-Kolodko's Figs 3-5 (K = 1, n0 = 1 monomers uniform
# in [-R, R]^2, D = 8.88e-2 R^2/T_c) solved by coagulationFoam (SWA, constant-D walk) on a coarse
# 40 x 40 box [-4R, 4R]^2, 200 particles a cell, dt' = 0.05, to t' = 5. n_l, l = 1..5, at
# t' = 1, 5 in the central 4 x 4 cells against a coarse Eulerian reference n^E (dx' = 0.1,
# dt' = 0.025, gamma = 1.1, Lambda = 200) and the Lagrangian model n^L: fails if any |z|
# against n^E reaches 4, or if n^L is nowhere off by more than 5 standard errors at t' = 5
# (the effective source).
. "$(dirname "$0")/caseLib.sh"
c="$workDir/column"
rm -rf "$c"; mkdir -p "$workDir"
"$COAGULATIONFOAM_BUILD/applications/studies/eulerianReference" --W 4 --dx 0.1 --dt 0.025 \
    --gamma 1.1 --Lambda 200 --sizes 5 --tmax 5 > "$workDir/eulerian.csv" 2> "$workDir/eulerian.log"
cat "$workDir/eulerian.log"
cp -r "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct" "$c"
cd "$c"
cleanCase
"$COAGULATIONFOAM_PYTHON" -m coagulationPost.coagulationDiffusionColumn setup . 200 40
setEntry . constant/coagulationProperties sampling/sampleInterval 0.05
runApplication blockMesh
runApplication topoSet
foamDictionary -entry functions -remove system/controlDict > /dev/null
for kv in "deltaT 0.05" "endTime 5" "writeInterval 1" "writeFormat ascii"; do
    setEntry . system/controlDict "${kv% *}" "${kv#* }"
done
runApplication coagulationFoam
checkBalance log.coagulationFoam
"$COAGULATIONFOAM_PYTHON" -m coagulationPost.coagulationDiffusionColumn compare . "$workDir/eulerian.csv" 40 1,5 5 0.4 \
    || fail "coagulationFoam off n^E, or not off n^L (see the table above)"
