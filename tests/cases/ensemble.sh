#!/bin/bash
# coagulationEnsemble: two realisations with distinct seeds run concurrently and are pooled
# by the report (twice the samples of one run; the realisations differ; balance closed).
. "$(dirname "$0")/caseLib.sh"

mkdir -p "$workDir"
out="$workDir/ensemble"
rm -rf "$out"
coagulationEnsemble -case "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct" -realisations 2 -jobs 2 \
    -seed0 7 -out "$out" -set system/controlDict:endTime=0.6 -set system/controlDict:writeInterval=0.6 \
    -- --no-plots > "$workDir/log.ensemble" 2>&1 || { tail -20 "$workDir/log.ensemble"; fail "ensemble failed"; }

for k in 0 1; do
    grep -q "^seed *$((7 + k));" "$out/realisation_$k/constant/coagulationProperties" || fail "realisation $k seed"
    checkBalance "$out/realisation_$k/log.coagulationFoam"
done
cmp -s "$out/realisation_0/0.6/M1" "$out/realisation_1/0.6/M1" && fail "the two realisations are identical"
grep -q "samples: 2 realisation(s), 50 cells, 82..82 samples per cell" "$workDir/log.ensemble" \
    || { grep samples: "$workDir/log.ensemble"; fail "pooled sample count"; }
[ -f "$out/results/moments.csv" ] || fail "no pooled moments.csv"
# two realisations on -jobs 2: one thread each, said in the log, the solver logs and the json
grep -q "2 at a time on 1 rank(s) x 1 thread(s) each" "$workDir/log.ensemble" || fail "ensemble thread count"
grep -q "1 thread(s) for the cell step" "$out/realisation_0/log.coagulationFoam" || fail "solver thread count"
grep -q '"threadsPerRank": 1,' "$out/ensemble.json" || fail "threadsPerRank in ensemble.json"
echo "PASS ensemble: 2 realisations pooled"
