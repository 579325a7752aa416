# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Two runs of a closed box (no flow) compared at their last sample time (case_liveFields).

    compareRuns.py caseA caseB            M0..M2: every cell an independent realisation
    compareRuns.py --spread N caseA caseB the variance of the particles' x about their mean

The moments: the mean over the cells of M0..M2 in each run, with the standard error of the
cells' spread. The spread: the M0-weighted variance of the cell centres' x, with the standard
error of the variance of N independent particles, sqrt((m4 - var^2)/N) (m4 the fourth
central moment of the same distribution).

Exit 0 when each figure agrees within 4 standard errors of the difference and 6 %;
3 otherwise (an error of the script exits 1). Prints the figures.
"""
import glob, sys
import numpy as np
from coagulationPost import samples


def last(case):
    f = samples.read_sample_file(glob.glob(case + "/postProcessing/coagulationSamples/*.h5")[0])
    return f["times"][-1], f["moments"][-1], f["centres"][:, 0]


def moments(case):
    t, M, _ = last(case)
    M = M[:, :3]                                     # [cell][moment]
    return t, M.mean(axis=0), M.std(axis=0, ddof=1) / np.sqrt(M.shape[0])


def spread(case, n):
    t, M, x = last(case)
    p = M[:, 0] / M[:, 0].sum()
    mean = (p * x).sum()
    var = (p * (x - mean) ** 2).sum()
    m4 = (p * (x - mean) ** 4).sum()
    return t, np.array([var]), np.array([np.sqrt((m4 - var ** 2) / n)])


args = sys.argv[1:]
if args[0] == "--spread":
    n = float(args[1])
    (ta, a, sa), (tb, b, sb) = spread(args[2], n), spread(args[3], n)
    what = "variance of x"
else:
    (ta, a, sa), (tb, b, sb) = moments(args[0]), moments(args[1])
    what = "M0..M2"
if abs(ta - tb) > 1e-9:
    sys.exit("the runs end at %g and %g" % (ta, tb))
z = np.abs(a - b) / np.hypot(sa, sb)
rel = np.abs(a / b - 1)
print("t = %g: %s %s against %s, relative difference %s, |z| %s"
      % (ta, what, a, b, np.round(rel, 4), np.round(z, 2)))
sys.exit(0 if (z.max() < 4 and rel.max() < 0.06) else 3)
