#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Transport across rotational cyclicAMI sides: OpenFOAM's simpleFoam pipeCyclic (a pipe
# sector, 1 250 cells), converged, then coagulationFoam with particles entering with the flow
# and the turbulent walk (tests/cases/openfoamCases.sh), with the sides as they are (a
# rotational cyclicAMI pair) and made rebounding walls. ROUNDS rounds alternate the two, one
# core each; each prints the transport's particle moves per second (the log's figure: the
# particles moved over the transport's wall time), the particles held at a face and the run's
# wall time, then the median of each.
#   tests/benchmarks/pipeCyclicTransport.sh [OUTDIR] [ROUNDS=3] [ENDTIME=2]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../../etc/functions"
. "$here/../cases/openfoamCases.sh"
out="${1:-/tmp/pipeCyclicTransport}"; rounds="${2:-3}"; end="${3:-2}"
export OMP_NUM_THREADS=1
rm -rf "$out"; mkdir -p "$out"

pipeCyclicCase "$out/cyclic" > "$out/cyclic.setup.log" 2>&1
pipeCyclicCase "$out/walls" walls > "$out/walls.setup.log" 2>&1
for c in cyclic walls; do
    foamDictionary -entry endTime -set "$end" "$out/$c/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set "$(awk -v e="$end" 'BEGIN { print int(e/0.01 + 0.5) }')" \
        "$out/$c/system/controlDict" > /dev/null
done

for r in $(seq "$rounds"); do
    for c in cyclic walls; do
        (cd "$out/$c" && rm -rf [1-9]* 0.[0-9]* postProcessing \
            && coagulationFoam > "log.$r" 2>&1)
        moves=$(awk '/particle moves per second/ { v = $NF } END { print v }' "$out/$c/log.$r")
        held=$(awk '/particles held at a face/ { v = $NF } END { print v }' "$out/$c/log.$r")
        wall=$(sed -n 's/^Run: .* in \(.*\) of wall time.*/\1/p' "$out/$c/log.$r")
        echo "round $r $c: $moves particle moves/s, $held held at a face, $wall"
        echo "$c $moves" >> "$out/moves.txt"
    done
done
for c in cyclic walls; do
    awk -v c="$c" '$1 == c { print $2 }' "$out/moves.txt" | sort -g \
        | awk -v c="$c" '{ v[NR] = $1 } END { printf "median %s: %.3g particle moves/s over %d rounds\n", c, v[int((NR + 1)/2)], NR }'
done
