# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.hotReactor: the plug flow's discrete sizes put into the solver's mass bins."""
import numpy as np

from coagulationPost import hotReactor


def test_bin_sizes_puts_each_mass_in_the_bin_below_its_upper_edge():
    upper = np.array([2.0, 4.0, 8.0])
    masses = [1, 2, 3, 4, 7, 8, 20]
    numbers = [1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6]
    # 1 -> bin 0; 2, 3 -> bin 1 (an edge belongs to the bin above); 4, 7 -> bin 2; 8, 20 dropped
    assert hotReactor.bin_sizes(masses, numbers, upper).tolist() == [1.0, 110.0, 11000.0]


def test_bin_sizes_keeps_the_number_in_range():
    rng = np.random.default_rng(3)
    masses = rng.integers(1, 100, 500)
    numbers = rng.random(500)
    upper = np.geomspace(1.5, 200.0, 12)
    assert np.isclose(hotReactor.bin_sizes(masses, numbers, upper).sum(), numbers.sum())
