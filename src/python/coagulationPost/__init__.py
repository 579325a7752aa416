# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost: post-processing of coagulationFoam's HDF5 moment samples and of the
benchmarks' output.

The command lines applications/utilities/coagulationReport/coagulationReport.py,
applications/utilities/coagulationTables/coagulationTables.py and
applications/utilities/coagulationProfiles/coagulationProfiles.py are thin layers over it;
the benchmarks' post-processing runs as python3 -m coagulationPost.<module> ARGS (the
modules marked 'main' below; installed, also as the console scripts coagulationPost-<module>).

Finding it: etc/bashrc puts <repo>/src/python on PYTHONPATH; or pip install src/python
(src/python/pyproject.toml).

Modules (each imports only what it needs; ``analytic`` and ``statistics`` need numpy and
scipy, ``samples`` h5py, ``plots`` and the figures matplotlib).  ``import coagulationPost``
imports none of them; ``coagulationPost.X`` imports module X on first use:

  samples     reading the solver's sample files: processors and restarts merged by cell
              centre and time, realisations of an ensemble, the time window
  statistics  mean, sd, 95 % confidence half-widths; the pooling of groups of samples
              (Chan et al.'s parallel update, written once); Student t; standard errors;
              intervals of correlated time series
  analytic    Patterson & Wagner's duct references: eqs (39)-(45), (47), (50), the moment
              ODEs (38)-(44) and those of the additive kernel, cell averages
  diffusion   exact solutions of pure diffusion between reflecting or absorbing walls (the
              random-walk tests)
  report      per-cell statistics of one case or of pooled realisations against the
              analytic reference, and their CSV, JSON and text table (coagulationReport)
  tables      rows of the paper's Tables 1 and 2 pooled over realisations, their CSV and
              markdown (coagulationTables)
  profiles    moments along an axis and deposition per wall of a run on a general mesh
              (coagulationProfiles)
  psd         the particle size distribution of a run: its samples, time averages,
              exact distributions, checks and plots (coagulationReport --psd)
  plots       the PNG figures of coagulationReport and coagulationTables (matplotlib, Agg)
  maps        maps of the report's cell moments on a two-dimensional mesh (maps.png, maps.csv),
              on planes through a mesh and along lines (coagulationReport --slice, --line)
  sections    the cells of a mesh an axis-aligned plane cuts (their polygons) and a segment
              crosses (their entry and exit)
  checks      the acceptance checks of coagulationReport and coagulationTables
  cloud       the coagulationCloud's ASCII particle files of a time folder (cells, fields)
  lagrangianStudy
              main: figures and summary of build/applications/studies/lagrangianStudy's CSV
              (Kolodko-Sabelfeld-Wagner §5, tutorials/pseudoTurbulence*)
  coagulationDiffusionFigures
              main: figures and checks of build/applications/studies/coagulationDiffusionFigures'
              CSV (Sabelfeld-Kolodko Figs 2-10, tutorials/coagulationDiffusion*)
  coagulationDiffusionColumn
              main: the coagulationFoam case (setup) and its n_l at x = 0
              against the Eulerian and Lagrangian references (compare)
  pseudoTurbulencePuff
              main: the coagulationFoam case of a puff in frozen pseudo-turbulence (setup)
              against the Lagrangian reference (compare)
  splittingStudy
              main: tables and plot of tests/benchmarks/splittingStudy.sh's runs
  hotReactor  main: the hot reactor's size distributions and mean diameter on the axis
              against plugFlowReference's plug flow (tutorials/hotReactor)
  squareCylinder
              main: the square cylinder's size distributions and probe series in the
              wake (tutorials/squareCylinder)

Tests: PYTHONPATH=src/python python3 -m pytest tests/python
"""

import importlib

__all__ = [
    "samples",
    "statistics",
    "analytic",
    "diffusion",
    "report",
    "tables",
    "profiles",
    "psd",
    "plots",
    "checks",
    "cloud",
    "lagrangianStudy",
    "coagulationDiffusionFigures",
    "coagulationDiffusionColumn",
    "pseudoTurbulencePuff",
    "splittingStudy",
    "hotReactor",
    "squareCylinder",
    "maps",
    "sections",
]


def __getattr__(name):
    """coagulationPost.X: submodule X of __all__, imported on first use (PEP 562)."""
    if name in __all__:
        return importlib.import_module("." + name, __name__)
    raise AttributeError("module %r has no attribute %r" % (__name__, name))


def __dir__():
    return sorted(set(globals()) | set(__all__))
