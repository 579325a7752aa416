#!/bin/bash
# coagulationEnsemble: two realisations with distinct seeds run concurrently and are pooled
# by the report (twice the samples of one run; the realisations differ; balance closed).
# Then -resume: an interrupted realisation goes on from its last written time and ends with
# the same fields and pooled statistics as the uninterrupted ensemble; finished ones are
# kept; a larger -realisations adds realisations with the next seeds.
. "$(dirname "$0")/caseLib.sh"

mkdir -p "$workDir"
out="$workDir/ensemble"
rm -rf "$out"
coagulationEnsemble -case "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct" -realisations 2 -jobs 2 \
    -seed0 7 -out "$out" -set system/controlDict:endTime=0.6 -set system/controlDict:writeInterval=0.3 \
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

# ---- -resume after an interruption of realisation 1 between its writes at 0.3 and 0.6
cp "$out/realisation_1/0.6/M1" "$workDir/M1.uninterrupted"
cp "$out/results/moments.csv" "$workDir/moments.uninterrupted.csv"
kept=$(cat "$out/realisation_0/runSeconds")
# what a kill during the write of 0.6 leaves: a short particle field, no completion marker
rm -f "$out/realisation_1/0.6/uniform/coagulationCloudComplete" "$out/realisation_1/runSeconds" \
    "$out/ensemble.json"
: > "$out/realisation_1/0.6/lagrangian/coagulationCloud/mass"
coagulationEnsemble -resume -out "$out" -- --no-plots > "$workDir/log.resume" 2>&1 \
    || { tail -20 "$workDir/log.resume"; fail "resume failed"; }
grep -q "kept: $out/realisation_0 (finished before)" "$workDir/log.resume" || fail "finished realisation not kept"
grep -q "set aside: $out/realisation_1/0.6 (incomplete" "$workDir/log.resume" \
    || { cat "$workDir/log.resume"; fail "the half-written 0.6 was not set aside"; }
grep -q "resumed: $out/realisation_1 from time 0.3" "$workDir/log.resume" || fail "did not resume from 0.3"
grep -q "Create mesh for time = 0.3" "$out/realisation_1/log.coagulationFoam" || fail "solver did not restart at 0.3"
[ -f "$out/realisation_1/log.coagulationFoam.segment1" ] || fail "interrupted segment's log not kept"
[ "$(cat "$out/realisation_0/runSeconds")" = "$kept" ] || fail "finished realisation's runSeconds changed"
awk -v a="$(cat "$out/realisation_1/runSeconds")" -v b="$(cat "$out/realisation_1/runSecondsBefore")" \
    'BEGIN { exit !(a > b && b >= 0) }' || fail "resumed runSeconds does not include the earlier segment"
cmp -s "$out/realisation_1/0.6/M1" "$workDir/M1.uninterrupted" || fail "resumed realisation's 0.6/M1 differs"
cmp -s "$out/results/moments.csv" "$workDir/moments.uninterrupted.csv" \
    || fail "pooled statistics after -resume differ from the uninterrupted ensemble's"
grep -q '"realisations": 2,' "$out/ensemble.json" || fail "ensemble.json after resume"

# ---- -resume -realisations 3: one more realisation, seed 9, pooled with the two
coagulationEnsemble -resume -out "$out" -realisations 3 -- --no-plots > "$workDir/log.extend" 2>&1 \
    || { tail -20 "$workDir/log.extend"; fail "extending the ensemble failed"; }
grep -q "^seed *9;" "$out/realisation_2/constant/coagulationProperties" || fail "realisation 2 seed"
grep -q "samples: 3 realisation(s), 50 cells, 123..123 samples per cell" "$workDir/log.extend" \
    || { grep samples: "$workDir/log.extend"; fail "pooled sample count after extension"; }
[ "$(grep -c "kept:" "$workDir/log.extend")" -eq 2 ] || fail "extension re-ran finished realisations"

# ---- what -resume refuses
coagulationEnsemble -resume -out "$workDir/noSuchEnsemble" > "$workDir/log.bad1" 2>&1 && fail "-resume of no ensemble"
grep -q "is not an ensemble started by coagulationEnsemble" "$workDir/log.bad1" || fail "message for a missing ensemble"
coagulationEnsemble -resume -out "$out" -set system/controlDict:endTime=1 > "$workDir/log.bad2" 2>&1 \
    && fail "-resume with -set"
grep -q "drop -case, -seed0, -np and -set" "$workDir/log.bad2" || fail "message for -resume with -set"
coagulationEnsemble -resume -out "$out" -realisations 1 > "$workDir/log.bad3" 2>&1 && fail "-resume shrinking"
grep -q "fewer than the 3 realisations" "$workDir/log.bad3" || fail "message for shrinking"
# options without a value, and a number of realisations that would fill the disk
rc=0
coagulationEnsemble -case "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct" -realisations \
    > "$workDir/log.bad4" 2>&1 || rc=$?
[ "$rc" -eq 2 ] && grep -q -- "-realisations needs a value" "$workDir/log.bad4" \
    || { cat "$workDir/log.bad4"; fail "-realisations without a value: rc $rc"; }
coagulationEnsemble -case "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct" -realisations 1000000000000 \
    -out "$workDir/huge" > "$workDir/log.bad5" 2>&1 && fail "a huge -realisations was taken"
grep -q "at most 10000" "$workDir/log.bad5" || { cat "$workDir/log.bad5"; fail "message for a huge R"; }
[ ! -d "$workDir/huge" ] || [ -z "$(ls "$workDir/huge")" ] || fail "a huge R made folders"
# ---- core-seconds count every thread: one short realisation on 2 threads
rm -rf "$workDir/ensembleThreads"
coagulationEnsemble -case "$COAGULATIONFOAM_DIR/tutorials/constantKernelDuct" -realisations 1 -threads 2 \
    -out "$workDir/ensembleThreads" -set system/controlDict:endTime=0.01 \
    -set system/controlDict:writeInterval=0.01 -set constant/coagulationProperties:sampling/tRelax=0 \
    -- --no-plots > "$workDir/log.threads" 2>&1 || { tail -20 "$workDir/log.threads"; fail "2-thread ensemble failed"; }
grep -q "2 thread(s) for the cell step" "$workDir/ensembleThreads/realisation_0/log.coagulationFoam" \
    || fail "2-thread ensemble: the solver did not run on 2 threads"
"$COAGULATIONFOAM_PYTHON" - "$workDir/ensembleThreads" <<'PY' || fail "cpuSeconds of the 2-thread ensemble"
import json, sys
e = json.load(open(sys.argv[1] + "/ensemble.json"))
run = float(open(sys.argv[1] + "/realisation_0/runSeconds").read())
print("2 threads: runSeconds %.3f, cpuSeconds %.3f" % (run, e["cpuSeconds"]))
sys.exit(0 if e["threadsPerRank"] == 2 and abs(e["cpuSeconds"] - 2 * run) <= 0.002 else 1)
PY
echo "PASS ensemble: 2 realisations pooled; resumed past a half-written 0.6 from 0.3 to identical statistics; extended to 3; bad options refused; core-seconds count threads"
