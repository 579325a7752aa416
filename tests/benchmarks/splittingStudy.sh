#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# splittingStudy.sh OUT [quick]: the splitting error of Lie, Strang and StrangSAS against deltaT
#, on the paper's ducts, then tables and plots (splittingStudy.py).
#
#   A  additive-duct geometry without coagulation (K0 = 1e-30): the mean of M1 is then the
#      additive duct's own for SWA (the SWA jump keeps every particle's w*m in place), and
#      each scheme's exact expectation is known (case_splitting): the measured errors near the
#      inlet against the predicted ones, dt = 3e-4, 6e-4, 1.2e-3 (dx/h = 20/3, 10/3, 5/3); for
#      StrangSAS too
#   B  constant-kernel duct (paper 3.1, SWA n = 256): M0..M3 against eqs 39-45,
#      dt = 1e-4 (the paper's), 4e-4, 1.6e-3
#   C  additive-kernel duct (paper 3.2, SWA n = 2048, the tutorial): M1 and M2, dt = 4e-4,
#      R seeds per scheme (independent realisations: intervals from the realisations)
#   D  the constant-duct geometry with the OpenFOAM-free reference (build/tests/benchmarks/
#      ductReference: exact 1-D advection, the same splittings) without coagulation, R = 12
#      seeds per scheme and dt, n = 4096, t = 4: dt = 6e-4, 1.2e-3, 2.4e-3 (dx/h = 20/3,
#      10/3, 5/3, along which the Strang staircase error of M1 scales cleanly): M1 against
#      eq 41 and against each scheme's exact expectation; intervals over the seeds.
#   F  as D with coagulation (the paper's K0 = 1e-5), n = 1024, R = 16 seeds: M0, M2, M3
#      against eqs 39, 43, 45 in cell 0 and at the outlet
#   E  cost at equal accuracy: the additive-kernel duct (tutorial, one seed) with Lie at the
#      largest dt whose outlet M1 bias u dt/(2x) is 0.1 % (2e-4) and Strang at dt = 1.2e-3
#      and 2e-3 (Courant 0.6 and 1), whose expected outlet M1 error is 0
# Every run's wall time is kept for the accuracy/cost table. quick: shorter runs, R = 2.
# Full: about 45 min on one core of the 2-core VM.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../../etc/bashrc"
out="$(mkdir -p "$1" && cd "$1" && pwd)"
quick="${2:-}"
endA=1.2; endB=2.0; R=4
[ "$quick" = quick ] && { endA=0.6; endB=1.0; R=2; }
report="$COAGULATIONFOAM_PYTHON $COAGULATIONFOAM_DIR/applications/utilities/coagulationReport/coagulationReport.py"

# run NAME TUTORIAL SCHEME DT END SAMPLE [dictEntry value]...
run()
{
    local name=$1 tutorial=$2 scheme=$3 dt=$4 end=$5 sample=$6
    shift 6
    local d="$out/$name"
    [ -f "$d/results/moments_full.csv" ] && return 0   # done in an earlier call
    rm -rf "$d"; cp -r "$COAGULATIONFOAM_DIR/tutorials/$tutorial" "$d"
    cd "$d"
    foamDictionary -entry splitting -set "$scheme" constant/coagulationProperties > /dev/null
    foamDictionary -entry sampling/sampleInterval -set "$sample" constant/coagulationProperties > /dev/null
    while [ $# -gt 0 ]; do
        foamDictionary -entry "$1" -set "$2" constant/coagulationProperties > /dev/null; shift 2
    done
    foamDictionary -entry deltaT -set "$dt" system/controlDict > /dev/null
    foamDictionary -entry endTime -set "$end" system/controlDict > /dev/null
    foamDictionary -entry writeInterval -set "$end" system/controlDict > /dev/null
    foamDictionary -entry functions -remove system/controlDict > /dev/null
    blockMesh > log.blockMesh 2>&1
    local s; s=$(date +%s.%N)
    OMP_NUM_THREADS=1 coagulationFoam > log.coagulationFoam 2>&1
    awk -v a="$(date +%s.%N)" -v b="$s" 'BEGIN { printf "%.2f\n", a - b }' > wallTime
    $report --case . --out results --no-plots > log.report 2>&1
    echo "$name $(cat wallTime) s"
}

for scheme in Lie Strang; do
    for dt in 3e-4 6e-4 1.2e-3; do
        run "A_${scheme}_$dt" additiveKernelDuct $scheme $dt $endA $(awk -v d=$dt 'BEGIN { printf "%g", 10 * d }') kernel/K0 1e-30
    done
    for dt in 1e-4 4e-4 1.6e-3; do
        run "B_${scheme}_$dt" constantKernelDuct $scheme $dt $endB 6.4e-3 sampling/tRelax 0.4
    done
    for ((r = 1; r <= R; r++)); do
        run "C_${scheme}_4e-4_r$r" additiveKernelDuct $scheme 4e-4 0.4 4e-3 seed $((776 + r))
    done
done
# StrangSAS: S(dt/2) A(dt) S(dt/2), part A (its order near the inlet), and R - 1 more
# realisations of each (A_StrangSAS_r<k>_<dt>, seed k; pooled with seed 1 by
# coagulationPost.splittingStudy.pooled, doc/validation.md)
for dt in 3e-4 6e-4 1.2e-3; do
    run "A_StrangSAS_$dt" additiveKernelDuct StrangSAS $dt $endA $(awk -v d=$dt 'BEGIN { printf "%g", 10 * d }') kernel/K0 1e-30
    for ((r = 2; r <= R; r++)); do
        run "A_StrangSAS_r${r}_$dt" additiveKernelDuct StrangSAS $dt $endA $(awk -v d=$dt 'BEGIN { printf "%g", 10 * d }') kernel/K0 1e-30 seed $r
    done
done
run E_Lie_2e-4 additiveKernelDuct Lie 2e-4 0.4 4e-3 seed 777
run E_Strang_1.2e-3 additiveKernelDuct Strang 1.2e-3 0.4 4.8e-3 seed 777
run E_Strang_2e-3 additiveKernelDuct Strang 2e-3 0.4 4e-3 seed 777
# reference PART R n seed0 [ductReference options]...: R seeds of the OpenFOAM-free reference
# per scheme and dt, each in OUT/PART_<scheme>_<dt>_r<seed>.txt
reference()
{
    local part=$1 R=$2 n=$3 seed0=$4 scheme dt r f
    shift 4
    for scheme in Lie Strang; do
        for dt in 6e-4 1.2e-3 2.4e-3; do
            for ((r = 1; r <= R; r++)); do
                f="$out/${part}_${scheme}_${dt}_r$r.txt"
                [ -s "$f" ] && continue
                "$COAGULATIONFOAM_BUILD/applications/studies/ductReference" SWA "$n" $((seed0 + r)) 4.0 \
                    --dt $dt --splitting $scheme --sample 4.8e-3 --cells "$@" > "$f.tmp" \
                    && mv "$f.tmp" "$f"
            done
        done
    done
}
reference D "$([ "$quick" = quick ] && echo 2 || echo 12)" 4096 1000 --K0 1e-30
reference F "$([ "$quick" = quick ] && echo 2 || echo 16)" 1024 2000
"$COAGULATIONFOAM_PYTHON" -m coagulationPost.splittingStudy "$out"
