#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Particle moves per second of the transport half step for each velocity interpolation and
# dispersion model, on the 2-D sheared box of the scale issue: 50 x 10 cells,
# u(y) = 1 + y/H, constant kernel with inception everywhere, nut = 1e-5 (1 + 9 y/H) for the
# turbulent walk, rebound walls. Runs are alternated (ROUNDS rounds of every combination) so
# that a busy machine biases none; prints transport ms per step and moves/s per run and the
# median per combination. BEFORE=<another checkout, built> runs its coagulationFoam beside this
# one's in every round (build "before"), for before/after pairs.
#   [BEFORE=DIR] tests/benchmarks/transportRates.sh [OUTDIR] [ROUNDS=3] [STEPS=1000]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../../etc/functions"
out="${1:-/tmp/transportRates}"; rounds="${2:-3}"; steps="${3:-1000}"
rm -rf "$out"; mkdir -p "$out"
base="$out/base"
. "$here/scaleBox.sh"
makeScaleBox "$base"
cd "$base"
foamDictionary -entry endTime -set "$(awk -v s="$steps" 'BEGIN { print s * 1e-3 }')" system/controlDict > /dev/null
foamDictionary -entry writeInterval -set "$(awk -v s="$steps" 'BEGIN { print s * 1e-3 }')" system/controlDict > /dev/null
foamDictionary -entry sampling/tRelax -set 100 constant/coagulationProperties > /dev/null
foamDictionary -entry statisticalWeight/n -set 160 constant/coagulationProperties > /dev/null

declare -A disp=(
    [none]="{ type none; }"
    [constant]="{ type constant; D 1e-5; }"
    [turbulent]="{ type turbulent; Sct 0.7; }"
)
before="${BEFORE:-}"
printf "%-8s %-10s %-10s %5s %12s %14s\n" build interp dispersion round "transport_ms" "moves_per_s" | tee "$out/runs.txt"
for r in $(seq 1 "$rounds"); do
    for interp in cell cellPoint; do
        for d in none constant turbulent; do
          for build in now ${before:+before}; do
            c="$out/${build}_${interp}_${d}_$r"
            cp -r "$base" "$c"
            foamDictionary -entry transport -add "{ type frozenFlow; interpolationSchemes { U $interp; } }" "$c/constant/coagulationProperties" > /dev/null
            foamDictionary -entry dispersion -add "${disp[$d]}" "$c/constant/coagulationProperties" > /dev/null
            if [ "$build" = before ]; then
                (. "$before/etc/bashrc" && OMP_NUM_THREADS=1 coagulationFoam -case "$c") > "$c/log" 2>&1 \
                    || { tail "$c/log"; exit 1; }
            else
                OMP_NUM_THREADS=1 coagulationFoam -case "$c" > "$c/log" 2>&1 || { tail "$c/log"; exit 1; }
            fi
            ms=$(grep "transport =" "$c/log" | tail -1 | sed 's/.*transport = \([0-9.e+-]*\) ms.*/\1/')
            mps=$(grep "particle moves per second" "$c/log" | tail -1 | awk '{print $NF}')
            printf "%-8s %-10s %-10s %5d %12.3f %14.0f\n" "$build" "$interp" "$d" "$r" "$ms" "$mps" | tee -a "$out/runs.txt"
          done
        done
    done
done
echo "median per combination (one thread):"
"$COAGULATIONFOAM_PYTHON" - "$out/runs.txt" <<'PY'
import sys
import numpy as np
rows = [l.split() for l in open(sys.argv[1]).read().splitlines()[1:] if l.strip()]
for key in dict.fromkeys((r[0], r[1], r[2]) for r in rows):
    ms = [float(r[4]) for r in rows if (r[0], r[1], r[2]) == key]
    mps = [float(r[5]) for r in rows if (r[0], r[1], r[2]) == key]
    print("  %-8s %-10s %-10s %8.2f ms per step %12.0f moves/s (%d runs)"
          % (key[0], key[1], key[2], np.median(ms), np.median(mps), len(ms)))
PY
