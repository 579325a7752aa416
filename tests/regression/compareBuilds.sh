#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# compareBuilds.sh REF NEW [WORK]: the same short runs with two built checkouts of
# coagulationFoam (each with its etc/bashrc, platforms/ and its own tutorials), compared byte
# for byte.
#
# For a change that must not change results (a refactoring): every file of every written time
# (M0..M3, the fieldAverage fields M*Mean and M*Prime2Mean, U, the particles under
# lagrangian/coagulationCloud, uniform/) and the HDF5 sample series (datasets and attributes,
# compared by value: HDF5's own bytes may differ) must be identical. Cases, each short:
#   constant-kernel duct with SWA, DSA1 and DSA2; additive-kernel duct SWA (n = 512);
#   SWA on 1 and 2 threads; a run restarted halfway; inflow through the inlet.
# Files that exist in one run only are differences too, unless --ignore names them (a
# regular expression on the path, e.g. --ignore coagulationCloudComplete for a change that
# adds that file).
#
#   tests/regression/compareBuilds.sh /work/old /work/main /tmp/compare
# exits 0 when everything is identical, 1 otherwise (and lists what differs).
set -euo pipefail
ignore='^$'
args=()
while [ $# -gt 0 ]; do
    case "$1" in
        --ignore) ignore="$2"; shift 2 ;;
        *) args+=("$1"); shift ;;
    esac
done
[ "${#args[@]}" -ge 2 ] || { sed -n '2,/^set /p' "$0" | grep '^#' | sed 's/^# \{0,1\}//'; exit 2; }
ref="$(cd "${args[0]}" && pwd)"
new="$(cd "${args[1]}" && pwd)"
work="${args[2]:-$(mktemp -d)}"
mkdir -p "$work"

# runCase build name tutorial threads edits...: one run with one build, in $work/<build>/<name>
runCase()
{
    local build="$1" name="$2" tutorial="$3" threads="$4"; shift 4
    local side; side=$([ "$build" = "$ref" ] && echo ref || echo new)
    local d="$work/$side/$name"
    rm -rf "$d"; mkdir -p "$(dirname "$d")"
    cp -r "$build/tutorials/$tutorial" "$d"   # each build with its own tutorials
    (
        # shellcheck source=/dev/null
        . "$build/etc/bashrc"
        cd "$d"
        foamDictionary system/controlDict -entry endTime -set 0.05 > /dev/null
        foamDictionary system/controlDict -entry writeInterval -set 0.025 > /dev/null
        foamDictionary constant/coagulationProperties -entry sampling/tRelax -set 0.01 > /dev/null
        local e
        for e in "$@"; do
            if [ "$e" = restart ]; then continue; fi
            foamDictionary "${e%%:*}" -entry "$(echo "${e#*:}" | cut -d= -f1)" \
                -set "${e#*=}" > /dev/null
        done
        blockMesh > log.blockMesh 2>&1
        if [[ " $* " == *" restart "* ]]; then
            foamDictionary system/controlDict -entry endTime -set 0.025 > /dev/null
            OMP_NUM_THREADS=$threads coagulationFoam > log.first 2>&1
            foamDictionary system/controlDict -entry endTime -set 0.05 > /dev/null
        fi
        OMP_NUM_THREADS=$threads coagulationFoam > log.coagulationFoam 2>&1
    ) || { echo "FAILED: $side $name (see $d/log.*)"; return 1; }
}

cases=(
    "constSWA constantKernelDuct 1"
    "constDSA1 constantKernelDuct 1 constant/coagulationProperties:algorithm=DSA1"
    "constDSA2 constantKernelDuct 1 constant/coagulationProperties:algorithm=DSA2"
    "addSWA additiveKernelDuct 1 constant/coagulationProperties:statisticalWeight/n=512"
    "constSWA2threads constantKernelDuct 2"
    "addSWA2threads additiveKernelDuct 2 constant/coagulationProperties:statisticalWeight/n=512"
    "restart constantKernelDuct 1 restart"
    "inflow constantKernelDuct 1 constant/coagulationProperties:inflow/density=1e7 constant/coagulationProperties:inception/rate=0 constant/coagulationProperties:statisticalWeight/n=2048"
)

status=0
for c in "${cases[@]}"; do
    # shellcheck disable=SC2086
    set -- $c
    runCase "$ref" "$@" || status=1
    runCase "$new" "$@" || status=1
done
[ "$status" -eq 0 ] || exit 1

# Every file of the written times and the sample series
"${COAGULATIONFOAM_PYTHON:-/usr/bin/python3}" - "$work" "$ignore" <<'EOF'
import filecmp, os, re, sys
import h5py
import numpy as np

work, ignore = sys.argv[1], re.compile(sys.argv[2])
bad = 0
compared = 0
for name in sorted(os.listdir(os.path.join(work, "ref"))):
    a_dir, b_dir = (os.path.join(work, s, name) for s in ("ref", "new"))
    times = [d for d in os.listdir(a_dir) if re.fullmatch(r"[0-9.e+-]+", d) and d != "0"]
    files = set()
    for side in (a_dir, b_dir):
        for t in times:
            for root, _, names in os.walk(os.path.join(side, t)):
                for f in names:
                    files.add(os.path.relpath(os.path.join(root, f), side))
    for f in sorted(files):
        if ignore.search(f):
            continue
        a, b = os.path.join(a_dir, f), os.path.join(b_dir, f)
        if not (os.path.exists(a) and os.path.exists(b)):
            print(f"{name}: {f} only in {'ref' if os.path.exists(a) else 'new'}")
            bad += 1
        elif not filecmp.cmp(a, b, shallow=False):
            print(f"{name}: {f} differs")
            bad += 1
        compared += 1
    sdir = "postProcessing/coagulationSamples"
    for f in sorted(os.listdir(os.path.join(a_dir, sdir))):
        if not f.endswith(".h5"):
            continue
        with h5py.File(os.path.join(a_dir, sdir, f)) as ha, h5py.File(os.path.join(b_dir, sdir, f)) as hb:
            for key in ("cellCentres", "time", "moments"):
                if not np.array_equal(ha[key][:], hb[key][:]):
                    print(f"{name}: {sdir}/{f}:/{key} differs")
                    bad += 1
            if {k: str(v) for k, v in ha.attrs.items()} != {k: str(v) for k, v in hb.attrs.items()}:
                print(f"{name}: {sdir}/{f} attributes differ")
                bad += 1
        compared += 1
print(f"compareBuilds: {compared} files compared, {bad} differ")
sys.exit(1 if bad else 0)
EOF
