#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# The random walk (dispersionModel) against exact diffusion, no flow, no
# coagulation, particles released by initialPopulation (tests/cases/dispersionCases.py says
# what each case is and checks it):
#   puff       a puff in a closed 2-D box, rebound walls: each cell against the image-sum
#              Gaussian at two times; puffBrownian the same with the Brownian model;
#   slab       stick walls: the fraction remaining against the Fourier series at eight
#              times; deposited + remaining = initial exactly (the balances close);
#   wellMixed  D = nut/Sct with nut varying 100x: a uniform start stays uniform; restarted
#              from its middle write, its end is the uninterrupted run's byte for byte.
. "$(dirname "$0")/caseLib.sh"
cases="$COAGULATIONFOAM_DIR/tests/cases/dispersionCases.py"
export PYTHONPATH="$COAGULATIONFOAM_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}"

for kind in ${1:-puff puffBrownian slab wellMixed}; do
    c=$(newCase constantKernelDuct "dispersion_$kind")
    cd "$c"
    rm -rf constant/polyMesh log.blockMesh
    read -r dt end every < <("$COAGULATIONFOAM_PYTHON" "$cases" setup . "$kind")
    runApplication blockMesh
    [ ! -f system/topoSetDict ] || runApplication topoSet
    setEntry . system/controlDict deltaT "$dt"
    setEntry . system/controlDict endTime "$end"
    setEntry . system/controlDict writeInterval "$every"
    setEntry . system/controlDict writeFormat ascii
    foamDictionary -entry functions -remove system/controlDict > /dev/null
    runApplication coagulationFoam
    checkBalance log.coagulationFoam
    "$COAGULATIONFOAM_PYTHON" "$cases" check . "$kind" || fail "$kind off its exact solution"
    if [ "$kind" = wellMixed ]; then
        # Restarted from t = 10 (nut and n0 were written with it): the walk's streams go on
        # where they were, so t = 20 is the uninterrupted run's byte for byte
        r="$workDir/dispersion_wellMixed_restart"; rm -rf "$r"; cp -r . "$r"
        rm -rf "$r/20" "$r/postProcessing" "$r"/log.coagulationFoam
        [ -f "$r/10/nut" ] || fail "nut not written with the time"
        (cd "$r" && runApplication coagulationFoam)
        grep -q "Initial population: not used" "$r/log.coagulationFoam" || fail "restart made a new population"
        for f in M0 M1 lagrangian/coagulationCloud/mass lagrangian/coagulationCloud/coordinates; do
            cmp -s "20/$f" "$r/20/$f" || fail "restart: 20/$f differs from the uninterrupted run"
        done
        echo "ok restart of the turbulent walk: t = 20 byte for byte"
    fi
done
echo "PASS dispersion: puff against the image-sum Gaussian, slab against the Fourier series, well-mixed stays uniform"
