#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# The coagulationFoam column: the coagulation-diffusion problem of Sabelfeld and
# Kolodko (Figs 3-5: K = 1, n0 = 1 monomers uniform in the square [-R, R]^2, D = 8.88e-2 R^2/T_c)
# solved by coagulationFoam itself (SWA, constant-D random walk, no effective source), its
# n_l(t', 0), l = 1..10, at t' = 1, 5, 10 beside the converged Eulerian reference n^E and the
# Lagrangian model n^L (applications/studies/eulerianReference). About 2 minutes on 2 cores.
#   tests/benchmarks/coagulationDiffusionColumn.sh [OUTDIR] [PARTICLES_PER_CELL=150] [SIZES=10]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../../etc/functions"
out="${1:-/tmp/coagulationDiffusionColumn}"; n="${2:-150}"; sizes="${3:-10}"
rm -rf "$out"; mkdir -p "$out"
"$COAGULATIONFOAM_BUILD/applications/studies/eulerianReference" --W 4 --gamma 1.05 --Lambda 500 \
    > "$out/eulerian.csv" 2> "$out/eulerian.log"
cp -r "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct" "$out/case"
cd "$out/case"
cleanCase
"$COAGULATIONFOAM_PYTHON" -m coagulationPost.coagulationDiffusionColumn setup . "$n"
runApplication blockMesh
runApplication topoSet
foamDictionary -entry functions -remove system/controlDict > /dev/null
for kv in "deltaT 0.02" "endTime 10" "writeInterval 1" "writeFormat ascii"; do
    foamDictionary -entry "${kv% *}" -set "${kv#* }" system/controlDict > /dev/null
done
start=$(date +%s)
runApplication coagulationFoam
echo "coagulationFoam: $(( $(date +%s) - start )) s; $(grep 'eulerianReference:' "$out/eulerian.log")"
"$COAGULATIONFOAM_PYTHON" -m coagulationPost.coagulationDiffusionColumn compare . "$out/eulerian.csv" 80 1,5,10 "$sizes" 0.3 \
    | tee "$out/column.csv"
