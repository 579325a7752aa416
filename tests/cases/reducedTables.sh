#!/bin/bash
# Reduced Tables 1 and 2 of Patterson & Wagner on the additive-kernel duct: the paper's study
# (coagulationTableStudy) at small n with few realisations, and its acceptance statements as
# checks (coagulationTables.py --check): SWA M1 near 9.877e3 and M2 near 9.1e7, SWA sd ~ n^-1/2,
# SWA sqrt(n var M1)/m1 on eq. (47), DSA1 M1 significantly above 9.90e3, DSA2 M2 rising with n.
# With these few samples the SWA mean tolerances are widened by 3 standard errors of the run.
. "$(dirname "$0")/caseLib.sh"

out="$workDir/study"
rm -rf "$out" "$workDir/log.study" "$workDir/log.tables"
mkdir -p "$workDir"
# rows: SWA n = 512 (8 realisations), 1024 (4) over [0.2, 0.4]; DSA1 n = 256 (8) over
# [0.2, 2.0]; DSA2 n = 256 (8), 512 (4) over [0.2, 1.0]
study() { coagulationTableStudy -out "$out" "$@" -- --no-plots >> "$workDir/log.study" 2>&1 \
    || { tail -30 "$workDir/log.study"; fail "coagulationTableStudy $*"; }; }
study -methods SWA -n 512,1024 -total 4096
study -methods DSA1 -n 256 -total 2048 -max-realisations 8 -dsa-end 2.0
study -methods DSA2 -n 256,512 -total 2048 -dsa-end 1.0
grep "==\|finished" "$workDir/log.study"

# DSA1's bias needs far more samples than CI can afford for 3 standard errors (the full
# study has them): here it is asserted at 1 SE, the DSA2 trend at 3
status=0
$COAGULATIONFOAM_PYTHON "$COAGULATIONFOAM_DIR/applications/utilities/coagulationTables/coagulationTables.py" \
    --rows "$out"/*_n* --out "$out/results" --check --z-ci 3 --z-dsa1 1 > "$workDir/log.tables" 2>&1 \
    || status=$?
cat "$workDir/log.tables"
[ "$status" -eq 0 ] || fail "reduced table checks: exit status $status"
for f in table1.csv table1.md table2.csv table2.md rows.csv figure7.png figure8.png figure9.png figure10.png; do
    [ -s "$out/results/$f" ] || fail "no $f"
done
[ "$(wc -l < "$out/results/table1.csv")" -eq 6 ] || fail "table1.csv should have 5 rows"
for r in "$out"/*_n*/realisation_*; do checkBalance "$r/log.coagulationFoam" > /dev/null; done
# the rows of one study (SWA n = 512 and 1024; DSA2 n = 256 and 512) are independent: no
# two realisations share a seed (separate studies number their rows from 1 again, so rows of
# the three calls above do share seeds)
for rows in "SWA_n512 SWA_n1024" "DSA2_n256 DSA2_n512"; do
    seeds=$(for r in $rows; do cat "$out/$r"/realisation_*/constant/coagulationProperties; done \
            | awk '$1 == "seed" { print $2 }')
    nReal=$(for r in $rows; do ls -d "$out/$r"/realisation_*; done | wc -l)
    [ "$(wc -l <<< "$seeds")" -eq "$nReal" ] || fail "$rows: $nReal realisations, $(wc -l <<< "$seeds") seeds"
    dup=$(sort <<< "$seeds" | uniq -d | tr '\n' ' ')
    [ -z "$dup" ] || fail "rows $rows share seeds: $dup"
done

# An interrupted row is resumed, not redone: SWA n = 1024 as if the study had been stopped
# during its last realisation (the row's folder still .running, that realisation unfinished).
# The study keeps the 3 finished realisations, reruns the 4th from its latest time (0: the
# study removed the written times) and the tables come out the same.
cp "$out/results/table1.csv" "$workDir/table1.before.csv"
mv "$out/SWA_n1024" "$out/SWA_n1024.running"
rm "$out/SWA_n1024.running/ensemble.json" "$out/SWA_n1024.running/realisation_3/runSeconds"
study -methods SWA -n 512,1024 -total 4096
grep -q "SWA n=512: done before" "$workDir/log.study" || fail "finished row not kept"
grep -q "SWA n=1024: resuming the interrupted row" "$workDir/log.study" || fail "interrupted row not resumed"
[ "$(grep -c "kept:" "$out/SWA_n1024/log.coagulationEnsemble")" -eq 3 ] || fail "finished realisations not kept"
grep -q "resumed: .*realisation_3 from time 0" "$out/SWA_n1024/log.coagulationEnsemble" \
    || fail "unfinished realisation not resumed"
$COAGULATIONFOAM_PYTHON "$COAGULATIONFOAM_DIR/applications/utilities/coagulationTables/coagulationTables.py" \
    --rows "$out"/*_n* --out "$out/results" > "$workDir/log.tables.resumed" 2>&1 \
    || fail "tables after the resumed row"
cmp -s "$out/results/table1.csv" "$workDir/table1.before.csv" || fail "table 1 changed after resuming a row"
echo "PASS reduced tables (and an interrupted row resumed to the same table 1)"
