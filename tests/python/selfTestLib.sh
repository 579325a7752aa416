# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# Shared set-up of the Python tools' self-tests (bash, sourced): PASS/FAIL counters, the
# interpreter check and a temporary folder removed on exit.
#   . selfTestLib.sh NAME      then ok/ko "message" ...; finish
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
PY=/usr/bin/python3
# the package coagulationPost, as etc/bashrc finds it
export PYTHONPATH="$ROOT/src/python${PYTHONPATH:+:$PYTHONPATH}"

pass=0
fail=0
ok() { pass=$((pass + 1)); echo "PASS: $1"; }
ko() { fail=$((fail + 1)); echo "FAIL: $1"; }
finish() { echo "$pass passed, $fail failed"; [ "$fail" -eq 0 ]; exit $?; }

# run_expect DESCRIPTION EXPECTED_RC LOG -- command...
run_expect() {
    local desc=$1 want=$2 log=$3; shift 4
    "$@" > "$log" 2>&1
    local rc=$?
    if [ "$rc" -eq "$want" ]; then ok "$desc (exit $rc)"; else
        ko "$desc: exit $rc, expected $want; output tail:"; tail -n 15 "$log" | sed 's/^/    /'; fi
}

if ! "$PY" -c "import numpy, h5py, scipy, matplotlib" 2>/dev/null; then
    ko "$PY cannot import numpy, h5py, scipy and matplotlib"
    finish
fi

TMP=$(mktemp -d "${TMPDIR:-/tmp}/$1.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
