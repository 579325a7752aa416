# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""pytest set-up of the coagulationPost unit tests: the package from <repo>/src/python.

Run: /usr/bin/python3 -m pytest -q tests/python   (CTest: python_unit)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "src", "python"))
