#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Laminar channels without dispersion: each streamline is the homogeneous
# constant-kernel solution at residence time x/u(y) (eqs 39-45 with x -> x/u), cell averages
# within the run's intervals: the Poiseuille parabola with the cell velocity, the Couette
# line with the cellPoint velocity (exact for a linear field; tests/cases/poiseuilleCase.py
# says why and how the exact cell averages are taken).
#   poiseuille.sh ["poiseuille:cell couette:cellPoint"]     (the default)
. "$(dirname "$0")/caseLib.sh"
check="$COAGULATIONFOAM_DIR/tests/cases/poiseuilleCase.py"
export PYTHONPATH="$COAGULATIONFOAM_DIR/src/python${PYTHONPATH:+:$PYTHONPATH}"

for run in ${1:-poiseuille:cell couette:cellPoint}; do
    flow=${run%%:*}; scheme=${run##*:}
    c=$(newCase constantKernelDuct "${flow}_$scheme")
    cd "$c"
    rm -rf constant/polyMesh log.blockMesh
    "$COAGULATIONFOAM_PYTHON" "$check" setup . "$flow"
    runApplication blockMesh
    setEntry . constant/coagulationProperties splitting Strang
    setEntry . constant/coagulationProperties statisticalWeight/n 512
    [ "$flow" = poiseuille ] && relax=0.4 end=0.75 || relax=0.25 end=0.6
    setEntry . constant/coagulationProperties sampling/tRelax $relax
    foamDictionary -entry transport -add "{ type frozenFlow; interpolationSchemes { U $scheme; } }" \
        constant/coagulationProperties > /dev/null
    setEntry . system/controlDict deltaT 5e-4
    setEntry . system/controlDict endTime $end
    setEntry . system/controlDict writeInterval $end
    foamDictionary -entry functions -remove system/controlDict > /dev/null
    runApplication coagulationFoam
    checkBalance log.coagulationFoam
    grep -q "velocity interpolation $scheme" log.coagulationFoam || fail "$scheme not selected"
    "$COAGULATIONFOAM_PYTHON" "$check" check . "$flow" "$scheme" || fail "$flow, $scheme: cell averages off x/u(y)"
done
echo "PASS laminar channels: cell averages at residence time x/u(y) (${1:-poiseuille:cell couette:cellPoint})"
