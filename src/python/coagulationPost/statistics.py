# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Sample statistics of the moment samples.

A group of samples is summarised by (count, mean, m2), m2 the sum of squared
deviations from the mean, elementwise over arrays (cells x moments).  Groups —
the time samples of one run, realisations, ensembles — are pooled with
Chan, Golub & LeVeque's parallel update (merge), the one place the pooling
formula is written.  As in Patterson & Wagner (section 2, after eq. 37),
successive samples are treated as independent: the 95 % half-width of a mean
is Z95 sd / sqrt(count); standard_error_from_realisations gives the one that
does not rely on it.
"""

import math

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


def fit_exponent(ns, ys):
    """Slope of log y against log n (least squares): y ~ n^slope."""
    a = np.polyfit(np.log(np.asarray(ns, float)), np.log(np.asarray(ys, float)), 1)
    return float(a[0])
