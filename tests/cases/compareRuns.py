# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Two runs of a closed box (no flow: every cell an independent realisation) compared at
their last sample time (case_liveFields): the mean over the cells of M0..M2 in each run,
with the standard error of the cells' spread.

    compareRuns.py caseA caseB

Exit 0 when each of M0..M2 agrees within 4 standard errors of the difference and 6 %;
3 otherwise (an error of the script exits 1). Prints the figures.
"""
import glob, sys
import numpy as np
from coagulationPost import samples


def last(case):
    f = samples.read_sample_file(glob.glob(case + "/postProcessing/coagulationSamples/*.h5")[0])
    M = f["moments"][-1, :, :3]                      # [cell][moment]
    return f["times"][-1], M.mean(axis=0), M.std(axis=0, ddof=1) / np.sqrt(M.shape[0])


(ta, a, sa), (tb, b, sb) = last(sys.argv[1]), last(sys.argv[2])
if abs(ta - tb) > 1e-9:
    sys.exit("the runs end at %g and %g" % (ta, tb))
z = np.abs(a - b) / np.hypot(sa, sb)
rel = np.abs(a / b - 1)
print("t = %g: M0..M2 %s against %s, relative difference %s, |z| %s"
      % (ta, a, b, np.round(rel, 4), np.round(z, 2)))
sys.exit(0 if (z.max() < 4 and rel.max() < 0.06) else 3)
