# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The constant-kernel duct in a flow uniform in space with u(t) = u0 (1 + a sin(2 pi t/P))
(case_flowSeries, case_functionObject): the particles at x at time t are of age s, the lesser
of t (the duct was empty at t = 0) and the tau with int_{t-tau}^t u = x, so each cell's sampled
M0..M3 are the cell average of the homogeneous constant-kernel solution (eqs 39-45) at that age.

    sineDuct.py case u0 a P

Exit 0 when, over the samples from tRelax on, every cell's (from the fourth) time mean of
sample/exact - 1 is within 4 standard errors (correlated intervals) and 8 % of 0, and so are
the components of their cell mean at the flow's frequency and its double (a phase error
cancels in a time mean); 3 otherwise (an error of the script exits 1). Prints the figures.
"""
import glob, math, sys
import numpy as np
from scipy.optimize import brentq
from coagulationPost import analytic, samples, statistics
case, u0, a, P = sys.argv[1], *map(float, sys.argv[2:5])
f = samples.read_sample_file(glob.glob(case + "/postProcessing/coagulationSamples/*.h5")[0])
t, M, x = f["times"], f["moments"], f["centres"][:, 0]
keep = t >= f["attrs"]["tRelax"] - 1e-9     # the duct filled: the samples of the report
t, M = t[keep], M[keep]
I, K0 = f["attrs"]["inceptionRate"], f["attrs"]["K0"]
w = 2 * math.pi / P
travel = lambda t0, t1: u0 * ((t1 - t0) - a / w * (math.cos(w * t1) - math.cos(w * t0)))
dx = x[1] - x[0]
nodes = (np.polynomial.legendre.leggauss(6)[0] + 1) / 2      # on [0, 1]
weights = np.polynomial.legendre.leggauss(6)[1] / 2
exact = np.zeros_like(M)
for j, tj in enumerate(t):
    for i, xi in enumerate(x):
        m = 0.0
        for q, wq in zip(nodes, weights):
            xq = xi - dx / 2 + q * dx
            # age: the tau with travel(t - tau, t) = x, or t (the duct was empty at t = 0)
            age = tj if travel(0.0, tj) <= xq else brentq(lambda s: travel(tj - s, tj) - xq, 0.0, tj)
            m = m + wq * analytic.constant_duct(age, I, K0, 1.0)
        exact[j, i] = m
r = M / exact - 1.0                       # [time][cell][moment]
cells = slice(3, None)                    # the first cells' M2, M3: few particles
mean, neff, ci, tau = statistics.correlated_interval(r[:, cells, :])
se = ci / 1.96
worst_z = np.max(np.abs(mean) / se)
worst = np.max(np.abs(mean))
print("largest |mean(sample/exact - 1)| = %.4f, %.2f standard errors (cells 3..%d, M0..M3, %d samples)"
      % (worst, worst_z, len(x) - 1, len(t)))
# The deviation at the flow's frequency and its double: mean over the cells of sample/exact
# - 1, projected on sin and cos (a time mean cancels over a period what the phase gets wrong)
y = r[:, cells, :].mean(axis=1)
fourier_z = 0.0
for name, b in (("sin wt", np.sin(w * t)), ("cos wt", np.cos(w * t)),
                ("sin 2wt", np.sin(2 * w * t)), ("cos 2wt", np.cos(2 * w * t))):
    amp, _, ci_amp, _ = statistics.correlated_interval(2 * y * b[:, None])
    z = np.abs(amp) / (ci_amp / 1.96)
    fourier_z = max(fourier_z, z.max())
    print("  %-8s amplitude M0..M3 %s, |z| %s" % (name, np.round(amp, 4), np.round(z, 2)))
sys.exit(0 if (worst_z < 4 and worst < 0.08 and fourier_z < 4) else 3)
