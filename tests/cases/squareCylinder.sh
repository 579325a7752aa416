#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# The square-cylinder tutorial from its own Allrun, reduced (0.6 s of flow, particles from
# 0.2 s, the size distributions from 0.45 s): pimpleFoam with the coagulationCloud function
# object -> foamToVTK -> the plots. The flow's times before 0.2 s hold no particles, those
# after do (written by the function object after the step), the balances close with
# deposition on the cylinder, and the wake's table and pictures are written.
. "$(dirname "$0")/caseLib.sh"

case=$(tutorialCase squareCylinder squareCylinder)
cd "$case"
setEntry . system/controlDict endTime 0.6
setEntry . system/controlDict writeInterval 0.1
setEntry . system/controlDict functions/particles/timeStart 0.2
setEntry . constant/coagulationProperties cloudFunctions/wakePsd/timeStart 0.45
sed -i "s/-time '2:'/-time '0.2:'/" Allrun

runAllrun
checkBalance log.pimpleFoam
grep -q "deposited cylinder" log.pimpleFoam || fail "nothing deposited on the cylinder"
[ ! -d 0.1/lagrangian ] && [ ! -f 0.1/M0 ] || fail "particles before the function object's timeStart"
[ -f 0.6/lagrangian/coagulationCloud/coordinates ] && [ -f 0.6/M0 ] \
    || fail "no particles or moments at 0.6"
[ -f 0.6/uniform/coagulationCloudComplete ] || fail "0.6 not marked complete"
n=$(grep "coagulationCloud particles: time 0.6, particles = " log.pimpleFoam | awk '{ print $NF }')
[ "${n:-0}" -gt 1000 ] || fail "only ${n:-no} particles at 0.6"
[ -n "$(ls VTK/lagrangian 2>/dev/null)" ] || fail "no particles in VTK"
ls results/wakePsd.png results/wakeProbes.png > /dev/null || fail "no plots"
[ "$(wc -l < results/wake.csv)" = 13 ] || fail "wake.csv: not 3 probes x 4 windows"
echo "PASS squareCylinder: $n particles in pimpleFoam's flow at 0.6 s, balances closed"
