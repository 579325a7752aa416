# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.analytic against independent references: the paper's equations
written in its own variables (I0, I = 3 I0), a numerical integration of the moment
ODEs (38), (40), (42), (44) done here, closed forms of the additive-kernel moment
ODEs (Dawson's integral, erf), quadrature, the Poisson law of eq. (46) and limits."""

import math

import numpy as np
import pytest
from scipy import integrate, special, stats

from coagulationPost import analytic

I0, K0 = 1e8, 1e-5          # section 3.1: I = 3 I0 = 3e8
I = 3 * I0
IA, KA = 1e5, 1.06e-2       # section 3.2


def paper_constant(x, u):
    """Eqs (39), (41), (43), (45) as printed, in I0."""
    return np.stack([
        np.sqrt(6 * I0 / K0) * np.tanh(np.sqrt(3 * I0 * K0 / 2) * x / u),
        3 * I0 * x / u,
        3 * I0 * x / u + 3 * I0**2 * K0 * x**3 / u**3,
        3 * I0 * x / u + 9 * I0**2 * K0 * x**3 / u**3 + 27 * I0**3 * K0**2 * x**5 / (5 * u**5)])


@pytest.mark.parametrize("u", [1.0, 2.5])
def test_constant_duct_solves_the_moment_equations(u):
    """Eqs (39)-(45) = an implicit (Radau) integration, here, of eqs (38), (40), (42), (44)."""
    def rhs(_x, m):
        return np.array([3 * I0 - K0 / 2 * m[0]**2, 3 * I0, 3 * I0 + K0 * m[1]**2,
                         3 * I0 + 3 * K0 * m[1] * m[2]]) / u
    x = np.linspace(0.0, 0.2, 41)
    sol = integrate.solve_ivp(rhs, (0, 0.2), np.zeros(4), method="Radau", t_eval=x,
                              rtol=1e-11, atol=1e-3)
    got = analytic.constant_duct(x, I, K0, u)
    np.testing.assert_allclose(got[:, 1:], sol.y[:, 1:], rtol=1e-7)
    np.testing.assert_allclose(got[:, 1:], paper_constant(x, u)[:, 1:], rtol=1e-13)


def test_constant_duct_limits():
    """m_k -> I x/u near the inlet (inception only); m0 -> sqrt(2 I/K0) far downstream;
    zero upstream of the inlet; K0 = 0 is pure inception."""
    x = np.array([1e-7])
    np.testing.assert_allclose(analytic.constant_duct(x, I, K0)[:, 0], I * x[0], rtol=1e-6)
    assert analytic.constant_duct(np.array([50.0]), I, K0)[0, 0] == pytest.approx(
        math.sqrt(2 * I / K0), rel=1e-12)
    assert np.all(analytic.constant_duct(np.array([-0.1]), I, K0) == 0)
    np.testing.assert_allclose(analytic.constant_duct(np.array([0.1]), I, 0.0)[:, 0], I * 0.1)


def test_constant_ode_equals_closed_forms():
    """The package's own ODE right-hand side (duct_ode "constant") against eqs (39)-(45)."""
    x = np.linspace(0, 0.2, 51)
    np.testing.assert_allclose(analytic.duct_ode("constant", x, I, K0)[:, 1:],
                               analytic.constant_duct(x, I, K0)[:, 1:], rtol=1e-7)


def test_additive_duct_closed_forms():
    """Additive kernel, m1 = I x (eq. 50): the moment ODEs are linear in m0 and m2,
    m0 = I e^{-a x^2} int_0^x e^{a s^2} ds = I/sqrt(a) dawsn(sqrt(a) x),  a = K0 I/2,
    m2 = I e^{b x^2} int_0^x e^{-b s^2} ds = I sqrt(pi)/(2 sqrt b) e^{b x^2} erf(sqrt(b) x), b = K0 I,
    and m3 = e^{c x^2} int_0^x e^{-c s^2} (I + 3 K0 m2(s)^2) ds, c = 3 K0 I/2 (quadrature)."""
    x = np.array([0.002, 0.03, 0.099])
    a, b, c = KA * IA / 2, KA * IA, 1.5 * KA * IA
    m0 = IA / math.sqrt(a) * special.dawsn(math.sqrt(a) * x)
    m2 = IA * math.sqrt(math.pi) / (2 * math.sqrt(b)) * np.exp(b * x**2) * special.erf(math.sqrt(b) * x)

    def m2_of(s):
        return IA * math.sqrt(math.pi) / (2 * math.sqrt(b)) * math.exp(b * s * s) * math.erf(math.sqrt(b) * s)
    m3 = np.array([math.exp(c * xx * xx) * integrate.quad(
        lambda s: math.exp(-c * s * s) * (IA + 3 * KA * m2_of(s)**2), 0, xx, epsabs=0, epsrel=1e-12)[0]
        for xx in x])
    got = analytic.additive_duct(x, IA, KA)
    np.testing.assert_allclose(got[0], m0, rtol=1e-8)
    np.testing.assert_array_equal(got[1], IA * x)          # eq. (50), exact
    np.testing.assert_allclose(got[2], m2, rtol=1e-8)
    np.testing.assert_allclose(got[3], m3, rtol=1e-7)
    # the paper's "true value 10^5 x 0.099 = 9.90 x 10^3" (section 3.2)
    assert got[1, 2] == pytest.approx(9.90e3, rel=1e-14)


def test_mass_moment_eq41_eq50():
    """m1 = I x / u for both kernels, 0 upstream of the inlet."""
    x = np.array([-1.0, 0.0, 0.05, 0.2])
    np.testing.assert_allclose(analytic.mass_moment(x, 3e8, 2.0), [0, 0, 7.5e6, 3e7])
    np.testing.assert_allclose(analytic.constant_duct(x, I, K0, 2.0)[1], analytic.mass_moment(x, I, 2.0))


@pytest.mark.parametrize("u", [1.0, 3.0])
def test_normalised_sd_m1_is_the_poisson_law_eq46(u):
    """Eq. (47) from eq. (46): n V1 M ~ Poi(I x n V1 / u), so n var(M)/m1^2 = u/(I V1 x)."""
    n, V1, x = 256, 1.25e-8, np.array([0.01, 0.1, 0.19])
    lam = I * x * n * V1 / u
    var_m = stats.poisson(lam).var() / (n * V1)**2
    np.testing.assert_allclose(analytic.normalised_sd_m1(x, I, V1, u),
                               np.sqrt(n * var_m) / (I * x / u), rtol=1e-12)


def test_cell_average_and_edges():
    """Gauss-Legendre cell averages = adaptive quadrature of the profile; faces from centres."""
    lo = np.arange(50) * 2e-3
    hi = lo + 2e-3
    for kind, args in (("constantDuct", (I, K0)), ("additiveDuct", (IA, KA))):
        avg = analytic.cell_average(kind, lo, hi, *args)
        for i in (0, 17, 49):
            for k in range(4):
                q = integrate.quad(lambda s: analytic.profile(kind, np.array([s]), *args)[k, 0],
                                   lo[i], hi[i], epsabs=0, epsrel=1e-11)[0] / (hi[i] - lo[i])
                assert avg[k, i] == pytest.approx(q, rel=1e-8), (kind, i, k)
    # shifted inlet: the profile of x - x_inlet
    sh = analytic.cell_average("constantDuct", lo + 0.5, hi + 0.5, I, K0, x_inlet=0.5)
    np.testing.assert_allclose(sh, analytic.cell_average("constantDuct", lo, hi, I, K0), rtol=1e-12)
    lo2, hi2 = analytic.cell_edges(np.array([0.006, 0.002, 0.01]))
    np.testing.assert_allclose(lo2, [0.004, 0.0, 0.008])
    np.testing.assert_allclose(hi2, [0.008, 0.004, 0.012])
    lo3, _ = analytic.cell_edges(np.array([0.5, 1.5]), x_inlet=0.7)
    np.testing.assert_allclose(lo3, [0.7, 1.0])


def test_kind_for_kernel_and_profile():
    assert analytic.kind_for_kernel(" Constant ") == "constantDuct"
    assert analytic.kind_for_kernel("additive") == "additiveDuct"
    assert analytic.kind_for_kernel("multiplicative") is None
    assert analytic.kind_for_kernel(None) is None
    with pytest.raises(ValueError):
        analytic.profile("nope", np.zeros(1), I, K0)
