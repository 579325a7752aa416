# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""A closed box (no flow) with the constant kernel and an inception rate that grows linearly
in time, r(t) = r0 + b t, in every cell (case_liveFields): M0..M2 are the solutions of the
closed moment equations dM0/dt = r - K0 M0^2/2, dM1/dt = r, dM2/dt = r + K0 M1^2 (eqs 38-44
with a rate of time; incepted particles of mass 1), from an empty box.

    rampBox.py case r0 b [moments]

Every cell is an independent realisation (its own random streams, nothing moves between
cells), so at each sample time the mean over the cells of sample/exact - 1 has the standard
error of the cells' spread. Exit 0 when at every sample time from t = 0.02 on each of M0..M2
is within 4 standard errors and 8 % of the exact value; 3 otherwise (an error of the script
exits 1). Prints the figures. moments (default 012) names the moments checked: M1 alone is
exact for any time step when the rate is taken at the middle of each step.
"""
import glob, sys
import numpy as np
from scipy.integrate import solve_ivp
from coagulationPost import samples
case, r0, b = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
checked = [int(k) for k in (sys.argv[4] if len(sys.argv) > 4 else "012")]
f = samples.read_sample_file(glob.glob(case + "/postProcessing/coagulationSamples/*.h5")[0])
t, M = f["times"], f["moments"]
K0 = f["attrs"]["K0"]
keep = t >= 0.02 - 1e-9
t, M = t[keep], M[keep]


def rhs(s, m):
    r = r0 + b * s
    return [r - 0.5 * K0 * m[0] ** 2, r, r + K0 * m[1] ** 2]


exact = solve_ivp(rhs, (0.0, t[-1]), [0.0, 0.0, 0.0], t_eval=t, rtol=1e-10, atol=1e-3).y.T
ratio = (M[:, :, :3] / exact[:, None, :] - 1.0)[:, :, checked]     # [time][cell][moment]
mean = ratio.mean(axis=1)
se = ratio.std(axis=1, ddof=1) / np.sqrt(ratio.shape[1])
z = np.abs(mean) / se
for j in range(0, len(t), max(1, len(t) // 4)):
    print("t = %.3f: sample/exact - 1 for M%s %s, |z| %s"
          % (t[j], ",".join(map(str, checked)), np.round(mean[j], 4), np.round(z[j], 2)))
print("largest |sample/exact - 1| %.4f, %.2f standard errors (%d times, %d cells)"
      % (np.abs(mean).max(), z.max(), len(t), ratio.shape[1]))
sys.exit(0 if (z.max() < 4 and np.abs(mean).max() < 0.08) else 3)
