#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
# What the log says of a run's progress: the constant-kernel duct for 10 000 steps (two writes)
# prints no line per step but a progress line at each write and at most every
# progressInterval (0.5 s here) between them (at least half as many), each with the fraction
# done, the steps per second and the time left, and at the end the steps and the wall time; a
# run of 400 steps prints a line every step (auto), and 'logSteps on' brings them back for a
# long run.
. "$(dirname "$0")/caseLib.sh"

c=$(newCase constantKernelDuct progress_long)
cd "$c"
setEntry . constant/coagulationProperties statisticalWeight/n 64
setEntry . system/controlDict endTime 1.0
setEntry . system/controlDict writeInterval 0.5
foamDictionary system/controlDict -entry progressInterval -add 0.5 > /dev/null
runApplication coagulationFoam
checkBalance log.coagulationFoam
"$COAGULATIONFOAM_PYTHON" - log.coagulationFoam <<'PY' || fail "progress lines of the long run"
import re, sys
lines = open(sys.argv[1]).read().splitlines()
steps = [l for l in lines if re.match(r"^Time = \S+  particles = \d+$", l)]
progress = [l for l in lines if re.match(r"^Time = \S+  \(\d+ %, step \d+ of 10000, \S+ steps/s, .* so far", l)]
end = [l for l in lines if re.match(r"^Run: 10000 steps in \S+( s)? of wall time, \S+ steps/s$", l)]
print("%d step lines, %d progress lines (first: %s; last: %s), end: %s"
      % (len(steps), len(progress), progress[0] if progress else None,
         progress[-1] if progress else None, end))
writes = [l for l in progress if re.match(r"^Time = (0.5|1)  ", l)]
left = [l for l in progress[:-1] if "left)" in l]
ok = not steps and len(writes) == 2 and len(end) == 1
ok &= len(left) == len(progress) - 1 and "(100 %, step 10000 of 10000" in progress[-1]
# between the writes a line at most every 0.5 s of the run's wall time, and at least half as
# many (the steps are short): the interval lines are there and respect the interval
m = re.search(r"in (\S+)( s)? of wall time", end[0]) if end else None
if m and m.group(2):
    wall = float(m.group(1))
elif m:
    h, mi, se = (int(v) for v in m.group(1).split(":"))
    wall = 3600 * h + 60 * mi + se
else:
    wall = 0.0
most, least = wall / 0.5 + 3, int(wall / 0.5) // 2
print("wall time %.1f s: %d progress lines (between %d and %.0f)" % (wall, len(progress), least, most))
ok &= least <= len(progress) <= most
sys.exit(0 if ok else 1)
PY

c=$(newCase constantKernelDuct progress_short)
cd "$c"
setEntry . system/controlDict endTime 0.04
setEntry . system/controlDict writeInterval 0.02
runApplication coagulationFoam
n=$(grep -c "^Time = .*  particles = " log.coagulationFoam)
[ "$n" -eq 400 ] || fail "a run of 400 steps printed $n step lines, not 400"
grep -q "^Run: 400 steps in" log.coagulationFoam || fail "no end line in the short run"

c=$(newCase constantKernelDuct progress_on)
cd "$c"
setEntry . system/controlDict endTime 0.06
setEntry . system/controlDict writeInterval 0.06
foamDictionary system/controlDict -entry logSteps -add on > /dev/null
runApplication coagulationFoam
n=$(grep -c "^Time = .*  particles = " log.coagulationFoam)
[ "$n" -eq 600 ] || fail "logSteps on: $n step lines of 600 steps"
echo "PASS progress: long runs print progress lines at the writes and every interval, short runs and 'logSteps on' a line every step"
