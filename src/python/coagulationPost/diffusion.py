# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Exact solutions of pure diffusion, dc/dt = D c'' on [0, L], for the random-walk tests.

* Reflecting walls at 0 and L (the image method): a particle released uniformly in
  [a, b] is in [x1, x2] at time t with probability
      P = 1/(b-a) sum_n int_a^b int_x1^x2 [g(x - x0 + 2nL) + g(x + x0 + 2nL)] dx dx0,
  g the Gaussian of variance s^2 = 2 D t. With Psi(z) = z Phi(z) + phi(z), the
  antiderivative of the normal CDF Phi, both integrals are closed forms.
* Absorbing walls at 0 and L, a uniform start: the fraction remaining is the Fourier series
      f(t) = sum_k 8/((2k+1)^2 pi^2) exp(-(2k+1)^2 pi^2 D t/L^2)
  (Crank, The Mathematics of Diffusion, eq. 4.18 for the plane sheet); and per cell, from
  the image sum with alternating signs (-1)^n for the absorbing images.

Public functions
----------------
reflected_cell_probability(x1, x2, a, b, L, s)    P above, vectorised over x1, x2
absorbed_remaining_fourier(Dt_over_L2, terms)     f(t), the Fourier series
absorbed_remaining_images(Dt_over_L2, images)     f(t) from the image sum (a cross-check)
"""

import numpy as np
from scipy.special import ndtr

SQRT_2PI = np.sqrt(2.0 * np.pi)


def _psi(z):
    """Antiderivative of the normal CDF: Psi'(z) = Phi(z)."""
    return z * ndtr(z) + np.exp(-0.5 * z * z) / SQRT_2PI


def _box_overlap(u, lo, hi, s):
    """int_lo^hi Phi((u - x0)/s) dx0 = s [Psi((u - lo)/s) - Psi((u - hi)/s)]."""
    return s * (_psi((u - lo) / s) - _psi((u - hi) / s))


def _free_cell(x1, x2, lo, hi, s):
    """int_lo^hi int_x1^x2 g(x - x0) dx dx0 for the free Gaussian g of sd s."""
    return _box_overlap(x2, lo, hi, s) - _box_overlap(x1, lo, hi, s)


def reflected_cell_probability(x1, x2, a, b, L, s, images=None):
    """P(particle in [x1, x2] at time t), released uniformly in [a, b], reflecting walls.

    Images out to 10 s beyond the box unless ``images`` says how many; the result carries
    round-off of about 1e-13 (differences of Psi at large arguments)."""
    x1 = np.asarray(x1, dtype=float)
    x2 = np.asarray(x2, dtype=float)
    if s <= 0:
        return np.clip((np.minimum(x2, b) - np.maximum(x1, a)) / (b - a), 0.0, None)
    if images is None:
        images = int(np.ceil(10.0 * s / (2.0 * L))) + 2
    total = np.zeros(np.broadcast(x1, x2).shape)
    for n in range(-images, images + 1):
        shift = 2.0 * n * L
        # direct image: source box [a, b] shifted by -shift; mirrored: [-b, -a] shifted
        total += _free_cell(x1, x2, a - shift, b - shift, s)
        total += _free_cell(x1, x2, -b - shift, -a - shift, s)
    return total / (b - a)


def absorbed_remaining_fourier(Dt_over_L2, terms=200):
    """Fraction remaining in a slab with absorbing walls, uniform start (Fourier series)."""
    tau = np.asarray(Dt_over_L2, dtype=float)
    k = np.arange(terms)[:, None] if tau.ndim else np.arange(terms)
    m = (2 * k + 1) ** 2 * np.pi ** 2
    return np.sum(8.0 / m * np.exp(-m * tau), axis=0)


def absorbed_remaining_images(Dt_over_L2, images=20):
    """The same fraction from the image sum: images at 2nL with sign +, mirrored with -."""
    tau = float(Dt_over_L2)
    s = np.sqrt(2.0 * tau)  # L = 1
    total = 0.0
    for n in range(-images, images + 1):
        total += _free_cell(0.0, 1.0, -2.0 * n, 1.0 - 2.0 * n, s)
        total -= _free_cell(0.0, 1.0, -1.0 - 2.0 * n, -2.0 * n, s)
    return total
