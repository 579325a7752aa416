# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The size distribution: the exact n_k of analytic.smoluchowski_sizes
against closed forms (constant kernel from monomers, Golovin's additive-kernel
distribution, the duct moments with inception), and coagulationPost.psd on a
synthetic sample file with known answers (reading, averages, exact reference, checks)."""

import os

import numpy as np
import pytest

from coagulationPost import analytic, psd


def test_constant_kernel_from_monomers_is_the_closed_form():
    # n_k = N0 (tau/(1+tau))^(k-1) / (1+tau)^2, tau = K0 N0 t / 2 (Smoluchowski 1917)
    N0, K0, K = 1e6, 2e-6, 80
    t = np.array([0.1, 1.0, 3.0])
    n0 = np.zeros(1); n0[0] = N0
    n = analytic.smoluchowski_sizes("constant", t, K, 0.0, K0, n0=n0)
    tau = (K0 * N0 * t / 2)[:, None]
    k = np.arange(1, K + 1)[None, :]
    ref = N0 * (tau / (1 + tau)) ** (k - 1) / (1 + tau) ** 2
    assert np.allclose(n, ref, rtol=1e-7, atol=1e-9 * N0)


def test_additive_kernel_from_monomers_is_golovin():
    N0, K0, K = 1e6, 1e-6, 60
    t = np.array([0.2, 0.7, 1.5])
    n0 = np.zeros(1); n0[0] = N0
    n = analytic.smoluchowski_sizes("additive", t, K, 0.0, K0, n0=n0)
    g = analytic.golovin(t, K, N0, K0)
    assert np.allclose(n, g, rtol=1e-6, atol=1e-9 * N0)
    # Golovin's distribution conserves number and mass as stated
    big = analytic.golovin(np.array([0.7]), 4000, N0, K0)[0]
    assert np.isclose(big.sum(), N0 * np.exp(-K0 * N0 * 0.7), rtol=1e-8)
    assert np.isclose((np.arange(1, 4001) * big).sum(), N0, rtol=1e-6)


@pytest.mark.parametrize("kernel", ["constant", "additive"])
def test_with_inception_the_sums_are_the_duct_moments(kernel):
    I, K0 = (3e8, 1e-5) if kernel == "constant" else (1e5, 1.06e-2)
    t = np.array([0.02, 0.05])
    n = analytic.smoluchowski_sizes(kernel, t, 600, I, K0)
    m = analytic.profile("constantDuct" if kernel == "constant" else "additiveDuct", t, I, K0)
    k = np.arange(1, 601)
    assert np.allclose(n.sum(axis=1), m[0], rtol=1e-6)
    assert np.allclose((k * n).sum(axis=1), m[1], rtol=1e-6)
    assert np.allclose((k ** 2 * n).sum(axis=1), m[2], rtol=1e-5)


def _synthetic_case(tmp, kernel="constant"):
    """A case with a sizeDistribution file whose samples are the exact n_k at the
    probes plus independent noise of known sd, and moment samples whose M0 is the sum."""
    import h5py
    rng = np.random.default_rng(5)
    K, N = 10, 400
    I, K0 = 3e8, 1e-5
    x = np.array([0.098, 0.194])
    lo, hi = x - 0.002, x + 0.002
    ref = analytic.duct_sizes(kernel, lo, hi, K, I, K0)
    t = 0.4 + 5e-3 * np.arange(N)
    noise = 0.05 * ref[None] * rng.standard_normal((N, 2, K))
    bins = ref[None] + noise
    ncol = K + 2 + len(psd.DERIVED)
    data = np.zeros((N, 2, ncol))
    data[:, :, :K] = bins
    data[:, :, K + 1] = 1e3                      # overflow
    data[:, :, K + 2] = bins.sum(axis=2) + 1e3   # M0
    data[:, :, K + 3:] = np.nan
    d = os.path.join(tmp, "postProcessing", "psd", "0")
    os.makedirs(d)
    with h5py.File(os.path.join(d, "sizeDistribution.h5"), "w") as h:
        h["time"] = t
        h["cellCentres"] = np.stack([x, [0.002] * 2, [0.002] * 2], axis=1)
        h["moments"] = data
        h.attrs["columns"] = " ".join(["n%d" % i for i in range(K)] + ["underflow", "overflow"]
                                      + list(psd.DERIVED))
        h.attrs["binEdges"] = " ".join("%g" % (i + 0.5) for i in range(K + 1))
        h.attrs["binType"] = "integer"
        h.attrs["regions"] = "probe0 probe1"
        h.attrs["regionVolumes"] = "6.4e-08 6.4e-08"
        h.attrs["timeStart"] = 0.4
        h.attrs["sampleInterval"] = 5e-3
        h.attrs["kernel"] = kernel
        h.attrs["K0"] = K0
        h.attrs["inceptionRate"] = I
    with open(os.path.join(d, "regions.csv"), "w") as f:
        f.write("region,name,x,y,z,volume,xMin,yMin,zMin,xMax,yMax,zMax\n")
        for r in range(2):
            f.write("%d,probe%d,%g,0.002,0.002,6.4e-8,%g,0,0,%g,0.004,0.004\n"
                    % (r, r, x[r], lo[r], hi[r]))
    s = os.path.join(tmp, "postProcessing", "coagulationSamples")
    os.makedirs(s)
    cells = np.stack([0.002 + 0.004 * np.arange(50), [0.002] * 50, [0.002] * 50], axis=1)
    mom = np.zeros((N, 50, 4))
    for r in range(2):
        c = int(np.argmin(abs(cells[:, 0] - x[r])))
        mom[:, c, 0] = data[:, r, K + 2]
    with h5py.File(os.path.join(s, "samples_0.h5"), "w") as h:
        h["time"] = t
        h["cellCentres"] = cells
        h["moments"] = mom
    return ref


def test_read_average_exact_and_checks(tmp_path):
    ref = _synthetic_case(str(tmp_path))
    assert psd.function_names(str(tmp_path)) == ["psd"]
    p = psd.read(str(tmp_path), "psd")
    assert p["nBins"] == 10 and p["regions"] == ["probe0", "probe1"]
    mean, neff, ci, tau = psd.average(p, correlation_time=0)
    ex = psd.exact(p)
    assert np.allclose(ex, ref, rtol=1e-9)
    # independent noise of sd 5 %: n_eff about N, the interval about 1.96 * 0.05 ref /
    # sqrt(400) (wider by the noise of tau_int, never narrower than t sd/sqrt(N - 2M - 1))
    assert np.all(np.abs(neff[:, :10] / 400 - 1) < 0.5)
    ratio = ci[:, :10] / (1.96 * 0.05 * ref / 20)
    assert np.all((ratio > 0.9) & (ratio < 1.6)), ratio
    ok, z, lines = psd.check(p, ex, list(range(10)), mean, ci)
    assert ok, lines
    # a reference 20 % off fails
    bad, _, _ = psd.check(p, 1.2 * ex, list(range(10)), mean, ci)
    assert not bad
    ok, lines = psd.check_m0(p, str(tmp_path))
    assert ok, lines
    # a PSD missing its overflow in the sum does not match M0
    p2 = dict(p)
    p2["data"] = p["data"].copy()
    p2["data"][:, :, 11] = 0
    assert not psd.check_m0(p2, str(tmp_path))[0]


def test_figures_two_runs_side_by_side(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    a.mkdir(); b.mkdir()
    _synthetic_case(str(a)); _synthetic_case(str(b))
    runs = [psd.read(str(a), "psd"), psd.read(str(b), "psd")]
    paths = psd.figures(runs, str(tmp_path / "out"), labels=["a", "b"])
    assert os.path.getsize(paths[0]) > 1000


def test_size_statistics_of_a_lognormal():
    # a lognormal of dg 30 nm, sigma_g 1.5 in 200 log bins from 1 nm to 1 um: the count
    # median and geometric mean diameters are dg, the geometric standard deviation 1.5
    edges = np.geomspace(1e-9, 1e-6, 201)
    lo, hi = edges[:-1], edges[1:]
    centre = np.sqrt(lo * hi)
    from scipy.stats import norm
    ln_sg = np.log(1.5)
    n = 1e12 * (norm.cdf(np.log(hi / 30e-9) / ln_sg) - norm.cdf(np.log(lo / 30e-9) / ln_sg))
    cmd, gmd, sg = psd.size_statistics(centre, n, lo, hi)
    assert abs(cmd / 30e-9 - 1) < 1e-3
    assert abs(gmd / 30e-9 - 1) < 1e-3
    assert abs(sg / 1.5 - 1) < 2e-3
    # shifted by a factor: every diameter statistic by the factor, sigma_g unchanged
    cmd2, gmd2, sg2 = psd.size_statistics(2 * centre, n, 2 * lo, 2 * hi)
    assert np.isclose(cmd2, 2 * cmd) and np.isclose(gmd2, 2 * gmd) and np.isclose(sg2, sg)


def test_diameter_bins_of_integer_and_log_bins(tmp_path):
    _synthetic_case(str(tmp_path))
    p = psd.read(str(tmp_path), "psd")
    rho, unit = 1800.0, 9.42e-22           # a mass of 1 is a 10 nm sphere
    d, lo, hi, dlog = psd.diameter_bins(p, rho, unit)
    k = np.arange(1, 11)
    assert np.allclose(d, 1e-8 * k ** (1 / 3), rtol=1e-3)
    assert np.allclose(dlog, np.log10((k + 0.5) / (k - 0.5)) / 3)
    assert np.all((lo < d) & (d < hi))
    q = dict(p, binType="log", edges=np.geomspace(1, 1000, 11))
    d, lo, hi, dlog = psd.diameter_bins(q, rho, unit)
    assert np.allclose(dlog, 0.1)            # a mass ratio of 10^0.3 a bin: 0.1 in log10 d
    assert np.allclose(d, np.sqrt(lo * hi))


def test_diameter_figure_with_the_exact_distribution(tmp_path):
    ref = _synthetic_case(str(tmp_path))
    p = psd.read(str(tmp_path), "psd")
    paths = psd.diameter_figure([p], str(tmp_path / "out"), density=1800.0, mass_unit=9.42e-22)
    assert os.path.getsize(paths[0]) > 1000
    rows = np.genfromtxt(paths[1], delimiter=",", names=True, dtype=None, encoding=None)
    d, lo, hi, dlog = psd.diameter_bins(p, 1800.0, 9.42e-22)
    for r in range(2):
        sel = rows["region"] == "probe%d" % r
        assert np.allclose(rows["exact"][sel] * dlog, ref[r], rtol=1e-9)
        assert np.allclose(rows["d_nm"][sel], 1e9 * d)
    # without a density (none in the run, none given) no figure
    assert psd.diameter_figure([p], str(tmp_path / "none")) == []
