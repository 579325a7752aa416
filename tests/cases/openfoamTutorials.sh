#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# OpenFOAM's own tutorials with particles, as a user would add them:
#  1. pimpleFoam/RAS/TJunction (its inlet pressure ramped from a fluid at rest; fixed steps)
#     with the coagulationCloud function object from timeStart 0.1, in one run: the velocity
#     is checked at the population's first step, not at t = 0 where nothing flows in; the
#     particles entering at the inlet's edges, where the owner cells' velocity points out of
#     the mesh, are tracked from the face and never placed outside the mesh; balances closed;
#  2. simpleFoam/pipeCyclic (a pipe sector whose sides are a rotational cyclicAMI pair; its
#     coded swirl inlet given as cylindricalInletVelocity, since coded conditions are not
#     compiled as root) -> coagulationFoam with the turbulent walk and sticking walls: the
#     rest of a walk is rotated with the particle across the sides, so that it does not carry
#     the particle back across them again and again; 100 steps end within the time limit
#     (tests/cases/openfoamCases.sh), balances closed.
. "$(dirname "$0")/caseLib.sh"
. "$(dirname "$0")/openfoamCases.sh"

# 1. TJunction, the function object from timeStart 0.1
mkdir -p "$workDir"
tj="$workDir/TJunction"
openfoamTutorial incompressible/pimpleFoam/RAS/TJunction "$tj" || fail "no TJunction tutorial"
cd "$tj"
runApplication blockMesh
setEntry . system/controlDict adjustTimeStep no
setEntry . system/controlDict deltaT 2e-4
setEntry . system/controlDict endTime 0.12
setEntry . system/controlDict writeInterval 0.01
foamDictionary system/controlDict -entry functions/particles \
    -add "{ type coagulationCloud; libs (coagulationModels); timeStart 0.1; }" > /dev/null
inflowParticles constant/coagulationProperties inlet defaultFaces 0.1 1e-3
rc=0; timeout 600 pimpleFoam > log.pimpleFoam 2>&1 || rc=$?
[ "$rc" -eq 0 ] || { grep -A8 "FOAM FATAL" log.pimpleFoam | head -20; fail "TJunction: pimpleFoam exit $rc"; }
checkBalance log.pimpleFoam
grep -q "The velocity is checked at the population's first step" log.pimpleFoam \
    || fail "TJunction: the velocity was checked at the start"
n=$(grep -c "outside of the mesh" log.pimpleFoam || true)
[ "$n" -eq 0 ] || fail "TJunction: $n particles placed outside the mesh"
particles=$(grep "coagulationCloud particles: time 0.12," log.pimpleFoam | sed 's/.*particles = //')
[ "${particles:-0}" -gt 1000 ] || fail "TJunction: ${particles:-no} particles at 0.12"
echo "ok TJunction: the function object from timeStart 0.1 in one run, $particles particles at 0.12, none placed outside the mesh"

# 2. pipeCyclic: the converged flow, then the particles with the walk
pc="$workDir/pipeCyclic"
pipeCyclicCase "$pc" || fail "pipeCyclic: the case"
cd "$pc"
rc=0; timeout 120 coagulationFoam > log.coagulationFoam 2>&1 || rc=$?
[ "$rc" -ne 124 ] || fail "pipeCyclic: 100 steps with the walk did not end within 120 s"
[ "$rc" -eq 0 ] || { grep -A8 "FOAM FATAL" log.coagulationFoam | head -20; fail "pipeCyclic: exit $rc"; }
checkBalance log.coagulationFoam
grep "particle moves per second\|held at a face" log.coagulationFoam | tail -2
echo "ok pipeCyclic: 100 steps with the turbulent walk across the rotational cyclicAMI sides"
echo "PASS openfoamTutorials"
