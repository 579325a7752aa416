# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.statistics: pooled groups equal the one-pass statistics of the
samples put together; confidence intervals cover at their nominal rate on iid
synthetic data (fixed seeds)."""

import math

import numpy as np
import pytest

from coagulationPost import statistics as st


def one_pass(x):
    return len(x), x.mean(axis=0), x.var(axis=0, ddof=1)


def test_pool_equals_concatenated_samples():
    """Groups of 1..40 samples with different means and spreads, pooled in any order."""
    rng = np.random.default_rng(1)
    groups = [rng.normal(10 * rng.standard_normal(3), rng.uniform(0.1, 5), size=(m, 3))
              for m in (1, 40, 2, 17, 5)]
    allx = np.concatenate(groups)
    n, mean, var = one_pass(allx)
    for order in ([0, 1, 2, 3, 4], [4, 2, 0, 3, 1]):
        c, m, m2 = st.pool(st.batch(groups[i]) for i in order)
        np.testing.assert_array_equal(c, n)
        np.testing.assert_allclose(m, mean, rtol=1e-13)
        np.testing.assert_allclose(m2 / (c - 1), var, rtol=1e-12)


def test_pool_of_summaries_with_empty_and_single_groups():
    """Realisations summarised by count, mean and variance (NaN where undefined), as
    coagulationPost.report gives them, pool to the statistics of all their samples."""
    rng = np.random.default_rng(2)
    parts = [rng.normal(5.0 + k, 1.0 + k, size=(m, 4)) for k, m in enumerate((30, 1, 12))]
    summaries = [st.group_of(np.full(4, len(p)), p.mean(axis=0),
                             p.var(axis=0, ddof=1) if len(p) > 1 else np.full(4, np.nan))
                 for p in parts]
    summaries.append(st.group_of(np.zeros(4), np.full(4, np.nan), np.full(4, np.nan)))
    c, m, m2 = st.pool(summaries)
    res = st.summary(c, m, m2)
    n, mean, var = one_pass(np.concatenate(parts))
    np.testing.assert_array_equal(c, n)
    np.testing.assert_allclose(res["mean"], mean, rtol=1e-13)
    np.testing.assert_allclose(res["var"], var, rtol=1e-12)
    np.testing.assert_allclose(res["ci"], 1.96 * np.sqrt(var) / np.sqrt(n), rtol=1e-12)


def test_batch_ignores_missing_samples():
    x = np.array([[1.0, np.nan], [3.0, np.nan], [np.nan, np.nan], [8.0, 2.0]])
    c, m, m2 = st.batch(x)
    np.testing.assert_array_equal(c, [3, 1])
    np.testing.assert_allclose(m, [4.0, 2.0])
    np.testing.assert_allclose(m2, [26.0, 0.0])
    c, m, m2 = st.batch(np.full((2, 1), np.nan))
    assert (c[0], m[0], m2[0]) == (0, 0, 0)


def test_accumulator_per_cell_over_batches():
    """Cells appearing in some batches only, in any order: per-cell one-pass values."""
    rng = np.random.default_rng(3)
    acc = st.Accumulator(2)
    per_cell = {c: [] for c in range(4)}
    for ids in ([2, 0], [1, 2, 3], [3], [0, 1, 2, 3]):
        data = rng.normal(rng.uniform(-5, 5), rng.uniform(0.5, 2), size=(int(rng.integers(1, 9)), len(ids), 2))
        data[0, 0, 1] = np.nan                       # one missing sample
        acc.add(np.array(ids), data)
        for j, c in enumerate(ids):
            per_cell[c].append(data[:, j, :])
    for c, chunks in per_cell.items():
        x = np.concatenate(chunks)
        for k in range(2):
            v = x[~np.isnan(x[:, k]), k]
            assert acc.count[c, k] == len(v)
            assert acc.mean[c, k] == pytest.approx(v.mean(), rel=1e-13)
            assert acc.m2[c, k] == pytest.approx(((v - v.mean())**2).sum(), rel=1e-11)


def test_summary_needs_two_samples():
    res = st.summary(np.array([0.0, 1.0, 2.0]), np.array([0.0, 3.0, 3.0]), np.array([0.0, 0.0, 2.0]))
    assert np.isnan(res["mean"][0]) and res["mean"][1] == 3.0
    assert np.isnan(res["var"][1]) and res["var"][2] == 2.0
    assert res["ci"][2] == pytest.approx(1.96 * math.sqrt(2.0) / math.sqrt(2.0))


def test_ci95_coverage_iid():
    """Z95 sd/sqrt(N) of N = 200 iid normal samples covers the true mean 95 % of the time
    (4000 trials: binomial sd 0.34 %)."""
    rng = np.random.default_rng(4)
    x = rng.normal(3.0, 2.0, size=(200, 4000))
    res = st.summary(*st.batch(x))
    cover = np.mean(np.abs(res["mean"] - 3.0) <= res["ci"])
    assert 0.935 <= cover <= 0.962, cover


def test_realisation_ci_coverage_student_t():
    """Four realisation means: the Student t (3 dof) half-width covers 95 %; 1.96 SE
    would cover about 86 %."""
    rng = np.random.default_rng(5)
    means = rng.normal(1.0, 0.3, size=(4, 4000))
    se, ci = st.standard_error_from_realisations(means)
    np.testing.assert_allclose(se, means.std(axis=0, ddof=1) / 2.0, rtol=1e-13)
    cover = np.mean(np.abs(means.mean(axis=0) - 1.0) <= ci)
    assert 0.935 <= cover <= 0.962, cover
    se1, ci1 = st.standard_error_from_realisations(means[:1])
    assert se1.shape == (4000,) and np.all(np.isnan(se1)) and np.all(np.isnan(ci1))


def test_student_t975():
    assert st.student_t975(1) == pytest.approx(12.7062, rel=1e-5)
    assert st.student_t975(3) == pytest.approx(3.18245, rel=1e-5)
    assert st.student_t975(1e7) == pytest.approx(1.95996, rel=1e-5)


def test_standard_error_of_sd():
    """R >= 3: spread of the realisations' sds; R < 3: sd/sqrt(2N), which is the sd of
    the sample sd of N iid normal samples (checked over 4000 trials)."""
    sds = np.array([[1.0], [2.0], [4.0]])
    np.testing.assert_allclose(st.standard_error_of_sd(sds, np.array([2.5]), np.array([30])),
                               np.std(sds, ddof=1) / math.sqrt(3))
    rng = np.random.default_rng(6)
    s = rng.normal(0, 1.5, size=(400, 4000)).std(axis=0, ddof=1)
    se = st.standard_error_of_sd(s[None, :1], np.array([1.5]), np.array([400]))[0]
    assert se == pytest.approx(1.5 / math.sqrt(800))
    assert s.std() == pytest.approx(se, rel=0.05)


def test_normalised_sd():
    """sqrt(n var)/m_k with the analytic m_k where there is one, else the sample mean."""
    var = np.array([4.0, 9.0, 1.0])
    got = st.normalised_sd(16, var, np.array([2.0, np.nan, 4.0]), np.array([5.0, 6.0, 7.0]))
    np.testing.assert_allclose(got, [4.0, 2.0, 1.0])
    assert np.all(np.isnan(st.normalised_sd(None, var, var, var)))


def test_fit_exponent():
    ns = [2048, 8192, 32768]
    assert st.fit_exponent(ns, [3.0 * n**-0.5 for n in ns]) == pytest.approx(-0.5, abs=1e-12)
    assert st.fit_exponent(ns, [7.0, 7.0, 7.0]) == pytest.approx(0.0, abs=1e-12)
