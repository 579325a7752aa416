#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Planted-bug campaign (issue 21 part 2): for each bug of bugs.py, plant it, rebuild if it
# is in C++ (./Allwmake), run its targeted case tests (plus case_faults and case_badInput),
# revert it (git checkout) and print one line: caught (by which tests) or MISSED.
#
#   tests/regression/plantedBugs/run.sh [BUG...]     default: every bug of bugs.py
#   FULL=1 run.sh B20          the whole case suite (ctest -L case) instead of the targeted tests
#   LOGDIR=dir                 logs per bug (default /tmp/plantedBugs): BUG.diff, BUG.build.log,
#                              BUG.ctest.log; one line per bug appended to LOGDIR/summary
#   JOBS=1                     ctest -j (default 2; 1 where the machine's cores are shared)
#   TESTS=regex                this ctest -R regex instead of the bug's targeted tests
# Needs a built tree (./Allwmake) with build/ configured; the bug's file must be unmodified.
# Runs niced, ctest -j${JOBS:-2}. The clean tree is rebuilt at the end if a C++ bug was planted.
set -u
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bugs="python3 $here/bugs.py"
logDir="${LOGDIR:-/tmp/plantedBugs}"
mkdir -p "$logDir"
cd "$root" || exit 1
export BUGROOT="$root"
# shellcheck source=/dev/null
. etc/bashrc > /dev/null 2>&1

ids=("$@")
[ ${#ids[@]} -gt 0 ] || mapfile -t ids < <($bugs list | awk '/^B[0-9]/ {print $1}')

planted=""
revert()
{
    [ -n "$planted" ] || return 0
    git checkout -- "$planted"
    git diff --quiet -- "$planted" || { echo "REVERT FAILED: $planted" >&2; exit 3; }
    planted=""
}
trap 'revert; exit 130' INT TERM

rebuild=""
for b in "${ids[@]}"; do
    file=$($bugs file "$b") || exit 2
    git diff --quiet -- "$file" || { echo "$b: $file has local changes; not planting" >&2; exit 2; }
    start=$(date +%s)
    $bugs plant "$b" > "$logDir/$b.txt" || { echo "$b: NOT PLANTED (string gone?)"; continue; }
    planted="$file"
    git diff -- "$file" > "$logDir/$b.diff"
    status=""
    case "$file" in
        *.C|*.H|*.cpp|*.hpp)
            rebuild=1
            nice -n 10 ./Allwmake > "$logDir/$b.build.log" 2>&1 || status="caught by the build (does not compile)"
            ;;
    esac
    if [ -z "$status" ]; then
        if [ -n "${FULL:-}" ]; then sel=(-L case); what="full case suite"
        elif [ -n "${TESTS:-}" ]; then sel=(-R "$TESTS"); what="tests $TESTS"
        else sel=(-R "$($bugs tests "$b")"); what="targeted"; fi
        (cd build && nice -n 10 ctest "${sel[@]}" -j"${JOBS:-2}" --output-on-failure) > "$logDir/$b.ctest.log" 2>&1
        failed=$(grep -E "^ *[0-9]+/[0-9]+ Test +#[0-9]+: .*\*\*\*" "$logDir/$b.ctest.log" \
                 | sed -E 's/.*Test +#[0-9]+: ([^ ]+) .*/\1/' | sort | tr '\n' ' ')
        passed=$(grep -E "^ *[0-9]+/[0-9]+ Test +#[0-9]+: .* Passed" "$logDir/$b.ctest.log" \
                 | sed -E 's/.*Test +#[0-9]+: ([^ ]+) .*/\1/' | sort | tr '\n' ' ')
        if [ -n "$failed" ]; then status="caught by: ${failed% }"
        else status="MISSED"; fi
        status="$status ($what; passed: ${passed% })"
    fi
    revert
    line="$b $(date +%T) $(( $(date +%s) - start )) s $(sed 's/ planted at / /' "$logDir/$b.txt" | cut -d' ' -f2): $status"
    echo "$line"
    echo "$line" >> "$logDir/summary"
done

if [ -n "$rebuild" ]; then
    nice -n 10 ./Allwmake > "$logDir/final.build.log" 2>&1 || echo "clean rebuild FAILED: $logDir/final.build.log"
fi
