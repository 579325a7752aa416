# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The exact diffusion references against each other and against direct sampling."""

import numpy as np
import pytest

from coagulationPost import diffusion


def test_reflected_probabilities_sum_to_one_and_start_in_the_box():
    edges = np.linspace(0.0, 1.0, 21)
    for s in (1e-9, 0.05, 0.3, 2.0):
        p = diffusion.reflected_cell_probability(edges[:-1], edges[1:], 0.2, 0.3, 1.0, s)
        assert p.sum() == pytest.approx(1.0, abs=1e-12)
        assert np.all(p >= -1e-12)
    p0 = diffusion.reflected_cell_probability(edges[:-1], edges[1:], 0.2, 0.3, 1.0, 1e-9)
    assert p0[4] == pytest.approx(0.5, abs=1e-7) and p0[5] == pytest.approx(0.5, abs=1e-7)


def test_reflected_probabilities_tend_to_uniform():
    edges = np.linspace(0.0, 1.0, 11)
    p = diffusion.reflected_cell_probability(edges[:-1], edges[1:], 0.0, 0.1, 1.0, 5.0)
    assert np.allclose(p, 0.1, atol=1e-9)


def test_reflected_probability_matches_a_folded_sample():
    # Fold free Gaussian end points into [0, 1]: the reflected walk's law
    rng = np.random.default_rng(4)
    n = 400000
    x = rng.uniform(0.1, 0.25, n) + rng.normal(0.0, 0.3, n)
    x = np.abs(np.mod(x + 1.0, 2.0) - 1.0)
    counts, edges = np.histogram(x, bins=20, range=(0.0, 1.0))
    p = diffusion.reflected_cell_probability(edges[:-1], edges[1:], 0.1, 0.25, 1.0, 0.3)
    z = (counts - n * p) / np.sqrt(n * p * (1 - p))
    assert np.max(np.abs(z)) < 4.0


def test_absorbed_fraction_fourier_equals_image_sum():
    for tau in (0.005, 0.02, 0.1, 0.3, 1.0):
        assert diffusion.absorbed_remaining_fourier(tau) == pytest.approx(
            diffusion.absorbed_remaining_images(tau), rel=1e-9)
    assert diffusion.absorbed_remaining_fourier(0.0, terms=20000) == pytest.approx(1.0, abs=1e-4)
    # late times: the first mode, 8/pi^2 exp(-pi^2 tau)
    assert diffusion.absorbed_remaining_fourier(1.0) == pytest.approx(
        8 / np.pi ** 2 * np.exp(-np.pi ** 2), rel=1e-9)
