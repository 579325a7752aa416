# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""pytest set-up of the coagulationPost unit tests.

The package comes from PYTHONPATH (etc/bashrc puts <repo>/src/python on it; CTest's
python_unit sets it) or from an installed copy (pip install src/python):

    PYTHONPATH=src/python /usr/bin/python3 -m pytest -q tests/python   (CTest: python_unit)
"""
import importlib.util

import pytest


def pytest_configure(config):
    if importlib.util.find_spec("coagulationPost") is None:
        raise pytest.UsageError(
            "coagulationPost is not importable: source etc/bashrc, set "
            "PYTHONPATH=<repo>/src/python, or pip install <repo>/src/python")
