# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.statistics on time-correlated samples: the integrated
autocorrelation time of AR(1) series, the coverage of the correlated-sample interval
(and the under-coverage of the independent-sample one), and the report's columns on a
synthetic AR(1) case.  Fixed seeds; each test fails when the correction is removed
(tau_int = 1/2, or COAGULATIONPOST_IID_INTERVAL=1)."""

import os

import h5py
import numpy as np
import pytest

from coagulationPost import report, samples
from coagulationPost import statistics as st


def ar1(rng, phi, n, cols, burn=400):
    """cols AR(1) series x_i = phi x_{i-1} + sqrt(1 - phi^2) e_i of length n, unit
    variance, started in equilibrium (burn-in)."""
    e = rng.standard_normal((n + burn, cols))
    x = np.empty_like(e)
    x[0] = e[0]
    s = np.sqrt(1 - phi * phi)
    for i in range(1, len(e)):
        x[i] = phi * x[i - 1] + s * e[i]
    return x[burn:]


def phi_of(tau):
    """AR(1) coefficient with tau_int = (1 + phi) / (2 (1 - phi)) = tau."""
    return (2 * tau - 1) / (2 * tau + 1)


@pytest.mark.parametrize("tau", [0.5, 2.0, 4.5, 10.0])
def test_tau_of_ar1(tau):
    """Median over 200 series of 20000 samples within 5 % of (1+phi)/(2(1-phi))."""
    x = ar1(np.random.default_rng(11), phi_of(tau), 20000, 200)
    est = st.autocorrelation_time(x)
    assert est.shape == (200,)
    assert np.median(est) == pytest.approx(tau, rel=0.05)


def test_tau_shapes_and_constant_columns():
    """[N][cells][moments] in, [cells][moments] out; a constant column has tau 1/2, n_eff
    N and a zero half-width."""
    x = ar1(np.random.default_rng(3), 0.5, 500, 6).reshape(500, 3, 2)
    x[:, 1, 1] = 7.0
    mean, neff, ci, tau = st.correlated_interval(x)
    assert tau.shape == neff.shape == ci.shape == mean.shape == (3, 2)
    assert tau[1, 1] == 0.5 and neff[1, 1] == 500 and ci[1, 1] == 0.0
    assert np.all(np.isfinite(ci))


def test_independent_samples_give_the_iid_interval():
    """Independent samples: n_eff ~ N and the half-width ~ t sd / sqrt(N)."""
    x = np.random.default_rng(4).standard_normal((4000, 50))
    mean, neff, ci, tau = st.correlated_interval(x)
    iid = 1.96 * x.std(axis=0, ddof=1) / np.sqrt(len(x))
    assert np.median(neff) > 0.85 * len(x)
    assert np.median(ci / iid) == pytest.approx(1.0, abs=0.1)


@pytest.mark.parametrize("tau,n", [(5.0, 2000), (5.0, 320), (10.0, 320)])
def test_coverage_on_ar1(tau, n):
    """2000 AR(1) series with mean 0: the 95 % correlated-sample intervals contain 0 for
    90..99 % of them; the independent-sample ones (1.96 sd / sqrt(N)) for under 70 %.
    (10, 320): the series are 32 tau long."""
    x = ar1(np.random.default_rng(int(10 * tau + n)), phi_of(tau), n, 2000)
    mean, neff, ci, est = st.correlated_interval(x)
    cover = np.mean(np.abs(mean) <= ci)
    iid = np.mean(np.abs(mean) <= 1.96 * x.std(axis=0, ddof=1) / np.sqrt(n))
    print("tau %g N %d: coverage %.3f (iid %.3f), median n_eff %.1f" % (tau, n, cover, iid,
                                                                       np.median(neff)))
    assert 0.90 <= cover <= 0.99
    assert iid < 0.70


def test_masked_columns_use_their_valid_samples():
    """A column with missing samples (NaN) gets the interval of its valid samples."""
    x = ar1(np.random.default_rng(5), 0.6, 600, 4).reshape(600, 2, 2)
    x[:100, 1, 0] = np.nan
    mean, neff, ci, tau = st.correlated_interval_masked(x)
    m1, n1, c1, t1 = st.correlated_interval(x[100:, 1, 0])
    assert mean[1, 0] == pytest.approx(float(m1)) and ci[1, 0] == pytest.approx(float(c1))
    m0, n0, c0, t0 = st.correlated_interval(x[:, 0, 0])
    assert ci[0, 0] == pytest.approx(float(c0))


ATTRS = dict(n=256, V1=1e-3, K0=1e-5, inceptionRate=3e8, seed=7, splitDeltaT=1e-2,
             sampleInterval=0.01, tRelax=0.0, algorithm="SWA", kernel="constant")


def write_case(case, x, seed, centres=None):
    d = os.path.join(str(case), samples.SAMPLE_DIR)
    os.makedirs(d, exist_ok=True)
    nc = x.shape[1]
    with h5py.File(os.path.join(d, "s.h5"), "w") as f:
        f["cellCentres"] = (np.stack([np.arange(nc) + 0.5, np.zeros(nc), np.zeros(nc)], 1)
                            if centres is None else centres)
        f["time"] = np.arange(len(x)) * 0.01
        f["moments"] = x
        for k, v in {**ATTRS, "seed": seed}.items():
            f.attrs[k] = v


def test_report_interval_and_columns(tmp_path):
    """One synthetic run (AR(1), tau 10, 400 cells x 4 moments, mean 100): the report's
    ci covers 100 in 90..99 % of the cell-moments, ciIid in under 70 %; moments_full.csv
    has Mk_neff, Mk_tauInt, Mk_ci95_iid.  Four runs: ci from the realisation means, n_eff their
    sum, tauInt their mean."""
    rng = np.random.default_rng(18)
    runs = []
    for r in range(4):
        x = 100.0 + ar1(rng, phi_of(10.0), 320, 400 * 4).reshape(320, 400, 4)
        runs.append(str(tmp_path / ("run%d" % r)))
        write_case(runs[-1], x, 11 + r)
    res = report.compute(runs[:1], analytic_kind="none")
    cover = np.mean(np.abs(res["mean"] - 100) <= res["ci"])
    iid = np.mean(np.abs(res["mean"] - 100) <= res["ciIid"])
    print("report: one run coverage %.3f, iid %.3f" % (cover, iid))
    assert 0.90 <= cover <= 0.99 and iid < 0.70
    assert np.median(res["tauInt"]) == pytest.approx(10.0, rel=0.4)
    out = str(tmp_path / "out")
    os.makedirs(out)
    report.write_csv(res, out)
    f = np.genfromtxt(os.path.join(out, "moments_full.csv"), delimiter=",", names=True)
    for k in range(4):
        np.testing.assert_allclose(f["M%d_neff" % k], res["neff"][:, k], rtol=1e-11)
        np.testing.assert_allclose(f["M%d_ci95_iid" % k], res["ciIid"][:, k], rtol=1e-11)
        np.testing.assert_allclose(f["M%d_ci95" % k], res["ci"][:, k], rtol=1e-11)
    pooled = report.compute(runs, analytic_kind="none")
    singles = [report.compute([r], analytic_kind="none") for r in runs]
    means = np.array([one["mean"] for one in singles])
    np.testing.assert_allclose(pooled["ci"], st.standard_error_from_realisations(means)[1],
                               rtol=1e-10)
    # pooled realisations: n_eff is their sum (independent runs), tauInt their mean
    np.testing.assert_allclose(pooled["neff"], np.sum([one["neff"] for one in singles], axis=0),
                               rtol=1e-10)
    np.testing.assert_allclose(pooled["tauInt"], np.mean([one["tauInt"] for one in singles], axis=0),
                               rtol=1e-10)
    cover4 = np.mean(np.abs(pooled["mean"] - 100) <= pooled["ci"])
    print("report: 4 realisations coverage %.3f" % cover4)
    assert 0.90 <= cover4 <= 0.99
    assert "4 realisations" in pooled["meta"]["interval"]
    # the mean mass M1/M0 (true value 1) and its interval, in the cells' order: one run's
    # from its samples, the realisations' from their ratios
    for r in [res, pooled]:
        np.testing.assert_allclose(r["meanMass"], r["mean"][:, 1] / r["mean"][:, 0], rtol=1e-12)
    np.testing.assert_allclose(
        pooled["meanMassCi"],
        st.standard_error_from_realisations(np.array([one["meanMass"] for one in singles]))[1],
        rtol=1e-10)
    for r, name in ((res, "one run"), (pooled, "4 realisations")):
        cover = np.mean(np.abs(r["meanMass"] - 1) <= r["meanMassCi"])
        print("report: mean mass, %s: coverage %.3f" % (name, cover))
        assert 0.90 <= cover <= 0.99


def test_min_window_sees_a_weak_slow_tail():
    """White noise plus a weak slow AR(1) part (tau 30, 1/4 of the variance; tau_int of
    the sum ~ 8): Sokal's window alone stops near lag 3 and the intervals of 320 samples
    under-cover; a minimum window of 40 lags (the duct's residence time) restores 90..99 %."""
    rng = np.random.default_rng(7)
    x = np.sqrt(0.75) * rng.standard_normal((320, 2000)) + 0.5 * ar1(rng, phi_of(30.0), 320, 2000)
    m0, _, c0, _ = st.correlated_interval(x)
    m1, _, c1, t1 = st.correlated_interval(x, min_window=40)
    cover0, cover1 = np.mean(np.abs(m0) <= c0), np.mean(np.abs(m1) <= c1)
    print("slow tail: coverage Sokal alone %.3f, min window 40 %.3f" % (cover0, cover1))
    assert cover0 < 0.85
    assert 0.90 <= cover1 <= 0.99


def test_short_series_corrections():
    """Series only 16 tau_int long (tau 20, 320 samples; 4000 of them): coverage >= 0.94
    needs both short-series corrections: without the (N - 2M - 1) bias correction it is
    0.928, with n_eff - 1 instead of N/(2M+1) dof 0.899 (without both about 0.84)."""
    x = ar1(np.random.default_rng(2020), phi_of(20.0), 320, 4000)
    mean, neff, ci, est = st.correlated_interval(x)
    cover = np.mean(np.abs(mean) <= ci)
    print("tau 20 N 320: coverage %.3f" % cover)
    assert 0.94 <= cover <= 0.99


def test_mean_mass_interval_covers_the_ratio():
    """The mean mass m1/m0 of 2000 cells, each an AR(1) series (tau 5, 800 samples) of M0
    and M1 = R M0 + noise, strongly correlated (as a cell's M0 and M1 are): its 95 %
    interval holds the true ratio for 90..99 % of the cells (94.6 %). The first-order bound
    as if M0 and M1 were independent is more than 3 times wider (18 times here). A cell
    whose M1 is exactly R M0 has a zero interval."""
    rng = np.random.default_rng(21)
    n, cells, R = 800, 2000, 2.5
    phi = phi_of(5.0)
    m0 = 100.0 + 10.0 * ar1(rng, phi, n, cells)
    m1 = R * m0 + 2.0 * ar1(rng, phi, n, cells)
    data = np.stack([m0, m1], axis=2)
    mean, _, ci, _ = st.correlated_interval_masked(data)
    ratio, ratio_ci = report.mean_mass_interval(data, mean, 0)
    cover = np.mean(np.abs(ratio - R) <= ratio_ci)
    bound = ratio * np.hypot(ci[:, 0] / mean[:, 0], ci[:, 1] / mean[:, 1])
    print("coverage %.3f, median width %.4g, independent bound %.4g"
          % (cover, np.median(ratio_ci), np.median(bound)))
    assert np.allclose(ratio, mean[:, 1] / mean[:, 0])
    assert 0.90 <= cover <= 0.99
    assert np.median(bound / ratio_ci) > 3
    exact = np.stack([m0, R * m0], axis=2)[:, :5]
    mean, _, _, _ = st.correlated_interval_masked(exact)
    assert np.allclose(report.mean_mass_interval(exact, mean, 0)[1], 0.0, atol=1e-12)


def test_report_mean_mass_per_cell_in_the_cells_order(tmp_path):
    """The report's mean mass and its interval belong to their cells: 60 cells written in a
    shuffled order, each with its own M1/M0 (1 + x/20); one run's interval is that of the
    cell's own samples (mean_mass_interval on the file's columns, window 0), three
    realisations' the t-interval of their ratios."""
    rng = np.random.default_rng(5)
    nc, n = 60, 400
    x_of = rng.permutation(nc) + 0.5                     # the file's cell j sits at x_of[j]
    centres = np.stack([x_of, np.zeros(nc), np.zeros(nc)], 1)
    runs, data = [], []
    for r in range(3):
        m0 = 100.0 + 5.0 * ar1(rng, phi_of(3.0), n, nc)
        m1 = (1 + x_of / 20) * m0 + ar1(rng, phi_of(3.0), n, nc)
        x = np.stack([m0, m1, m0, m0], axis=2)
        data.append(x)
        runs.append(str(tmp_path / ("run%d" % r)))
        write_case(runs[-1], x, 30 + r, centres)
    one = report.compute(runs[:1], analytic_kind="none", correlation_time=0)
    order = np.argsort(x_of)                             # the report's rows: by x
    np.testing.assert_allclose(one["centres"][:, 0], x_of[order])
    mean, _, _, _ = st.correlated_interval_masked(data[0])
    ratio, ci = report.mean_mass_interval(data[0], mean, 0)
    np.testing.assert_allclose(one["meanMass"], ratio[order], rtol=1e-12)
    np.testing.assert_allclose(one["meanMassCi"], ci[order], rtol=1e-9)
    assert np.all(np.abs(one["meanMass"] - (1 + one["centres"][:, 0] / 20)) < 0.05)
    pooled = report.compute(runs, analytic_kind="none", correlation_time=0)
    ratios = np.array([report.mean_mass_interval(d, st.correlated_interval_masked(d)[0], 0)[0]
                       for d in data])[:, order]
    np.testing.assert_allclose(pooled["meanMassCi"],
                               st.standard_error_from_realisations(ratios)[1], rtol=1e-9)
