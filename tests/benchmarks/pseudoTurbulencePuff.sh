#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# coagulationFoam advecting a coagulating puff in a frozen pseudo-turbulent U:
# pseudoTurbulenceField writes one sample of (5.14) into U; coagulationFoam (SWA, Saffman-Turner
# K_11 = 1, no dispersion) runs to T; the clusters and mass in balls of cells are compared with
# the Lagrangian direct estimator (3.14) in the same analytic field (pseudoTurbulencePuff).
#   [PUFF_NX=48] tests/benchmarks/pseudoTurbulencePuff.sh [OUTDIR] [PARTICLES_PER_CELL=16] [SEED=1] [T=2]
# (PUFF_NX: cells per side of the cube [-12, 12]^3)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../../etc/functions"
out="${1:-/tmp/pseudoTurbulencePuff}"; n="${2:-16}"; seed="${3:-1}"; T="${4:-2}"
rm -rf "$out"; mkdir -p "$out"
nx="${PUFF_NX:-48}"
"$COAGULATIONFOAM_BUILD/applications/studies/pseudoTurbulencePuff" --seed "$seed" --T "$T" \
    --h "$(awk -v n="$nx" 'BEGIN{print 24/n}')" --points 40000 > "$out/lagrangian.csv" 2> "$out/lagrangian.log"
cp -r "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct" "$out/case"
cd "$out/case"
cleanCase
"$COAGULATIONFOAM_PYTHON" -m coagulationPost.pseudoTurbulencePuff setup . "$n" "$seed"
runApplication blockMesh
runApplication topoSet
runApplication pseudoTurbulenceField
foamDictionary -entry functions -remove system/controlDict > /dev/null
for kv in "deltaT 0.02" "endTime $T" "writeInterval $T" "writeFormat ascii"; do
    foamDictionary -entry "${kv% *}" -set "${kv#* }" system/controlDict > /dev/null
done
start=$(date +%s)
runApplication coagulationFoam
echo "coagulationFoam: $(( $(date +%s) - start )) s; $(cat "$out/lagrangian.log")"
grep -A4 "Kolmogorov pseudo" log.pseudoTurbulenceField
"$COAGULATIONFOAM_PYTHON" -m coagulationPost.pseudoTurbulencePuff compare . "$out/lagrangian.csv" "$T" | tee "$out/puff.csv"
