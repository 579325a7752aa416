# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Sample statistics of the moment samples.

A group of samples is summarised by (count, mean, m2), m2 the sum of squared
deviations from the mean, elementwise over arrays (cells x moments).  Groups —
the time samples of one run, realisations, ensembles — are pooled with
Chan, Golub & LeVeque's parallel update (merge), the one place the pooling
formula is written.  As in Patterson & Wagner (section 2, after eq. 37),
successive samples are treated as independent in summary: the 95 % half-width
of a mean is Z95 sd / sqrt(count) (the "iid" interval).  Successive samples of a
run are correlated over up to the residence time upstream of a cell, so that
interval is too narrow; correlated_interval gives one from the integrated
autocorrelation time of each run's ordered time series (autocorrelation_time,
effective sample size), and standard_error_from_realisations one from
independent realisations.
"""

import math
import os

import numpy as np

Z95 = 1.96


def batch(data):
    """(count, mean, m2) over axis 0 of data, NaN = no sample; mean and m2 are 0
    where count is 0."""
    valid = ~np.isnan(data)
    nb = valid.sum(axis=0).astype(float)
    with np.errstate(invalid="ignore", divide="ignore"):
        mb = np.where(nb > 0, np.nansum(data, axis=0) / np.maximum(nb, 1), 0.0)
        m2b = np.nansum((data - mb[None]) ** 2, axis=0)
    return nb, mb, m2b


def merge(a, b):
    """Pool two groups (count, mean, m2) into one (Chan et al.'s parallel update):

        n = na + nb,  mean = ma + d nb/n,  m2 = m2a + m2b + d^2 na nb/n,  d = mb - ma.

    Empty groups (count 0) may carry any finite mean and m2 = 0."""
    na, ma, m2a = a
    nb, mb, m2b = b
    n = na + nb
    safe = np.maximum(n, 1)
    delta = mb - ma
    mean = np.where(n > 0, ma + delta * nb / safe, 0.0)
    m2 = m2a + m2b + delta ** 2 * na * nb / safe
    return n, mean, m2


def pool(groups):
    """Pool a sequence of groups (count, mean, m2) with merge."""
    groups = iter(groups)
    acc = next(groups)
    for g in groups:
        acc = merge(acc, g)
    return acc


def group_of(count, mean, var):
    """(count, mean, m2) of a group summarised by count, mean and sample variance
    (NaN mean or variance where count is 0 or 1 is allowed)."""
    count = np.asarray(count, dtype=float)
    mean = np.where(count > 0, mean, 0.0)
    m2 = np.where(count > 1, np.asarray(var) * (count - 1), 0.0)
    return count, mean, m2


def summary(count, mean, m2):
    """mean (NaN without samples), sample variance and sd (N - 1; NaN below two
    samples) and the 95 % half-width Z95 sd / sqrt(count)."""
    mean = np.where(count > 0, mean, np.nan)
    with np.errstate(invalid="ignore", divide="ignore"):
        var = np.where(count > 1, m2 / np.maximum(count - 1, 1), np.nan)
        sd = np.sqrt(var)
        ci = Z95 * sd / np.sqrt(count)
    return {"mean": mean, "var": var, "sd": sd, "ci": ci}


def normalised_sd(n, var, reference, mean):
    """sqrt(n var(M_{n,k})) / m_k, the left side of eq. (47) and the quantity of the
    paper's Figures 3-6 and 9: m_k the analytic reference where it is finite, else the
    sample mean; NaN without a statistical weight n."""
    if not n:
        return np.full_like(var, np.nan)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.sqrt(n * var) / np.where(np.isfinite(reference), reference, mean)


class Accumulator:
    """Per-cell, per-moment count / mean / m2, pooled batch by batch with merge;
    cells are ids (samples.CellIndex), the arrays grow as new ids appear."""

    def __init__(self, nmom):
        self.nmom = nmom
        self.count = np.zeros((0, nmom))
        self.mean = np.zeros((0, nmom))
        self.m2 = np.zeros((0, nmom))

    def add(self, ids, data):
        """data: [nSamples][len(ids)][nmom], NaN = no sample."""
        new = int(ids.max()) + 1 - len(self.count) if len(ids) else 0
        if new > 0:
            z = np.zeros((new, self.nmom))
            self.count = np.vstack([self.count, z])
            self.mean = np.vstack([self.mean, z])
            self.m2 = np.vstack([self.m2, z])
        n, mean, m2 = merge((self.count[ids], self.mean[ids], self.m2[ids]), batch(data))
        self.count[ids], self.mean[ids], self.m2[ids] = n, mean, m2


def student_t975(dof):
    """97.5 % quantile of Student's t (two-sided 95 %); scipy is a bootstrap dependency."""
    from scipy.stats import t
    return float(t.ppf(0.975, dof))


def standard_error_from_realisations(means):
    """Standard error of the pooled mean from R realisation means (axis 0) and its
    95 % half-width (Student t, R - 1 degrees of freedom); NaN when R < 2."""
    means = np.asarray(means, dtype=float)
    R = means.shape[0]
    if R < 2:
        nan = np.full(means.shape[1:], np.nan)
        return nan, nan.copy()
    se = means.std(axis=0, ddof=1) / math.sqrt(R)
    return se, student_t975(R - 1) * se


def standard_error_of_sd(realisation_sds, sd, count):
    """Standard error of a pooled sd: from the spread of the R realisations' own
    sds (axis 0) when R >= 3 (this sees the samples' correlation), else the
    independent-sample value sd / sqrt(2 count)."""
    R = len(realisation_sds)
    with np.errstate(invalid="ignore", divide="ignore"):
        if R >= 3:
            return np.asarray(realisation_sds).std(axis=0, ddof=1) / math.sqrt(R)
        return sd / np.sqrt(2.0 * np.maximum(count, 1))


# ------------------------------------------------------------ correlated time samples

SOKAL_C = 5.0        # window constant: the sum of the autocorrelations stops at the
                     # first lag M >= SOKAL_C tau(M) (Sokal 1997, section 3)


def _windowed(x, c, min_window=0):
    """Sokal's windowed autocorrelation sum of each column of x [N][cols]:
    (tau(M), M, gamma0, constant) with tau(M) = 1/2 + sum_{t=1}^{M} rho(t); the window
    is at least min_window (scalar or per column) and at most N/4."""
    N = x.shape[0]
    d = x - x.mean(axis=0)
    nfft = 1 << int(2 * N - 1).bit_length()
    f = np.fft.rfft(d, n=nfft, axis=0)
    acov = np.fft.irfft(f * np.conj(f), n=nfft, axis=0)[:N] / N
    g0 = acov[0]
    const = ~(g0 > 1e-28 * np.maximum(1e-300, np.abs(x).max(axis=0)) ** 2)
    with np.errstate(invalid="ignore", divide="ignore"):
        rho = acov / np.where(const, 1.0, g0)
    taus = 0.5 + np.cumsum(rho[1:], axis=0)          # tau(M), M = 1..N-1
    lags = np.arange(1, N)[:, None]
    Mmax = max(N // 4, 1)
    ok = lags >= c * taus
    ok[Mmax:] = False
    found = ok.any(axis=0)
    M = np.where(found, np.argmax(ok, axis=0) + 1, Mmax)
    cols = np.arange(taus.shape[1])
    tau = taus[M - 1, cols]
    # min_window: the longer window where it gives the larger tau (a tail beyond
    # Sokal's window), never a smaller one (its noise could make tau near 0)
    Mw = np.minimum(np.maximum(M, np.broadcast_to(np.asarray(min_window, dtype=int), M.shape)),
                    Mmax)
    Nf = float(N)
    tau_w = taus[Mw - 1, cols]
    longer = tau_w / (Nf - 2 * Mw - 1) > tau / (Nf - 2 * M - 1)
    M = np.where(longer, Mw, M)
    tau = np.where(longer, tau_w, tau)
    # at least 1/2, the independent-sample value: a negative estimate of the sum (noise,
    # or anticorrelated samples) never makes the interval narrower than the iid one
    tau = np.where(const, 0.5, np.maximum(tau, 0.5))
    M = np.where(const, 0, M)
    return tau, M, g0, const, found


def autocorrelation_time(series, c=SOKAL_C, min_window=0):
    """Integrated autocorrelation time tau_int of each column of series [N][...]
    (NaN-free, ordered in time, equally spaced), in sample units:

        tau_int = 1/2 + sum_{t=1}^{M} rho(t),

    rho the sample autocorrelation (FFT, mean subtracted, 1/N normalisation) and M
    Sokal's automatic window, the smallest lag with M >= c tau_int(M) (c = 5; Sokal,
    "Monte Carlo methods in statistical mechanics: foundations and new algorithms",
    1997, section 3; also emcee's autocorr), but at least min_window lags (the
    correlation time known from elsewhere, e.g. a residence time) and at most N/4.
    tau_int = 1/2 for independent samples; for an AR(1) series with coefficient phi,
    tau_int = (1+phi)/(2(1-phi)).

    This is the plain estimate, biased low on short series (the mean subtraction
    lowers every rho(t) by about 2 tau/N), and blind to a weak tail of rho beyond
    Sokal's window; correlated_interval corrects the first and min_window guards
    against the second.  tau_int is at least 1/2 (a negative windowed sum, from
    noise or anticorrelated samples, is not trusted).  Constant columns get 1/2.  Shape series.shape[1:]."""
    x = np.asarray(series, dtype=float)
    N = x.shape[0]
    if N < 4:
        return np.full(x.shape[1:], 0.5)
    mw = np.broadcast_to(np.asarray(min_window), x.shape[1:]).reshape(-1)
    return _windowed(x.reshape(N, -1), c, mw)[0].reshape(x.shape[1:])


def correlated_interval(series, c=SOKAL_C, min_window=0):
    """Mean, effective sample size and 95 % half-width of the mean of each column of
    one run's ordered time series [N][...] (NaN-free), allowing for the correlation
    of successive samples.  With tau_int and the window M of autocorrelation_time
    and gamma0 = m2/N (m2 = sum (x_i - mean)^2):

        var(mean) = 2 tau_int gamma0 / (N - 2M - 1)
        n_eff     = sd^2 / var(mean)      (sd^2 = m2/(N-1); = N for independent samples)
        nu        = N / (2M + 1)
        half-width = t_{0.975, nu} sqrt(var(mean))        (Student t, nu dof)

    2 tau_int gamma0 = sum_{|t|<=M} gamma(t) is the truncated-window spectral estimate
    of N var(mean) at frequency 0 (Sokal 1997, eq. 3.19 ff.); each sample autocovariance
    is low by var(mean) on average (the mean is subtracted), so the sum is low by the
    factor (N - 2M - 1)/N, which the denominator undoes; nu is the equivalent degrees
    of freedom of that estimate (Priestley, "Spectral analysis and time series", 1981,
    section 6.2.4: nu = 2N / sum lambda(t)^2 away from frequency 0, half that at 0,
    sum lambda^2 = 2M + 1 for the truncated window), so the t quantile allows for
    the noise of tau_int on short series.  Series of 320 samples with tau_int = 10
    (AR(1)) cover 89 % with N/(2 tau_int) and n_eff - 1 dof and no bias correction,
    95 % with them (tests/python/test_correlated.py).

    min_window (lags; scalar or per column): the smallest window, against a weak
    tail of rho beyond Sokal's window, which the windowed sum cannot tell from noise
    (coagulationPost.report passes the residence time upstream of the cell).  The
    window is at most N/4; where Sokal's condition is not met below N/4 the series
    is too short to see its correlation, the window is N/4 (nu ~ 2: a wide interval,
    still low when tau_int > N/20).  Constant columns: half-width 0.  COAGULATIONPOST_IID_INTERVAL=1 (tests) sets tau_int = 1/2, M = 0: the
    independent-sample interval with t_{N}.  Returns (mean, n_eff, ci, tau_int)."""
    x = np.asarray(series, dtype=float)
    N = x.shape[0]
    shape = x.shape[1:]
    if N < 4:
        nan = np.full(shape, np.nan)
        return (x.mean(axis=0) if N else nan), np.full(shape, float(N)), nan, np.full(shape, 0.5)
    flat = x.reshape(N, -1)
    mw = np.broadcast_to(np.asarray(min_window), shape).reshape(-1)
    tau, M, g0, const, found = _windowed(flat, c, mw)
    if os.environ.get("COAGULATIONPOST_IID_INTERVAL") == "1":   # tests: the correction removed
        tau, M = np.full_like(tau, 0.5), np.zeros_like(M)
    mean = flat.mean(axis=0)
    m2 = g0 * N
    from scipy.stats import t as student
    with np.errstate(invalid="ignore", divide="ignore"):
        var_mean = np.maximum(2.0 * tau, 1e-3) * g0 / np.maximum(N - 2 * M - 1, 1)
        sd2 = m2 / (N - 1)
        neff = np.where(const, float(N), sd2 / var_mean)
        nu = N / (2.0 * M + 1.0)
        ci = student.ppf(0.975, np.maximum(nu, 1.0)) * np.sqrt(var_mean)
        ci = np.where(const, 0.0, ci)
    return (mean.reshape(shape), neff.reshape(shape), ci.reshape(shape), tau.reshape(shape))


def correlated_interval_masked(data, min_window=0):
    """correlated_interval of each column of data [N][cells][moments] with NaN for a
    missing sample: columns without NaN together, the others on their valid samples
    (gaps closed).  Returns (mean, n_eff, ci, tau) [cells][moments]; NaN / 0 where a
    column has no sample."""
    data = np.asarray(data, dtype=float)
    shape = data.shape[1:]
    flat = data.reshape(data.shape[0], -1)
    full = ~np.isnan(flat).any(axis=0)
    mw = np.broadcast_to(np.asarray(min_window), shape).reshape(-1)
    out = [np.full(flat.shape[1], np.nan) for _ in range(4)]
    out[1][:] = 0.0
    if full.any():
        r = correlated_interval(flat[:, full], min_window=mw[full])
        for o, v in zip(out, r):
            o[full] = v
    for j in np.nonzero(~full)[0]:
        col = flat[:, j]
        col = col[~np.isnan(col)]
        if col.size:
            r = correlated_interval(col[:, None], min_window=mw[j:j + 1])
            for o, v in zip(out, r):
                o[j] = v[0]
    return tuple(o.reshape(shape) for o in out)


def fit_exponent(ns, ys):
    """Slope of log y against log n (least squares): y ~ n^slope."""
    a = np.polyfit(np.log(np.asarray(ns, float)), np.log(np.asarray(ys, float)), 1)
    return float(a[0])
