#!/bin/bash
# A run restarted from a written time continues the same random sequence: the
# restarted run's final particles and moments equal the uninterrupted run's. Inception and
# inflow through the inlet both draw random numbers (the cells' and the inlet faces' streams).
. "$(dirname "$0")/caseLib.sh"

full=$(newCase constantKernelDuct restart_full)
cd "$full"
setEntry . constant/coagulationProperties inflow/density 1e7
setEntry . system/controlDict endTime 0.2
setEntry . system/controlDict writeInterval 0.1
runApplication coagulationFoam

split=$(newCase constantKernelDuct restart_split)
cd "$split"
setEntry . constant/coagulationProperties inflow/density 1e7
setEntry . system/controlDict endTime 0.1
setEntry . system/controlDict writeInterval 0.1
runApplication -s first coagulationFoam
setEntry . system/controlDict endTime 0.2
runApplication -s restart coagulationFoam
grep -q "Create mesh for time = 0.1" log.coagulationFoam.restart || fail "did not restart from 0.1"
grep "particles in/incepted/out" log.coagulationFoam.restart | tail -1 | awk '{ exit !($4 > 0) }' \
    || fail "no inflow"

for f in M0 M1 M2 M3 lagrangian/coagulationCloud/mass lagrangian/coagulationCloud/weight \
         lagrangian/coagulationCloud/coordinates
do
    cmp -s "$full/0.2/$f" "$split/0.2/$f" || fail "0.2/$f differs between the full and the restarted run"
done
n=$(grep -c . "$full/0.2/lagrangian/coagulationCloud/mass" || true)
[ "$n" -gt 0 ] || fail "no particles written"
echo "PASS restart: 0.2/M0..M3 and all particles identical after a restart from 0.1 (inception and inflow)"
